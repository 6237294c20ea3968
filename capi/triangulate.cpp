// libtriangle's entry points: triangulate(), trifree(), gpdr_last_error()
// and gpdr_triangulate_ex().  This layer, not lib/, owns every message:
// unless the switches say 'Q', warnings, what was written, the statistics
// and errors go to standard output, as Triangle's library prints them.
// Errors are returned, never exit(), and no exception crosses into C.
#include <triangle.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include <gpdr/errors.hpp>
#include <gpdr/memory_job.hpp>
#include <gpdr/switches.hpp>

#include "convert.hpp"

// A triunsuitable() for -u, when the program that loads libtriangle defines
// one (as a program linked with Triangle built with -DEXTERNAL_TEST does).
// The reference is weak: without one it is null, and -u is an error.
extern "C" int triunsuitable(double* org, double* dest, double* apex, double area)
    __attribute__((weak));

namespace gpdr::capi {
namespace {

void print_line(std::string_view line) { fmt::print(stdout, "{}\n", line); }

// Warnings as they come, on standard output, unless 'Q'.
WarningSink warning_printer(const Options& options) {
    if (options.quiet) return ignore_warning;
    return [](const Warning& w) {
        if (w.file.empty())
            fmt::print(stdout, "Warning:  {}\n", w.message);
        else
            fmt::print(stdout, "Warning:  {}: {}\n", w.file, w.message);
        std::fflush(stdout);
    };
}

// What Triangle's library prints after a run: which arrays it filled, then
// the statistics (with 'V', also the quality statistics), and what 'C' found.
void print_report(const Options& o, const JobResult& report, bool voronoi) {
    if (report.checked && !report.check_problems.empty()) {
        // Problems are printed even with 'Q': they are the answer to 'C'.
        for (const std::string& problem : report.check_problems)
            print_line(fmt::format("Check: {}", problem));
        print_line(fmt::format("Check: {} problem{} found in the mesh",
                               report.check_problems.size(),
                               report.check_problems.size() == 1 ? "" : "s"));
    }
    if (o.quiet) {
        std::fflush(stdout);
        return;
    }
    print_line("");
    print_line(o.no_node_output ? "NOT writing vertices." : "Writing vertices.");
    print_line(o.no_ele_output ? "NOT writing triangles." : "Writing triangles.");
    if (o.poly || o.convex_hull)
        print_line(o.no_poly_output ? "NOT writing segments." : "Writing segments.");
    if (o.write_edges) print_line("Writing edges.");
    if (voronoi) {
        print_line("Writing Voronoi vertices.");
        print_line("Writing Voronoi edges.");
    }
    if (o.write_neighbours) print_line("Writing neighbors.");
    print_line("");
    for (const std::string& line : report.statistics) print_line(line);
    if (report.checked && report.check_problems.empty())
        print_line("Check: no problems found in the mesh.");
    print_line("");
    std::fflush(stdout);
}

// What a call adds to its switch string.
struct CallOptions {
    unsigned threads = 0;  // 0: as the switches say
    UnsuitableTest unsuitable;
};

// One call, from the switch string to the filled structures.  Throws what
// the library throws, and UsageError for what only this interface refuses.
void run(const char* switches, triangulateio* in, triangulateio* out, triangulateio* vorout,
         const CallOptions& call, Options& options) {
    if (!switches) throw UsageError("the switch string is NULL");
    parse_switches(switches, options, SwitchDialect::library);
    if (!in || !out) throw UsageError("the in and out structures must not be NULL");
    if (options.write_voronoi && !vorout)
        throw UsageError("v: the Voronoi diagram needs a vorout structure, but it is NULL");
    options.command = "triangulate";
    // One thread unless asked: deterministic, and safe for callbacks into
    // an interpreter.
    if (call.threads > 0) options.threads = call.threads;
    if (options.threads == 0) options.threads = 1;
    // Triangle's triangulate() tries whatever it is asked; a library caller
    // sizes its own problems and has no --force to give.
    options.force = true;

    JobPlugins plugins;
    plugins.triunsuitable = &triunsuitable;  // null unless the program defines one
    plugins.unsuitable = call.unsuitable;
    if (options.user_test && !plugins.triunsuitable && !plugins.unsuitable)
        throw UsageError(
            "u: the program defines no triunsuitable() function and passed no unsuitable "
            "callback to gpdr_triangulate_ex()");

    const MemoryJobResult result =
        run_job_in_memory(options, read_input(*in, options), warning_printer(options), plugins);
    write_output(result, options, *in, *out, vorout);
    print_report(options, result.report, options.write_voronoi);
}

// The calling thread's last error, for gpdr_last_error().
thread_local std::string last_error;

// Every count triangulate() writes, set to 0 after a failure.
void clear_counts(triangulateio* io) {
    if (!io) return;
    io->numberofpoints = io->numberofpointattributes = 0;
    io->numberoftriangles = io->numberofcorners = io->numberoftriangleattributes = 0;
    io->numberofsegments = io->numberofholes = io->numberofregions = io->numberofedges = 0;
}

// Runs `run` and turns what it throws into a status, a message kept for
// gpdr_last_error() and printed unless 'Q'.  No exception leaves.
int guarded(const char* switches, triangulateio* in, triangulateio* out, triangulateio* vorout,
            const CallOptions& call) noexcept {
    Options options;
    int status = 0;
    try {
        last_error.clear();
        run(switches, in, out, vorout, call, options);
        return 0;
    } catch (const InputError& e) {
        // The input is the caller's arrays, not a file: the reason alone.
        last_error = e.reason();
        status = 1;
    } catch (const InternalError& e) {
        last_error = std::string(e.what()) + " (an internal error in gpdr: please report it)";
        status = 3;
    } catch (const Error& e) {
        last_error = e.what();
        status = 1;
    } catch (const std::bad_alloc&) {
        last_error = "out of memory";
        status = 2;
    } catch (const std::exception& e) {
        last_error = std::string(e.what()) + " (an internal error in gpdr: please report it)";
        status = 3;
    } catch (...) {
        last_error = "unknown exception (an internal error in gpdr: please report it)";
        status = 3;
    }
    clear_counts(out);
    if (out != vorout) clear_counts(vorout);
    // The switches may have failed to parse before their Q.
    if (!options.quiet && !(switches && std::strchr(switches, 'Q'))) {
        std::fflush(stdout);
        std::printf("Error:  %s\n", last_error.c_str());
        std::fflush(stdout);
    }
    return status;
}

}  // namespace
}  // namespace gpdr::capi

extern "C" {

int triangulate(char* switches, triangulateio* in, triangulateio* out, triangulateio* vorout) {
    return gpdr::capi::guarded(switches, in, out, vorout, {});
}

void trifree(void* memory) { std::free(memory); }

const char* gpdr_last_error(void) { return gpdr::capi::last_error.c_str(); }

int gpdr_triangulate_ex(const char* switches, triangulateio* in, triangulateio* out,
                        triangulateio* vorout, const gpdr_triangulate_options* options) {
    gpdr::capi::CallOptions call;
    // Fields past what the caller's version of the structure holds keep
    // their defaults.
    const auto has = [options](std::size_t end) { return options && options->size >= end; };
    if (has(offsetof(gpdr_triangulate_options, threads) + sizeof options->threads))
        call.threads = options->threads;
    if (has(offsetof(gpdr_triangulate_options, user_data) + sizeof options->user_data) &&
        options->unsuitable) {
        const gpdr_unsuitable_function f = options->unsuitable;
        void* const data = options->user_data;
        call.unsuitable = [f, data](double* org, double* dest, double* apex, double area) {
            return f(data, org, dest, apex, area);
        };
    }
    return gpdr::capi::guarded(switches, in, out, vorout, call);
}

}  // extern "C"
