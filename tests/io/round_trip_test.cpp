// Round trips: data written by the io writers and read back by the io
// readers is bit-for-bit what was written, for every format, both
// numbering bases, attributes and markers, and awkward doubles (0.1,
// 1e-300, -0.0, 1/3, denormals, the largest double).  Also the exact text
// of small files, where Triangle's layout and the trailing comment matter.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include <gpdr/io.hpp>

#include "io/io_test_support.hpp"

using namespace gpdr;
using gpdr::test::same_bits;
using gpdr::test::TempDir;

namespace {

const std::vector<double> awkward = {0.1,
                                     1e-300,
                                     -0.0,
                                     1.0 / 3.0,
                                     -2.0 / 3.0,
                                     0.0,
                                     1e300,
                                     4.9406564584124654e-324,
                                     std::numeric_limits<double>::max(),
                                     -std::numeric_limits<double>::min(),
                                     123456789.125,
                                     -7,
                                     0.30000000000000004,
                                     2.5e-8};

double pick(std::mt19937_64& rng, std::size_t i) {
    if (i < awkward.size()) return awkward[i];
    return std::uniform_real_distribution<double>(-1e3, 1e3)(rng);
}

NodeSet make_nodes(std::size_t n, std::uint32_t attrs, bool markers, std::mt19937_64& rng) {
    NodeSet s;
    s.attribute_count = attrs;
    for (std::size_t i = 0; i < 2 * n; ++i) s.xy.push_back(pick(rng, i));
    for (std::size_t i = 0; i < n * attrs; ++i) s.attributes.push_back(pick(rng, (i + 3) % 20));
    if (markers)
        for (std::size_t i = 0; i < n; ++i) s.markers.push_back(static_cast<int>(i % 5) - 2);
    return s;
}

void check_same(const NodeSet& a, const NodeSet& b) {
    CHECK(same_bits(a.xy, b.xy));
    CHECK(a.attribute_count == b.attribute_count);
    CHECK(same_bits(a.attributes, b.attributes));
    CHECK(a.markers == b.markers);
}

io::WriteFormat format(int base) {
    io::WriteFormat f;
    f.base = base;
    f.command = "gpdr -pq box.poly";
    return f;
}

std::string last_line(const std::string& text) {
    const auto end = text.find_last_not_of('\n');
    return text.substr(text.rfind('\n', end) + 1, end - text.rfind('\n', end));
}

}  // namespace

