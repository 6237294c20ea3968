// gpdr's entry point: argv -> Options -> gpdr::run_job() -> messages and an
// exit status.  No geometry here; every error the library reports arrives as
// an exception and leaves as "gpdr: <message>" on stderr with the exit status
// its kind calls for (exit_error and the others below).
//
// This file is also what a user links with libgpdr.a and their own
// triunsuitable() object to build a custom gpdr (see apps/CMakeLists.txt).
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include <gpdr/errors.hpp>
#include <gpdr/job.hpp>

#include "command_line.hpp"
#include "help_text.hpp"
#include "progress_line.hpp"
#include "report.hpp"
#include "signals.hpp"
#include "unsuitable.hpp"

namespace {

int run(int argc, const char* const* argv) {
    using gpdr::app::CommandLine;
    const CommandLine line = gpdr::app::parse_command_line(argc, argv);
    switch (line.action) {
        case CommandLine::Action::usage:
            fmt::print("{}", gpdr::app::usage_text());
            return 0;
        case CommandLine::Action::help:
            fmt::print("{}", gpdr::app::help_text());
            return 0;
        case CommandLine::Action::version:
            fmt::print("{}", gpdr::app::version_text());
            return 0;
        case CommandLine::Action::run:
            break;
    }
    gpdr::app::remove_temporaries_on_signals();
    // &triunsuitable is null unless the user linked one in; the weak
    // reference is taken here, in main's object (see unsuitable.hpp).
    const gpdr::app::LoadedPlugins loaded = gpdr::app::load_plugins(line.options, &triunsuitable);
    // On a terminal, a line that says what a long run is doing; warnings
    // erase it before they are printed.
    gpdr::Progress progress;
    std::optional<gpdr::app::ProgressLine> progress_line;
    gpdr::WarningSink sink = gpdr::app::printing_sink(line.options, stderr);
    if (gpdr::app::wants_progress_line(line.options, stderr)) {
        progress_line.emplace(progress, stderr);
        sink = [&progress_line, print = sink](const gpdr::Warning& w) {
            progress_line->interrupt([&] { print(w); });
        };
    }
    const gpdr::JobResult result =
        gpdr::run_job(line.options, sink, loaded.plugins, progress_line ? &progress : nullptr);
    progress_line.reset();  // erased before the results are printed
    return gpdr::app::report_result(line.options, result, stdout, stderr);
}

// Exit statuses (man/gpdr.1, EXIT STATUS; README's table).
constexpr int exit_error = 1;           // the input, the switches, a file, the mesh's size
constexpr int exit_out_of_memory = 2;   // as libtriangle's triangulate() returns
constexpr int exit_internal_error = 3;  // a bug in gpdr

// Prints "gpdr: <what><note>" on stderr and returns `status`; two parts so
// that reporting an internal error needs no allocation.
int fail(int status, std::string_view what, std::string_view note = {}) {
    std::fflush(stdout);
    fmt::print(stderr, "gpdr: {}{}\n", what, note);
    return status;
}

constexpr std::string_view please_report =
    " (an internal error: please report it, with the input and the command line)";

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const gpdr::InternalError& e) {
        return fail(exit_internal_error, e.what(), please_report);
    } catch (const gpdr::ResourceError& e) {
        return fail(exit_error, e.what(), "; use --force to try anyway");
    } catch (const gpdr::Error& e) {
        // Every other error, a CapacityError's included: a mesh larger than
        // gpdr's ids can number is refused like the input that asks for it,
        // and no --force would help.
        return fail(exit_error, e.what());
    } catch (const std::bad_alloc&) {
        return fail(exit_out_of_memory, "out of memory");
    } catch (const std::exception& e) {
        return fail(exit_internal_error, e.what(), please_report);
    } catch (...) {
        return fail(exit_internal_error, "unknown exception", please_report);
    }
}
