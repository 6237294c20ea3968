#pragma once
// What gpdr prints about a run: warnings as they come (stderr), then the
// files written, the -C verdict and the -V statistics (stdout).  -Q silences
// everything except errors and check failures.

#include <cstdio>
#include <string>

#include <gpdr/diagnostics.hpp>
#include <gpdr/job.hpp>
#include <gpdr/options.hpp>

namespace gpdr::app {

// "gpdr: FILE:LINE: warning: MESSAGE", "gpdr: FILE: warning: MESSAGE" or
// "gpdr: warning: MESSAGE", without the newline.
std::string format_warning(const Warning& warning);

// A sink printing each warning on `err` at once, or nothing with -Q.
WarningSink printing_sink(const Options& options, std::FILE* err);

// The exit status of a run whose -C check found problems (and so wrote
// nothing); main.cpp has the others (1 an error, 2 out of memory, 3 an
// internal error), 128 + n a signal.
inline constexpr int check_failed_status = 4;

// Prints the outcome of a finished job and returns the exit status:
// check_failed_status when a -C check found problems, otherwise 0.
int report_result(const Options& options, const JobResult& result, std::FILE* out, std::FILE* err);

}  // namespace gpdr::app
