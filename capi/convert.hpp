#pragma once
// struct triangulateio <-> gpdr's in-memory job (gpdr/memory_job.hpp): the
// input arrays read into a MeshInput, and a finished mesh copied out into
// the caller's structures with Triangle's rules for who allocates what
// (docs/c-api.md).

#include <gpdr/memory_job.hpp>
#include <gpdr/options.hpp>

#include <triangle.h>

namespace gpdr::capi {

// The name messages give the input arrays.
inline constexpr const char* input_name = "triangulate() input";

// The arrays of `in` the switches use, checked for what the C structure
// alone can get wrong (negative counts, missing arrays, indices below the
// numbering base); run_job_in_memory() checks the rest.  Throws InputError.
MeshInput read_input(const triangulateio& in, const Options& options);

// Fills `out` and, when not null, `vorout` from `result`.  Every array is
// allocated before any field is written, so that a failure (std::bad_alloc,
// or an InputError for a mesh too large for int indices) leaves both
// structures untouched and allocates nothing.
void write_output(const MemoryJobResult& result, const Options& options, const triangulateio& in,
                  triangulateio& out, triangulateio* vorout);

}  // namespace gpdr::capi
