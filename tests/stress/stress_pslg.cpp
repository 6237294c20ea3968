// stress_pslg: meshes many random crossing-heavy PSLGs (random_pslg.hpp)
// with gpdr or Triangle and counts, per switch set, the outputs that are
// wrong by the independent check (mesh_check.hpp), the runs that failed
// (non-zero exit, crash) and those that hung.  scripts/stress-pslg.sh runs it.
//
//   stress_pslg --mesher PATH [--triangle] [--count N] [--first-seed S]
//               [--threads "1 2"] [--time-limit SECONDS] [--keep FOLDER]
//               [--verbose] [--strict-angles] SWITCHES...
//   stress_pslg --mesher PATH [--triangle] --input FILE.poly SWITCHES...
//
// Every switch set meshes the same inputs (seeds S .. S+N-1).  gpdr runs each
// set once per thread count (-jN); --triangle runs Triangle, once per set.
// --keep writes each input that was not right to FOLDER, named by switches,
// threads and seed, with the reason in its first line; --verbose prints each
// such seed and reason as it happens.  Progress goes to stderr.
// --strict-angles counts as wrong the small angles opposite an edge that
// spans a sharp input angle (mesh_check.hpp), which Triangle leaves too.
// --input meshes one .poly (such as one kept by --keep) instead of random
// inputs, and prints its verdict and why for each switch set and thread count.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gpdr/io.hpp>

#include "stress/random_pslg.hpp"
#include "stress/stress_case.hpp"

namespace fs = std::filesystem;
using namespace gpdr::stress;

namespace {

[[noreturn]] void usage(const char* reason) {
    std::fprintf(stderr,
                 "stress_pslg: %s\nusage: stress_pslg --mesher PATH [--triangle] [--count N] "
                 "[--first-seed S] [--threads \"1 2\"] [--time-limit SECONDS] [--keep FOLDER] "
                 "[--verbose] [--strict-angles] [--input FILE.poly] SWITCHES...\n",
                 reason);
    std::exit(2);
}

struct Tally {
    std::size_t inputs = 0;
    std::map<Verdict, std::size_t> counts;
    std::map<Verdict, std::vector<std::uint64_t>> seeds;
};

}  // namespace