TEST_CASE("round trip of every format, both bases", "[io][round-trip]") {
    const int base = GENERATE(0, 1);
    const std::uint32_t attrs = GENERATE(0u, 2u);
    const bool markers = GENERATE(false, true);
    CAPTURE(base, attrs, markers);
    std::mt19937_64 rng(42 + base);
    TempDir dir;
    const auto path = [&](const char* name) { return (dir / name).string(); };

    const NodeSet nodes = make_nodes(40, attrs, markers, rng);

    PolyFile poly;
    poly.nodes = nodes;
    for (std::uint32_t i = 0; i < 40; ++i) {
        poly.segments.endpoints.push_back(i);
        poly.segments.endpoints.push_back((i * 7 + 1) % 40);
        if (markers) poly.segments.markers.push_back(static_cast<int>(i) - 20);
    }
    poly.holes = {0.1, -0.0, 1.0 / 3.0, 1e-300};
    poly.regions = {Region{0.1, 0.2, 3, 0.5}, Region{-0.0, 1.0 / 3.0, -1.0 / 3.0, -1}};

    EleSet ele3, ele6;
    ele6.corners_per_triangle = 6;
    ele3.attribute_count = ele6.attribute_count = attrs;
    for (std::uint32_t t = 0; t < 30; ++t) {
        for (std::uint32_t c = 0; c < 6; ++c) {
            if (c < 3) ele3.corners.push_back((t + c * 11) % 40);
            ele6.corners.push_back((t * 3 + c * 5) % 40);
        }
        for (std::uint32_t a = 0; a < attrs; ++a) {
            ele3.attributes.push_back(pick(rng, (t + a) % 20));
            ele6.attributes.push_back(pick(rng, (t * 2 + a) % 20));
        }
    }
    AreaSet areas;
    for (std::size_t t = 0; t < 30; ++t) areas.push_back(t % 3 == 0 ? -1.0 : pick(rng, t));
    EdgeSet edges;
    for (std::uint32_t e = 0; e < 50; ++e) {
        edges.endpoints.push_back(e % 40);
        edges.endpoints.push_back((e + 1) % 40);
        if (markers) edges.markers.push_back(static_cast<int>(e % 2));
    }
    NeighbourSet neigh;
    for (std::uint32_t t = 0; t < 30; ++t)
        for (std::uint32_t j = 0; j < 3; ++j)
            neigh.neighbours.push_back((t + j) % 4 == 0 ? NeighbourSet::none : (t + j * 7) % 30);
    io::VoronoiEdgeSet vedges;
    for (std::uint32_t e = 0; e < 20; ++e) {
        vedges.endpoints.push_back(e % 30);
        const bool ray = e % 3 == 0;
        vedges.endpoints.push_back(ray ? io::VoronoiEdgeSet::ray : (e + 5) % 30);
        vedges.directions.push_back(ray ? pick(rng, e) + 1 : 0.0);
        vedges.directions.push_back(ray ? -0.5 : 0.0);
    }
    NodeSet vnodes = make_nodes(30, attrs, false, rng);

    {
        io::OutputTransaction tx;
        io::write_node(tx, path("m.node"), nodes, format(base));
        io::write_poly(tx, path("m.poly"), poly, format(base));
        io::write_ele(tx, path("m3.ele"), ele3, format(base));
        io::write_ele(tx, path("m6.ele"), ele6, format(base));
        io::write_area(tx, path("m3.area"), areas, format(base));
        io::write_edge(tx, path("m.edge"), edges, format(base));
        io::write_neigh(tx, path("m3.neigh"), neigh, format(base));
        io::write_node(tx, path("m.v.node"), vnodes, format(base));
        io::write_voronoi_edge(tx, path("m.v.edge"), vedges, format(base));
        tx.commit();
        CHECK(tx.files().size() == 9);
    }

    test::WarningLog log;
    const auto n = io::read_node(path("m.node"), log.sink(), 1 - base);
    CHECK(n.base == base);
    check_same(n.data, nodes);

    const auto p = io::read_poly(path("m.poly"), log.sink(), 1 - base);
    CHECK(p.base == base);
    CHECK_FALSE(p.data.nodes_from_node_file);
    check_same(p.data.nodes, nodes);
    CHECK(p.data.segments.endpoints == poly.segments.endpoints);
    CHECK(p.data.segments.markers == poly.segments.markers);
    CHECK(same_bits(p.data.holes, poly.holes));
    REQUIRE(p.data.regions.size() == 2);
    for (std::size_t r = 0; r < 2; ++r) {
        CHECK(same_bits({p.data.regions[r].x, p.data.regions[r].y, p.data.regions[r].attribute,
                         p.data.regions[r].max_area},
                        {poly.regions[r].x, poly.regions[r].y, poly.regions[r].attribute,
                         poly.regions[r].max_area}));
    }

    for (const auto* ele : {&ele3, &ele6}) {
        const auto e = io::read_ele(path(ele == &ele3 ? "m3.ele" : "m6.ele"), base, 40, log.sink());
        CHECK(e.base == base);
        CHECK(e.data.corners_per_triangle == ele->corners_per_triangle);
        CHECK(e.data.corners == ele->corners);
        CHECK(e.data.attribute_count == ele->attribute_count);
        CHECK(same_bits(e.data.attributes, ele->attributes));
    }
    const auto a = io::read_area(path("m3.area"), base, 30, log.sink());
    CHECK(same_bits(a.data, areas));
    const auto ed = io::read_edge(path("m.edge"), base, 40, log.sink());
    CHECK(ed.data.endpoints == edges.endpoints);
    CHECK(ed.data.markers == edges.markers);
    const auto ne = io::read_neigh(path("m3.neigh"), base, 30, log.sink());
    CHECK(ne.data.neighbours == neigh.neighbours);
    const auto vn = io::read_node(path("m.v.node"), log.sink());
    check_same(vn.data, vnodes);
    const auto ve = io::read_voronoi_edge(path("m.v.edge"), base, 30, log.sink());
    CHECK(ve.data.endpoints == vedges.endpoints);
    CHECK(same_bits(ve.data.directions, vedges.directions));

    CHECK(log.warnings.empty());
    // Every file ends with the command that made it.
    for (const char* name : {"m.node", "m.poly", "m3.ele", "m6.ele", "m3.area", "m.edge",
                             "m3.neigh", "m.v.node", "m.v.edge"})
        CHECK(last_line(dir.read(name)) == "# Generated by gpdr -pq box.poly");
}

