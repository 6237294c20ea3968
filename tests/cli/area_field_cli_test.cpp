// -ra with an .area file: the bounds are a field over the triangles read,
// and every triangle of the refined mesh is held to the bound at its
// centroid, whatever thread made it and whatever cavity it came from.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/cli_support.hpp"
#include "cli/mesh_files.hpp"
#include "geometry/area_field.hpp"
#include "geometry/predicates.hpp"

using namespace gpdr::test;
using gpdr::geometry::Point;

namespace {

constexpr double none = std::numeric_limits<double>::infinity();

// The square (0,0)-(4,4) cut into four triangles around (2,2): 1 at the
// bottom, 2 on the right, 3 at the top, 4 on the left.
const std::string square_node = "5 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 2 2\n";
const std::string square_ele = "4 3 0\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n";

std::string area_file(const std::vector<double>& bounds) {
    std::string s = fmt::format("{}\n", bounds.size());
    for (std::size_t t = 0; t < bounds.size(); ++t) s += fmt::format("{} {}\n", t + 1, bounds[t]);
    return s;
}

// Which of the square's triangles hold p (closed), from the two diagonals'
// exact orientations: a test of its own, apart from the field's grid.
std::vector<int> holders(const Point& p) {
    const double up = gpdr::geometry::orient2d({0, 0}, {4, 4}, p);    // > 0: above y = x
    const double down = gpdr::geometry::orient2d({0, 4}, {4, 0}, p);  // > 0: above y = 4 - x
    std::vector<int> k;
    if (up <= 0 && down <= 0) k.push_back(1);
    if (up <= 0 && down >= 0) k.push_back(2);
    if (up >= 0 && down >= 0) k.push_back(3);
    if (up >= 0 && down <= 0) k.push_back(4);
    return k;
}

Point centroid(const MeshFiles& m, std::size_t t) { return {m.centroid_x(t), m.centroid_y(t)}; }

// The bound at p: the smallest of its holders' (none: +infinity).
double bound_at(const std::vector<double>& bounds, const Point& p) {
    double b = none;
    for (int k : holders(p))
        if (bounds[static_cast<std::size_t>(k - 1)] > 0)
            b = std::min(b, bounds[static_cast<std::size_t>(k - 1)]);
    return b;
}

// Refines the square with these bounds on `threads` threads in a folder of
// its own, checked by -C; returns the mesh.
MeshFiles refine_square(const TempDir& dir, const std::vector<double>& bounds, int threads) {
    dir.write("t.node", square_node);
    dir.write("t.ele", square_ele);
    dir.write("t.area", area_file(bounds));
    const RunResult r = run_gpdr(dir, fmt::format("-QCra -j{} t", threads));
    INFO(r.err);
    REQUIRE(r.status == 0);
    return MeshFiles::read(dir, "t.1");
}

}  // namespace

TEST_CASE("an .area bound holds where it was written and spreads nowhere", "[cli][area]") {
    for (int k = 1; k <= 4; ++k) {
        std::vector<double> bounds(4, -1.0);
        bounds[static_cast<std::size_t>(k - 1)] = 0.01;
        for (int threads : {1, 2}) {
            INFO("bound on input triangle " << k << ", -j" << threads);
            TempDir dir;
            const MeshFiles m = refine_square(dir, bounds, threads);
            std::size_t elsewhere = 0;
            for (std::size_t t = 0; t < m.triangles.size(); ++t) {
                const Point c = centroid(m, t);
                CHECK(m.area(t) <= bound_at(bounds, c) * (1 + 1e-12));
                const auto in = holders(c);
                if (std::find(in.begin(), in.end(), k) == in.end()) ++elsewhere;
            }
            // The bounded triangle (area 4) needs about 4 / 0.01 triangles;
            // the others only the fans that meet its refined edges.
            CHECK(m.triangles.size() >= 400);
            CHECK(4 * elsewhere <= m.triangles.size());
        }
    }
}

