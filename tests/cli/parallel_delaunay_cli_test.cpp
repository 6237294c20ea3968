// gpdr -jN triangulates a large point set in bands on N threads
// (triangulate/strip_inserter.hpp): -j2, -j3 and -j8 write the same files,
// byte for byte, and the same triangles as -j1, numbered otherwise.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

// Above DelaunayOptions::parallel_from, so that -jN takes the bands.
constexpr std::size_t point_count = 250000;

std::string random_node_file() {
    std::string text = fmt::format("{} 2 0 0\n", point_count);
    std::uint64_t state = 7;
    const auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) / double(std::uint64_t{1} << 53);
    };
    for (std::size_t k = 0; k < point_count; ++k)
        text += fmt::format("{} {:.17g} {:.17g}\n", k + 1, next(), next());
    return text;
}

// The .ele's triangles as corner triples, each rotated to start at its
// lowest corner, sorted.
std::vector<std::array<long, 3>> triangle_set(const std::string& ele) {
    std::istringstream in(ele);
    long count = 0, corners = 0, attributes = 0;
    in >> count >> corners >> attributes;
    std::vector<std::array<long, 3>> out;
    for (long i = 0; i < count; ++i) {
        long id = 0;
        std::array<long, 3> v{};
        in >> id >> v[0] >> v[1] >> v[2];
        std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
        out.push_back(v);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST_CASE("gpdr -jN triangulates a large point set alike on any thread count",
          "[cli][parallel][delaunay]") {
    const std::string text = random_node_file();
    std::string one_ele, two_ele;
    for (const int threads : {1, 2, 3, 8}) {
        TempDir dir;
        dir.write("points.node", text);
        const RunResult r = run_gpdr(dir, fmt::format("-Qj{} points.node", threads));
        INFO("-j" << threads << ": " << r.err);
        REQUIRE(r.status == 0);
        const std::string ele = dir.read("points.1.ele");
        if (threads == 1) {
            one_ele = ele;
        } else if (threads == 2) {
            two_ele = ele;
            REQUIRE(triangle_set(two_ele) == triangle_set(one_ele));
            // (Numbered otherwise: the test would prove nothing if the
            // bands were not taken.)
            REQUIRE(two_ele != one_ele);
        } else {
            REQUIRE(ele == two_ele);
        }
    }
}
