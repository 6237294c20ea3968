// Meshing inputs whose segments cross, overlap and pass through vertices:
// the three reproducers in tests/data/crossings/ and a few hundred random
// PSLGs (random_pslg.hpp), each meshed by the built gpdr with -C under a
// time limit and checked against the input by the test's own exact check
// (mesh_check.hpp).  A hang, a crash and a clean error exit all fail: every
// input here is valid.  scripts/stress-pslg.sh runs thousands.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gpdr/io.hpp>

#include "cli/cli_support.hpp"
#include "stress/random_pslg.hpp"
#include "stress/stress_case.hpp"

namespace fs = std::filesystem;
using namespace gpdr::stress;

namespace {

const Mesher gpdr_exe{GPDR_EXE, true};
constexpr double time_limit = 10;  // seconds; these inputs mesh in milliseconds

// Random inputs per switch set; GPDR_STRESS_INPUTS overrides it.
std::uint64_t inputs_per_switch_set() {
    const char* value = std::getenv("GPDR_STRESS_INPUTS");
    return value ? std::stoull(value) : 64;
}

}  // namespace

TEST_CASE("crossing reproducers", "[stress]") {
    const fs::path data = fs::path(GPDR_SOURCE_DIR) / "tests" / "data" / "crossings";
    const gpdr::test::TempDir scratch;
    for (const char* name : {"a.poly", "b.poly", "c.poly", "near-end.poly", "hull-bend.poly"}) {
        const auto input = gpdr::io::read_poly((data / name).string(), gpdr::ignore_warning).data;
        for (const char* switches : {"-p", "-pc", "-pq20", "-pq30"}) {
            const Outcome outcome = run_case(gpdr_exe, RunSpec{switches, 0, time_limit}, input,
                                             name, scratch.path().string());
            INFO(name << " " << switches << "C: " << verdict_name(outcome.verdict) << ": "
                      << outcome.detail);
            CHECK(outcome.verdict == Verdict::right);
        }
    }
}

// Each switch set meshes its own seeds, with one worker thread and with two.
// An input that is not right is written to GPDR_STRESS_FAILURES, named by
// its switches, thread count and seed, and the failure names the file.
TEST_CASE("random PSLGs", "[stress]") {
    const std::uint64_t count = inputs_per_switch_set();
    const fs::path failures = GPDR_STRESS_FAILURES;
    const gpdr::test::TempDir scratch;
    const char* switch_sets[] = {"-p", "-pc", "-pq20", "-pq30"};
    for (std::uint64_t set = 0; set < 4; ++set) {
        const std::string switches = switch_sets[set];
        const std::uint64_t first_seed = 100000 * (set + 1);
        for (std::uint64_t seed = first_seed; seed < first_seed + count; ++seed) {
            const RandomPslg pslg = random_pslg(seed);
            const std::string comment =
                "random_pslg seed " + std::to_string(seed) + " (" + family_name(pslg.family) + ")";
            for (int threads : {1, 2}) {
                const RunSpec spec{switches, threads, time_limit};
                const Outcome outcome =
                    run_case(gpdr_exe, spec, pslg.poly, comment, scratch.path().string());
                std::string kept = "-";
                if (outcome.verdict != Verdict::right) {
                    fs::create_directories(failures);
                    const fs::path file =
                        failures / (switches.substr(1) + "-j" + std::to_string(threads) + "-seed" +
                                    std::to_string(seed) + ".poly");
                    std::ofstream(file) << poly_text(pslg.poly, comment);
                    kept = file.string();
                }
                std::string command = "gpdr";
                for (const std::string& word : mesher_switches(gpdr_exe, spec, pslg.poly))
                    command += " " + word;
                INFO("seed " << seed << " (" << family_name(pslg.family) << "), " << command << ": "
                             << verdict_name(outcome.verdict) << ": " << outcome.detail
                             << "\n  input: " << kept);
                CHECK(outcome.verdict == Verdict::right);
            }
        }
    }
}
