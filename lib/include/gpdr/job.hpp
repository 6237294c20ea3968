#pragma once
// One run of gpdr, as the command line describes it: read the input files,
// triangulate, refine, write the output files.  This is what apps/gpdr calls
// once it has turned argv into Options.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <gpdr/diagnostics.hpp>
#include <gpdr/options.hpp>
#include <gpdr/progress.hpp>

namespace gpdr {

struct JobResult {
    std::vector<std::string> files_written;  // in the order they were renamed into place

    std::uint64_t input_vertices = 0;
    std::uint64_t vertices = 0;  // in the output mesh
    std::uint64_t triangles = 0;
    std::uint64_t segments = 0;  // subsegments in the output mesh
    std::uint64_t edges = 0;
    std::uint64_t hull_edges = 0;

    // Seconds spent in each stage.
    double read_seconds = 0, triangulate_seconds = 0, refine_seconds = 0, write_seconds = 0;

    // -C: what the invariant checker found (empty when it found nothing).
    bool checked = false;
    std::vector<std::string> check_problems;

    // Human-readable statistics lines prepared by the library (no printing
    // happens in the library): timings and counts always; with -V also the
    // threads' times and the quality statistics.  apps/gpdr prints them for
    // -V, libtriangle unless Q.
    std::vector<std::string> statistics;
};

// Triangle's user test: non-zero means "refine this triangle".  Each pointer
// gives x, y of a corner (counter-clockwise); area is positive.  gpdr calls it
// from several threads at once, so it must be thread-safe.
using Triunsuitable = int (*)(double* org, double* dest, double* apex, double area);

// The same test as a function object, which may carry data of its own (a
// library caller's callback and its user data).
using UnsuitableTest = std::function<int(double* org, double* dest, double* apex, double area)>;

// Code the application plugs into the job (linked in, or loaded with dlopen).
// -u needs one of the two; `unsuitable` wins when both are set.
struct JobPlugins {
    Triunsuitable triunsuitable = nullptr;
    UnsuitableTest unsuitable;
};

// Runs the whole job.  Throws gpdr::Error subclasses on bad input or output;
// warnings go to `warn` (the caller silences them for -Q).  With `progress`,
// the job records there what it is doing, for the caller to show.
JobResult run_job(const Options& options, const WarningSink& warn, const JobPlugins& plugins = {},
                  Progress* progress = nullptr);

}  // namespace gpdr