int main(int argc, char** argv) {
    Mesher mesher;
    std::size_t count = 10000;
    std::uint64_t first_seed = 1;
    std::vector<int> threads{1, 2};
    double time_limit = 10;
    std::string keep, input;
    bool verbose = false, strict_angles = false;
    std::vector<std::string> switch_sets;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage(("missing value after " + arg).c_str());
            return argv[++i];
        };
        if (arg == "--mesher")
            mesher.path = value();
        else if (arg == "--triangle")
            mesher.gpdr = false;
        else if (arg == "--count")
            count = std::stoul(value());
        else if (arg == "--first-seed")
            first_seed = std::stoull(value());
        else if (arg == "--time-limit")
            time_limit = std::stod(value());
        else if (arg == "--keep")
            keep = value();
        else if (arg == "--input")
            input = value();
        else if (arg == "--verbose")
            verbose = true;
        else if (arg == "--strict-angles")
            strict_angles = true;
        else if (arg == "--threads") {
            threads.clear();
            std::istringstream words(value());
            for (int t; words >> t;) threads.push_back(t);
        } else if (arg.size() > 1 && arg[0] == '-' && arg[1] != '-')
            switch_sets.push_back(arg);
        else
            usage(("unknown argument " + arg).c_str());
    }
    if (mesher.path.empty()) usage("--mesher is required");
    if (switch_sets.empty()) switch_sets = {"-p", "-pc", "-pq20", "-pq30"};
    if (!mesher.gpdr || threads.empty()) threads = {0};
    mesher.path = fs::absolute(mesher.path).string();
    if (!keep.empty()) fs::create_directories(keep);

    char scratch_template[] = "/tmp/stress-pslg-XXXXXX";
    const char* scratch = mkdtemp(scratch_template);
    if (!scratch) usage("cannot make a scratch folder in /tmp");

    if (!input.empty()) {
        const gpdr::PolyFile poly = gpdr::io::read_poly(input, [](const gpdr::Warning&) {}).data;
        for (const std::string& switches : switch_sets)
            for (int t : threads) {
                const Outcome outcome =
                    run_case(mesher, RunSpec{switches, t, time_limit, strict_angles}, poly,
                             "from " + input, scratch);
                std::printf("%s%s: %s%s%s\n", switches.c_str(),
                            t > 0 ? (" -j" + std::to_string(t)).c_str() : "",
                            verdict_name(outcome.verdict), outcome.detail.empty() ? "" : ": ",
                            outcome.detail.c_str());
            }
        fs::remove_all(scratch);
        return 0;
    }

    std::printf(
        "| mesher | switches | family | inputs | wrong | failed | hung | seeds (wrong / failed / "
        "hung) |\n");
    std::printf("|---|---|---|---:|---:|---:|---:|---|\n");
    for (const std::string& switches : switch_sets) {
        for (int t : threads) {
            std::map<Family, Tally> tallies;
            const RunSpec spec{switches, t, time_limit, strict_angles};
            for (std::uint64_t seed = first_seed; seed < first_seed + count; ++seed) {
                const RandomPslg pslg = random_pslg(seed);
                const std::string comment = "random_pslg seed " + std::to_string(seed) + " (" +
                                            family_name(pslg.family) + ")";
                if ((seed - first_seed) % 100 == 0)
                    std::fprintf(stderr, "%s%s: %llu inputs done\n", switches.c_str(),
                                 t > 0 ? (" -j" + std::to_string(t)).c_str() : "",
                                 static_cast<unsigned long long>(seed - first_seed));
                const Outcome outcome = run_case(mesher, spec, pslg.poly, comment, scratch);
                Tally& tally = tallies[pslg.family];
                ++tally.inputs;
                ++tally.counts[outcome.verdict];
                if (outcome.verdict == Verdict::right) continue;
                tally.seeds[outcome.verdict].push_back(seed);
                if (verbose)
                    std::fprintf(stderr, "%s seed %llu: %s: %.300s\n", switches.c_str(),
                                 static_cast<unsigned long long>(seed),
                                 verdict_name(outcome.verdict), outcome.detail.c_str());
                if (!keep.empty()) {
                    std::string name = switches.substr(1);
                    if (t > 0) name += "-j" + std::to_string(t);
                    name += "-seed" + std::to_string(seed) + ".poly";
                    std::ofstream(fs::path(keep) / name) << poly_text(
                        pslg.poly, comment + "; " + switches + " " + verdict_name(outcome.verdict) +
                                       ": " + outcome.detail.substr(0, 300));
                }
            }
            for (auto& [family, tally] : tallies) {
                std::string examples;
                for (Verdict v : {Verdict::wrong, Verdict::failed, Verdict::hung}) {
                    std::string list;
                    const auto& seeds = tally.seeds[v];
                    for (std::size_t k = 0; k < seeds.size() && k < 4; ++k) {
                        if (k > 0) list += ' ';
                        list += std::to_string(seeds[k]);
                    }
                    if (v != Verdict::wrong) examples += " / ";
                    examples += list.empty() ? std::string("-") : list;
                }
                std::string shown = switches;
                if (t > 0) shown += " -j" + std::to_string(t);
                std::printf("| %s | %s | %s | %zu | %zu | %zu | %zu | %s |\n",
                            mesher.gpdr ? "gpdr" : "Triangle", shown.c_str(), family_name(family),
                            tally.inputs, tally.counts[Verdict::wrong],
                            tally.counts[Verdict::failed], tally.counts[Verdict::hung],
                            examples.c_str());
                std::fflush(stdout);
            }
        }
    }
    fs::remove_all(scratch);
    return 0;
}
