// InsertBuffer::tagged_gone: every tagged triangle that an insertion or a
// subsegment split kills, or that a split's Lawson flips change in place, is
// reported with the corners (in order) and tag it had, and nothing else is.
// The parallel refiner uncounts a triangle from exactly these corners, so a
// triangle missed here would leave its quadtree cells counted for ever.
// (Flips of triangles outside a split's cavity are rare on random input:
// tests/mesh/flip_test.cpp makes one happen.)

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "geometry/constructions.hpp"
#include "mesh/insert.hpp"
#include "mesh/split_subsegment.hpp"
#include "mesh/test_support.hpp"
#include "triangulate/cdt_support.hpp"

using namespace gpdr;
using namespace gpdr::triangulate;
using namespace gpdr::triangulate::testing;
using gpdr::mesh::Mesh;

namespace {

// A tagged triangle as it was: corners in order, then the tag.
using Was = std::array<std::uint32_t, 4>;

struct Tagged {
    std::uint32_t generation;
    Was was;
};

Was was_of(const mesh::Triangle& t, std::uint8_t tag) {
    return {index(t.v[0]), index(t.v[1]), index(t.v[2]), tag};
}

// Tags every untagged live triangle with a tag of its own (1..250) and
// records the tagged ones.
std::map<std::uint32_t, Tagged> tag_all(Mesh& m, std::uint32_t& next_tag) {
    std::map<std::uint32_t, Tagged> tagged;
    mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle&) {
        mesh::Triangle& t = m.triangle(id);
        if (t.user_tag == 0) t.user_tag = static_cast<std::uint8_t>(1 + next_tag++ % 250);
        tagged[index(id)] = {t.generation, was_of(t, t.user_tag)};
    });
    return tagged;
}

// What changed since `before`: the recorded triangles whose slot died or
// moved to another generation, or whose corners or tag changed.
std::vector<Was> gone_since(const Mesh& m, const std::map<std::uint32_t, Tagged>& before) {
    std::vector<Was> gone;
    for (const auto& [i, rec] : before) {
        const mesh::Triangle& t = m.triangle(mesh::TriangleId{i});
        if (!t.live() || t.generation != rec.generation || was_of(t, t.user_tag) != rec.was)
            gone.push_back(rec.was);
    }
    std::sort(gone.begin(), gone.end());
    return gone;
}

std::vector<Was> reported(const mesh::InsertBuffer& buffer) {
    std::vector<Was> out;
    for (const auto& g : buffer.tagged_gone)
        out.push_back({index(g.v[0]), index(g.v[1]), index(g.v[2]), g.tag});
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST_CASE("insertions and subsegment splits report the tagged triangles they kill or flip",
          "[mesh][cdt]") {
    // A cloud crossed by a few segments; points are inserted and
    // subsegments split at points off their line (so that the bent halves
    // need Lawson flips, which change triangles outside the cavity).
    std::mt19937_64 rng(17);
    CdtReport report;
    Mesh m = triangulate_segments(random_pslg(rng, 300, 40, false), report);
    mesh::Pool pool(m);
    mesh::InsertBuffer buffer;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uint32_t next_tag = 0;
    std::size_t killed = 0;
    for (int k = 0; k < 1000; ++k) {
        const auto before = tag_all(m, next_tag);
        if (k % 2 == 0) {
            std::vector<mesh::EdgeRef> subs;
            mesh::for_each_edge(m, [&](const mesh::EdgeView& e) {
                if (e.subsegment) subs.push_back(e.edge);
            });
            const mesh::EdgeRef e = subs[rng() % subs.size()];
            const auto& a = m.point(m.origin(e));
            const auto& b = m.point(m.destination(e));
            // At the foot of the apex across the subsegment, or at random,
            // off the line by 1e-16 to 1e-2 of its length, either side.
            const mesh::Triangle& t = m.triangle(e.triangle());
            const Point& w = m.point(t.v[e.edge()]);
            const double dx = b.x - a.x, dy = b.y - a.y;
            double along = ((w.x - a.x) * dx + (w.y - a.y) * dy) / (dx * dx + dy * dy);
            if (k % 4 == 0 || !(along > 0.01 && along < 0.99)) along = 0.3 + 0.4 * u(rng);
            Point p = geometry::point_on_segment(a, b, along);
            const double off = (u(rng) < 0.5 ? -1 : 1) * std::pow(10.0, -16 + 14 * u(rng));
            p = {p.x - off * dy, p.y + off * dx};
            const auto r = mesh::split_subsegment(pool, e, p, mesh::VertexKind::segment, buffer);
            REQUIRE(r.status == mesh::InsertStatus::inserted);
        } else {
            const Point p{u(rng), u(rng)};
            mesh::TriangleId hint = mesh::no_triangle;
            mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle&) {
                if (hint == mesh::no_triangle) hint = id;
            });
            const auto r = mesh::insert_point(pool, p, mesh::VertexKind::free, hint, buffer);
            if (r.status != mesh::InsertStatus::inserted) continue;
        }
        const auto gone = gone_since(m, before);
        REQUIRE(reported(buffer) == gone);
        killed += buffer.killed.size();
        // Flipped triangles are in `created`, untagged.
        for (const mesh::TriangleId id : buffer.created) CHECK(m.triangle(id).user_tag == 0);
    }
    REQUIRE(mesh::check_mesh(m).empty());
    CHECK(killed > 2000);
}
