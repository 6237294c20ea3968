// The stress test's own checker on inputs and meshes whose answers are known
// by hand: it must accept a right mesh and name what is wrong with a wrong one.

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include <gpdr/io.hpp>

#include "stress/exact_domain.hpp"
#include "stress/mesh_check.hpp"

using namespace gpdr::stress;

namespace {

// The unit square with both diagonals as segments: they cross at (0.5, 0.5).
gpdr::PolyFile square_with_diagonals() {
    gpdr::PolyFile poly;
    poly.nodes.xy = {0, 0, 1, 0, 1, 1, 0, 1};
    poly.segments.endpoints = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 1, 3};
    return poly;
}

// Its right mesh: four triangles around the crossing point.
WrittenMesh four_triangles() {
    WrittenMesh mesh;
    mesh.xy = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    mesh.triangles = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    return mesh;
}

bool mentions(const std::vector<std::string>& problems, const std::string& text) {
    for (const std::string& p : problems)
        if (p.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE("stress checker: the exact domain", "[stress][checker]") {
    const ExactDomain square(square_with_diagonals(), false);
    CHECK(square.area() == 1.0);
    CHECK(square.required_vertices().size() == 4);
    std::size_t crossings = 0;
    for (const ArrangementPoint& p : square.points()) crossings += p.crossing;
    CHECK(crossings == 1);
    CHECK(square.edges().size() == 8);

    // Two crossing segments enclose nothing; with -c the hull is the domain.
    gpdr::PolyFile cross;
    cross.nodes.xy = {0, 0, 2, 2, 2, 0, 0, 2};
    cross.segments.endpoints = {0, 1, 2, 3};
    CHECK(ExactDomain(cross, false).area() == 0);
    CHECK(ExactDomain(cross, false).required_vertices().empty());
    CHECK(ExactDomain(cross, true).area() == 4.0);

    // A hole removes the face it lies in, and only that face.
    gpdr::PolyFile holed = square_with_diagonals();
    holed.holes = {0.5, 0.2};
    CHECK(ExactDomain(holed, false).area() == 0.75);

    // The reproducer whose domain has area 3.025 (vertex 1 lies on segment 2).
    const auto a = gpdr::io::read_poly(
        (std::filesystem::path(GPDR_SOURCE_DIR) / "tests/data/crossings/a.poly").string(),
        gpdr::ignore_warning);
    CHECK(ExactDomain(a.data, false).area() == Approx(3.025).epsilon(1e-12));

    // A segment bends through a vertex within rounding of it, and a third
    // segment crosses the pieces, not the straight segment.  Here the
    // vertex (0.3, 0.5) lies 1e-17 off the segment from (0, 0.6) to
    // (0.6, 0.4), whose second half another segment repeats; with the
    // straight segment, the crossing segment x = 0.4 would close a sliver
    // between the two, and the open chain would enclose a face.
    gpdr::PolyFile bent;
    bent.nodes.xy = {0.30000000000000004,
                     0.5,
                     0,
                     0.60000000000000009,
                     0.60000000000000009,
                     0.40000000000000002,
                     0.4,
                     0.5,
                     0.4,
                     0.30000000000000004};
    bent.segments.endpoints = {1, 2, 2, 0, 3, 4};
    const ExactDomain open_chain(bent, false);
    CHECK(open_chain.area() == 0);
    CHECK(open_chain.required_vertices().empty());
    std::size_t bent_crossings = 0;
    for (const ArrangementPoint& p : open_chain.points()) bent_crossings += p.crossing;
    CHECK(bent_crossings == 1);
}

TEST_CASE("stress checker: right and wrong meshes", "[stress][checker]") {
    const gpdr::PolyFile input = square_with_diagonals();
    const ExactDomain domain(input, false);
    CHECK(check_mesh(input, domain, four_triangles(), {}).empty());

    WrittenMesh missing = four_triangles();
    missing.triangles.resize(9);
    const auto lost = check_mesh(input, domain, missing, {});
    CHECK(mentions(lost, "area"));
    CHECK(mentions(lost, "segment 4 from (0, 0) to (0, 1) is not covered"));

    WrittenMesh moved = four_triangles();
    moved.xy[8] = 0.501;
    const auto off = check_mesh(input, domain, moved, {});
    CHECK(mentions(off, "crossing at (0.5, 0.5) is not a mesh vertex"));

    // Two triangles over the square: the diagonal 1-3 is not covered.
    WrittenMesh uncovered;
    uncovered.xy = {0, 0, 1, 0, 1, 1, 0, 1};
    uncovered.triangles = {0, 1, 2, 0, 2, 3};
    CHECK(mentions(check_mesh(input, domain, uncovered, {}), "not a mesh vertex"));

    WrittenMesh clockwise = four_triangles();
    std::swap(clockwise.triangles[0], clockwise.triangles[1]);
    CHECK(mentions(check_mesh(input, domain, clockwise, {}), "clockwise"));

    // Angles of 45 degrees: fine for 30, not for 50 where the square's
    // corners are input angles of 90 degrees, which excuse nothing; with the
    // diagonals, each corner is two input angles of 45 degrees.
    gpdr::PolyFile plain = input;
    plain.segments.endpoints.resize(8);
    const ExactDomain plain_domain(plain, false);
    CheckSettings quality;
    quality.min_angle = 30;
    CHECK(check_mesh(plain, plain_domain, four_triangles(), quality).empty());
    quality.min_angle = 50;
    CHECK(mentions(check_mesh(plain, plain_domain, four_triangles(), quality),
                   "4 triangles have an angle below 50"));
    CHECK(check_mesh(input, domain, four_triangles(), quality).empty());
    quality.left_by_precision = 4;
    CHECK(check_mesh(plain, plain_domain, four_triangles(), quality).empty());

    // Regions: the attribute of the later region point wins in its face.
    gpdr::PolyFile regions = input;
    regions.regions = {{0.5, 0.2, 1, -1}, {0.5, 0.8, 2, -1}};
    const ExactDomain regioned(regions, false);
    WrittenMesh attributed = four_triangles();
    attributed.attributes = {1, 0, 2, 0};
    CheckSettings with_attributes;
    with_attributes.attributes = true;
    CHECK(check_mesh(regions, regioned, attributed, with_attributes).empty());
    attributed.attributes = {2, 0, 1, 0};
    CHECK(mentions(check_mesh(regions, regioned, attributed, with_attributes), "attribute"));
}

TEST_CASE("stress checker: small angles near a sharp input angle", "[stress][checker]") {
    // A triangle with an angle of 11.3 degrees at (0, 0); p and q lie on its
    // two sides at distance 1 from there, as concentric shells put them.
    gpdr::PolyFile input;
    input.nodes.xy = {0, 0, 10, 0, 10, 2};
    input.segments.endpoints = {0, 1, 1, 2, 2, 0};
    const ExactDomain domain(input, false);
    WrittenMesh mesh;
    const double s = std::sqrt(104.0);
    mesh.xy = {0, 0, 10, 0, 10, 2, 1, 0, 10 / s, 2 / s};
    mesh.triangles = {0, 3, 4, 3, 1, 4, 1, 2, 4};
    CheckSettings quality;
    quality.min_angle = 10;
    // The angle of 1.2 degrees at (10, 0) is opposite the edge pq.
    CHECK(check_mesh(input, domain, mesh, quality).empty());
    quality.excuse_spanning_edges = false;
    CHECK(mentions(check_mesh(input, domain, mesh, quality), "1 triangles have an angle below 10"));
}