TEST_CASE("several .area bounds each hold in their own triangle", "[cli][area]") {
    const std::vector<double> bounds{0.5, 0.05, -1, 0.01};
    for (int threads : {1, 2}) {
        INFO("-j" << threads);
        TempDir dir;
        const MeshFiles m = refine_square(dir, bounds, threads);
        std::size_t in_unbounded = 0;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) {
            const Point c = centroid(m, t);
            CHECK(m.area(t) <= bound_at(bounds, c) * (1 + 1e-12));
            in_unbounded += bound_at(bounds, c) == none ? 1 : 0;
        }
        CHECK(m.triangles.size() < 1000);
        CHECK(in_unbounded < 100);
    }
}

TEST_CASE("the .area field gives the same files for every thread count from 2", "[cli][area]") {
    for (const auto& bounds :
         {std::vector<double>{0.01, -1, -1, -1}, std::vector<double>{0.5, 0.05, -1, 0.01}}) {
        TempDir two, eight;
        refine_square(two, bounds, 2);
        refine_square(eight, bounds, 8);
        REQUIRE(two.files() == eight.files());
        for (const std::string& name : two.files()) {
            INFO(name);
            CHECK(two.read(name) == eight.read(name));
        }
    }
}

// The adaptive loop of Triangle's users: mesh, estimate, write one bound per
// triangle into NAME.area, refine with -rpq30a, repeat.  The estimate here
// asks for small triangles near the corner (30, 10) of the flow channel,
// smaller each round, and leaves the rest at the first mesh's bound.
TEST_CASE("an adaptive loop refines where its bounds shrink", "[cli][area]") {
    TempDir dir;
    std::filesystem::copy_file(project_samples() / "flow.poly", dir / "flow.poly");
    REQUIRE(run_gpdr(dir, "-Qpq30a0.5 flow.poly").status == 0);
    const auto distance = [](const Point& p) { return std::hypot(30 - p.x, 10 - p.y); };
    // Triangles within 8 of the corner, where the bounds shrink, and
    // beyond 12, where they stay and -q30's grading has faded.
    const auto count_near = [&](const MeshFiles& m) {
        std::size_t n = 0;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) n += distance(centroid(m, t)) < 8;
        return n;
    };
    const auto count_far = [&](const MeshFiles& m) {
        std::size_t n = 0;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) n += distance(centroid(m, t)) > 12;
        return n;
    };
    for (int round = 1; round <= 3; ++round) {
        INFO("round " << round);
        const std::string stem = fmt::format("flow.{}", round);
        const MeshFiles before = MeshFiles::read(dir, stem);
        std::vector<double> bounds;
        for (std::size_t t = 0; t < before.triangles.size(); ++t) {
            const double d = distance(centroid(before, t)) / 8;
            bounds.push_back(0.5 * std::min(1.0, std::max(std::pow(16.0, -round), d * d)));
        }
        std::string area = fmt::format("{}\n", bounds.size());
        for (std::size_t t = 0; t < bounds.size(); ++t)
            area += fmt::format("{} {}\n", t + static_cast<std::size_t>(before.base), bounds[t]);
        dir.write(stem + ".area", area);
        const RunResult r = run_gpdr(dir, "-QCrpq30a " + stem);
        INFO(r.err);
        REQUIRE(r.status == 0);  // -C: the invariants and every bound hold
        const MeshFiles after = MeshFiles::read(dir, fmt::format("flow.{}", round + 1));

        // Each triangle meets the bound of the triangle read that holds its
        // centroid.
        std::vector<Point> points;
        for (std::uint32_t v = 0; v < before.nodes.size(); ++v)
            points.push_back({before.point(v)[0], before.point(v)[1]});
        const gpdr::geometry::AreaField field(points, before.triangles.corners,
                                              before.triangles.corners_per_triangle, bounds);
        for (std::size_t t = 0; t < after.triangles.size(); ++t)
            CHECK(after.area(t) <= field.at(centroid(after, t)).area * (1 + 1e-12));
        // More triangles near the corner, as many far from it.
        CHECK(count_near(after) > count_near(before) + 200);
        CHECK(count_far(after) <= count_far(before) + count_far(before) / 50);
    }
}
