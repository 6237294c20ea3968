#pragma once
// Reading the vertex lines of a mapped .node or .poly file on several
// threads (-jN).  The bytes after the header are cut at line starts into
// slices; each thread parses whole slices into arrays of their own, as if
// every data line of the slice were a vertex, and stops a slice at its
// first error.  Only then, in file order, are the slices joined: the first
// `count` data lines are the vertices, the first error among them (or among
// the lines up to the last vertex: a NUL byte, a line too long) is reported
// with its line number in the file, the numbering warnings are those one
// thread gives, and the reader goes on after the last vertex line.  So the
// values, errors and warnings are those of the one-thread reader
// (read_poly.cpp), and lines past the vertex list are left to it.
//
// Meanwhile one task hashes the whole file for the run stamp (the hash is a
// chain over the bytes, so it runs beside the parsing rather than in
// pieces), and one allocates the result's arrays, which the slices are then
// copied into in parallel.

#include <cstddef>

#include <gpdr/diagnostics.hpp>
#include <gpdr/files.hpp>

#include "io/read_settings.hpp"
#include "io/text_reader.hpp"
#include "io/vertex_lines.hpp"

namespace gpdr::io::detail {

// How many slices the vertex lines of `in` (after its header) would be cut
// into: 1 when they are read on this thread alone (one thread, a stream, a
// short file).
std::size_t vertex_slices(const TextReader& in, const ReadSettings& settings);

// Reads the `h.count` vertices after the header `in` has just read, in
// vertex_slices() slices (at least 2), and leaves `in` after the last
// vertex line, with the file's content hash for its finish().  Sets `base`
// from the first vertex as read_vertices does.
NodeSet read_vertices_in_parallel(TextReader& in, const NodeHeader& h, int default_base, int& base,
                                  const WarningSink& warn, const ReadSettings& settings);

}  // namespace gpdr::io::detail
