// One call, from Python's arguments to Python's results (see call.hpp).
#include "call.hpp"

#include <mutex>
#include <utility>
#include <vector>

#include <gpdr/diagnostics.hpp>
#include <gpdr/errors.hpp>
#include <gpdr/memory_job.hpp>
#include <gpdr/switches.hpp>

#include "errors.hpp"
#include "input_dict.hpp"
#include "output_dict.hpp"
#include "unsuitable.hpp"

namespace gpdr::python {
namespace {

Options options_for(const std::string& opts, const Extras& extras, const UserTest& test) {
    Options o;
    // Every index is 0-based in memory; z only makes messages count from 0 too.
    o.zero_based = true;
    parse_switches(opts, o, SwitchDialect::library);
    o.command = "gpdr.triangulate";
    if (extras.threads) {
        if (*extras.threads < 0) raise_error("threads must be 0 (every hardware thread) or more");
        o.threads = static_cast<unsigned>(*extras.threads);
        // 0 asks for every hardware thread, as the program's -j0 does.
    } else if (o.threads == 0) {
        // One thread unless asked, as libtriangle: a call never competes
        // with the caller's own threads unasked, and makes the same mesh every time.
        o.threads = 1;
    }
    if (!extras.placement.is_none())
        o.placement = parse_placement(std::string(py::str(extras.placement)));
    if (extras.check) o.check = true;
    if (extras.force) o.force = true;
    if (test.given()) o.user_test = true;
    if (o.user_test && !test.given())
        raise_error(
            "u: the switches ask for triunsuitable(), but triunsuitable= names none (a Python "
            "callable (org, dest, apex, area) -> bool, or the path of a shared object exporting "
            "triunsuitable)");
    // Python code runs one call at a time under the GIL: more threads would
    // only wait for it.
    if (test.needs_one_thread()) o.threads = 1;
    return o;
}

// Warnings arrive while the GIL is released, possibly from several threads;
// they are kept and issued once the call holds the GIL again.
class WarningQueue {
public:
    WarningSink sink() {
        return [this](const Warning& w) {
            std::string text = w.message;
            if (!w.file.empty() && w.file != input_name)
                text = w.file + (w.line > 0 ? ":" + std::to_string(w.line) : "") + ": " + text;
            const std::lock_guard lock(mutex_);
            messages_.push_back(std::move(text));
        };
    }
    void issue() {
        for (const std::string& message : messages_) warn(message);
    }

private:
    std::mutex mutex_;
    std::vector<std::string> messages_;
};

// V without Q: the statistics, on sys.stdout, as the program prints them.
void print_report(const Options& o, const JobResult& report) {
    if (o.verbosity == 0 || o.quiet) return;
    for (const std::string& line : report.statistics) py::print(line);
    if (report.checked && report.check_problems.empty())
        py::print("Check: no problems found in the mesh.");
}

}  // namespace

py::tuple run(py::handle tri, const std::string& opts, const Extras& extras) {
    ConvertedInput input = read_input(tri);
    const UserTest test(extras.triunsuitable, input.mesh.nodes.attribute_count);
    const Options o = options_for(opts, extras, test);
    const JobPlugins plugins = test.plugins();
    WarningQueue warnings;
    const WarningSink sink = warnings.sink();

    MemoryJobResult result;
    try {
        py::gil_scoped_release released;
        result = run_job_in_memory(o, std::move(input.mesh), sink, plugins);
    } catch (...) {
        warnings.issue();  // what came before the failure, then the failure
        throw;
    }
    warnings.issue();
    print_report(o, result.report);
    if (result.report.checked && !result.report.check_problems.empty())
        raise_check_error(result.report.check_problems);

    py::dict mesh = mesh_dict(result.mesh, o, input);
    py::object voronoi = o.write_voronoi ? py::object(voronoi_dict(result.mesh)) : py::none();
    return py::make_tuple(mesh, voronoi);
}

}  // namespace gpdr::python
