// A bound out of reach above 34 degrees, through the library as libtriangle
// calls it (run_job_in_memory): the warning names the angle reached, -C
// reports the unmet bound, -V lists the tries; a reachable bound says
// nothing.

#include <catch2/catch.hpp>

#include <regex>
#include <string>
#include <vector>

#include <gpdr/diagnostics.hpp>
#include <gpdr/io.hpp>
#include <gpdr/memory_job.hpp>
#include <gpdr/switches.hpp>

using namespace gpdr;

namespace {

MeshInput model(const std::string& name) {
    const PolyFile poly =
        io::read_poly(std::string(GPDR_SOURCE_DIR) + "/tests/data/models/" + name + ".poly",
                      ignore_warning)
            .data;
    MeshInput in;
    in.nodes = poly.nodes;
    in.segments = poly.segments;
    in.holes = poly.holes;
    in.regions = poly.regions;
    in.name = name;
    return in;
}

struct Outcome {
    MemoryJobResult result;
    std::vector<std::string> warnings;
};

Outcome run(const std::string& switches, const std::string& name) {
    Options o;
    parse_switches(switches, o);
    Outcome out;
    out.result = run_job_in_memory(o, model(name),
                                   [&](const Warning& w) { out.warnings.push_back(w.message); });
    return out;
}

}  // namespace

TEST_CASE("the library warns of a bound out of reach and names the angle reached",
          "[memory_job][high-angle]") {
    const Outcome out = run("-pq38j1CV", "channel");
    std::smatch reached;
    bool named = false;
    for (const std::string& w : out.warnings)
        named =
            named || std::regex_search(w, reached, std::regex("reached ([0-9.]+) degrees of 38"));
    INFO(out.warnings.size() << " warnings");
    REQUIRE(named);
    CHECK(std::stod(reached[1]) >= 34);
    CHECK(std::stod(reached[1]) < 38);
    const JobResult& r = out.result.report;
    REQUIRE(r.checked);
    REQUIRE(r.check_problems.size() == 1);
    CHECK(r.check_problems[0].find("38 degrees was not met") != std::string::npos);
    std::size_t tries = 0;
    for (const std::string& line : r.statistics) tries += line.find("  tried ") == 0 ? 1 : 0;
    CHECK(tries > 2);  // 38 with each placement, 34, then bounds between
}

TEST_CASE("a reachable bound above 34 degrees draws no warning", "[memory_job][high-angle]") {
    const Outcome out = run("-pq36j1C", "star");
    CHECK(out.warnings.empty());
    CHECK(out.result.report.check_problems.empty());
}
