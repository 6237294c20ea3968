#include "stress/stress_case.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gpdr/errors.hpp>

#include "stress/exact_domain.hpp"
#include "stress/mesh_check.hpp"
#include "stress/random_pslg.hpp"
#include "stress/run_limited.hpp"

namespace gpdr::stress {

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The angle bound a switch word asks for: the number after q, 20 for a bare
// q, 0 without q.
double min_angle_of(const std::string& switches) {
    const auto q = switches.find('q');
    if (q == std::string::npos) return 0;
    const char* start = switches.c_str() + q + 1;
    char* end = nullptr;
    const double angle = std::strtod(start, &end);
    return end == start ? 20 : angle;
}

// The count in gpdr's warning about triangles left because refining them
// would exhaust floating-point precision.
std::size_t left_by_precision(const std::string& err) {
    static const std::regex warning(
        R"((\d+) triangles were left as they are because refining them further would exhaust)");
    std::smatch match;
    if (std::regex_search(err, match, warning)) return std::stoul(match[1]);
    return 0;
}

}  // namespace

const char* verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::right:
            return "right";
        case Verdict::wrong:
            return "wrong";
        case Verdict::failed:
            return "failed";
        case Verdict::hung:
            return "hung";
    }
    return "?";
}

std::vector<std::string> mesher_switches(const Mesher& mesher, const RunSpec& spec,
                                         const PolyFile& input) {
    std::vector<std::string> words{spec.switches + (input.regions.empty() ? "" : "A") + "C"};
    if (mesher.gpdr && spec.threads > 0) words.push_back("-j" + std::to_string(spec.threads));
    return words;
}

Outcome run_case(const Mesher& mesher, const RunSpec& spec, const PolyFile& input,
                 const std::string& comment, const std::string& folder) {
    const fs::path dir(folder);
    for (const char* name : {"in.1.node", "in.1.ele", "in.1.poly"}) fs::remove(dir / name);
    std::ofstream(dir / "in.poly", std::ios::binary) << poly_text(input, comment);

    std::vector<std::string> arguments{mesher.path};
    for (std::string& word : mesher_switches(mesher, spec, input)) arguments.push_back(word);
    arguments.push_back("in.poly");
    const LimitedRun run = run_limited(arguments, folder, (dir / "out.txt").string(),
                                       (dir / "err.txt").string(), spec.time_limit);
    Outcome outcome;
    outcome.seconds = run.seconds;
    const std::string err = slurp(dir / "err.txt");
    if (run.timed_out) {
        outcome.verdict = Verdict::hung;
        char text[80];
        std::snprintf(text, sizeof text, "still running after %g s", spec.time_limit);
        outcome.detail = text;
        return outcome;
    }
    if (run.signal != 0 || run.exit_status != 0) {
        outcome.verdict = Verdict::failed;
        // The last line of the error stream that is not a warning says why.
        std::string last;
        std::istringstream lines(err);
        for (std::string line; std::getline(lines, line);)
            if (line.find("warning") == std::string::npos && !line.empty()) last = line;
        outcome.detail = run.signal != 0
                             ? "killed by signal " + std::to_string(run.signal)
                             : "exit status " + std::to_string(run.exit_status) + ": " + last;
        return outcome;
    }

    std::vector<std::string> problems;
    try {
        const WrittenMesh mesh = read_written_mesh((dir / "in.1").string());
        const ExactDomain domain(input, spec.switches.find('c') != std::string::npos);
        CheckSettings settings;
        settings.min_angle = min_angle_of(spec.switches);
        settings.left_by_precision = mesher.gpdr ? left_by_precision(err) : 0;
        settings.attributes = !input.regions.empty();
        settings.excuse_spanning_edges = !spec.strict_angles;
        problems = check_mesh(input, domain, mesh, settings);
    } catch (const Error& e) {
        problems.push_back(std::string("its output does not read: ") + e.what());
    }
    if (!problems.empty()) {
        outcome.verdict = Verdict::wrong;
        for (const std::string& p : problems)
            outcome.detail += (outcome.detail.empty() ? "" : "; ") + p;
    }
    return outcome;
}

}  // namespace gpdr::stress
