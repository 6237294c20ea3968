// Prints a run's warnings and results.  Unlike Triangle, which prints
// everything on stdout, warnings and errors go to stderr so that a script
// can read stdout cleanly (man/gpdr.1, DEVIATIONS FROM TRIANGLE).
#include "report.hpp"

#include <fmt/format.h>

namespace gpdr::app {

std::string format_warning(const Warning& warning) {
    if (warning.file.empty()) return fmt::format("gpdr: warning: {}", warning.message);
    if (warning.line == 0)
        return fmt::format("gpdr: {}: warning: {}", warning.file, warning.message);
    return fmt::format("gpdr: {}:{}: warning: {}", warning.file, warning.line, warning.message);
}

WarningSink printing_sink(const Options& options, std::FILE* err) {
    if (options.quiet) return ignore_warning;
    return [err](const Warning& warning) {
        fmt::print(err, "{}\n", format_warning(warning));
        std::fflush(err);
    };
}

int report_result(const Options& options, const JobResult& result, std::FILE* out, std::FILE* err) {
    int status = 0;
    if (!options.quiet)
        for (const std::string& file : result.files_written) fmt::print(out, "Wrote {}\n", file);

    if (options.check) {
        if (!result.checked) {
            // Asked for and not done must not look like "no problems".
            if (!options.quiet) fmt::print(err, "gpdr: warning: the mesh was not checked (-C)\n");
        } else if (result.check_problems.empty()) {
            if (!options.quiet) fmt::print(out, "Check: no problems found in the mesh.\n");
        } else {
            for (const std::string& problem : result.check_problems)
                fmt::print(err, "gpdr: check: {}\n", problem);
            fmt::print(err, "gpdr: check: {} problem{} found in the mesh; no file written\n",
                       result.check_problems.size(), result.check_problems.size() == 1 ? "" : "s");
            status = check_failed_status;
        }
    }

    if (options.verbosity > 0)
        for (const std::string& line : result.statistics) fmt::print(out, "{}\n", line);
    std::fflush(out);
    return status;
}

}  // namespace gpdr::app
