// --vtk and --gmsh: the files for other programs are written beside
// Triangle's, named like them (-I included), and the .vtu read back holds
// exactly the mesh of the .node and .ele files (scripts/../tests/formats
// has meshio read both formats too).

#include <catch2/catch.hpp>

#include <string>

#include "cli/cli_support.hpp"
#include "cli/mesh_files.hpp"
#include "io/vtu_reader.hpp"

using namespace gpdr::test;

TEST_CASE("the .vtu of a run holds the mesh of its .node and .ele", "[cli][formats]") {
    const std::string switches = GENERATE(as<std::string>{}, "-pq30a0.2", "-pq -z -o2");
    INFO(switches);
    TempDir dir;
    fs::copy_file(test_data() / "letter.poly", dir / "letter.poly");
    const RunResult r = run_gpdr(dir, switches + " --vtk letter.poly");
    REQUIRE(r.status == 0);
    CHECK(r.out.find("Wrote letter.1.vtu\n") != std::string::npos);
    const MeshFiles mesh = MeshFiles::read(dir, "letter.1");
    const VtuFile vtu(dir.read("letter.1.vtu"));

    REQUIRE(vtu.points() == mesh.nodes.size());
    REQUIRE(vtu.cells() == mesh.triangles.size());
    const auto points = vtu.values<double>("Points", "Float64");
    for (std::size_t v = 0; v < mesh.nodes.size(); ++v) {
        REQUIRE(points[3 * v] == mesh.nodes.xy[2 * v]);
        REQUIRE(points[3 * v + 1] == mesh.nodes.xy[2 * v + 1]);
    }
    const std::uint32_t nc = mesh.triangles.corners_per_triangle;
    const auto connectivity = vtu.integers("connectivity");
    REQUIRE(connectivity.size() == mesh.triangles.corners.size());
    static constexpr int vtk_order[6] = {0, 1, 2, 5, 3, 4};
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t k = 0; k < nc; ++k)
            REQUIRE(connectivity[t * nc + k] == mesh.corner(t, vtk_order[k]));
    const auto markers = vtu.values<std::int32_t>("boundary_marker", "Int32");
    CHECK(std::vector<int>(markers.begin(), markers.end()) == mesh.nodes.markers);
    REQUIRE(mesh.nodes.attribute_count == 1);
    CHECK(vtu.values<double>("attribute_0", "Float64") == mesh.nodes.attributes);
    const auto angles = vtu.values<float>("min_angle", "Float32");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        REQUIRE(angles[t] == Approx(mesh.smallest_angle(t)).epsilon(1e-6));
}

TEST_CASE("with -I the files for other programs have no iteration number", "[cli][formats]") {
    TempDir dir;
    fs::copy_file(test_data() / "box_hole.poly", dir / "box_hole.poly");
    const RunResult r = run_gpdr(dir, "-pcqI --vtk --gmsh box_hole.poly");
    REQUIRE(r.status == 0);
    CHECK(dir.files() == std::vector<std::string>{"box_hole.ele", "box_hole.msh", "box_hole.node",
                                                  "box_hole.poly", "box_hole.vtu"});
    CHECK(dir.read("box_hole.msh").rfind("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n", 0) == 0);
}