TEST_CASE("output .poly with vertices in the .node file reads back", "[io][round-trip]") {
    const int base = GENERATE(0, 1);
    TempDir dir;
    std::mt19937_64 rng(7);
    PolyFile poly;
    poly.nodes = make_nodes(5, 1, true, rng);
    poly.nodes_from_node_file = true;
    poly.segments.endpoints = {0, 1, 1, 2, 2, 0};
    poly.segments.markers = {1, 2, 3};
    poly.holes = {0.25, 0.125};
    {
        io::OutputTransaction tx;
        io::write_node(tx, (dir / "out.node").string(), poly.nodes, format(base));
        io::write_poly(tx, (dir / "out.poly").string(), poly, format(base));
        tx.commit();
    }
    CHECK(dir.read("out.poly").rfind("0  2  1  1\n", 0) == 0);
    const auto p = io::read_poly((dir / "out.poly").string(), ignore_warning);
    CHECK(p.base == base);
    CHECK(p.data.nodes_from_node_file);
    check_same(p.data.nodes, poly.nodes);
    CHECK(p.data.segments.endpoints == poly.segments.endpoints);
    CHECK(p.data.segments.markers == poly.segments.markers);
    CHECK(p.data.holes == poly.holes);
    CHECK(p.data.regions.empty());

    // The vertices themselves may be left out of the PolyFile: only the
    // header's counts are taken from it.
    PolyFile header_only;
    header_only.nodes_from_node_file = true;
    header_only.nodes.attribute_count = 1;
    header_only.nodes.markers.assign(1, 0);
    header_only.segments = poly.segments;
    {
        io::OutputTransaction tx;
        io::write_poly(tx, (dir / "out.poly").string(), header_only, format(base));
        tx.commit();
    }
    CHECK(dir.read("out.poly").rfind("0  2  1  1\n", 0) == 0);
    CHECK(io::read_poly((dir / "out.poly").string(), ignore_warning).data.segments.endpoints ==
          poly.segments.endpoints);
}

TEST_CASE("exact text: Triangle's layout, shortest doubles, markers last", "[io][format]") {
    TempDir dir;
    NodeSet nodes;
    nodes.xy = {0, 0, 1, 0.1, -0.0, 1.0 / 3.0};
    nodes.attribute_count = 1;
    nodes.attributes = {1e-300, 2, 0.5};
    nodes.markers = {1, 0, 33};
    EleSet ele;
    ele.corners = {0, 1, 2};
    io::VoronoiEdgeSet v;
    v.endpoints = {0, 1, 1, io::VoronoiEdgeSet::ray};
    v.directions = {0, 0, -1, 0.5};
    io::WriteFormat f = format(1);
    {
        io::OutputTransaction tx;
        io::write_node(tx, (dir / "a.node").string(), nodes, f);
        io::write_ele(tx, (dir / "a.ele").string(), ele, f);
        io::write_off(tx, (dir / "a.off").string(), nodes, ele, 3, f);
        io::write_voronoi_edge(tx, (dir / "a.v.edge").string(), v, f);
        f.markers = false;  // -B
        io::write_node(tx, (dir / "b.node").string(), nodes, f);
        tx.commit();
    }
    CHECK(dir.read("a.node") ==
          "3  2  1  1\n"
          "   1    0  0  1e-300    1\n"
          "   2    1  0.1  2    0\n"
          "   3    -0  0.3333333333333333  0.5    33\n"
          "# Generated by gpdr -pq box.poly\n");
    CHECK(dir.read("b.node").rfind("3  2  1  0\n   1    0  0  1e-300\n", 0) == 0);
    CHECK(dir.read("a.ele") ==
          "1  3  0\n   1       1     2     3\n# Generated by gpdr -pq box.poly\n");
    // .off numbers from 0 whatever the base.
    CHECK(dir.read("a.off") ==
          "OFF\n3  1  3\n0  0  0\n1  0.1  0\n-0  0.3333333333333333  0\n"
          " 3      0     1     2\n# Generated by gpdr -pq box.poly\n");
    CHECK(dir.read("a.v.edge") ==
          "2  0\n   1   1  2\n   2   2  -1  -1  0.5\n# Generated by gpdr -pq box.poly\n");
}
