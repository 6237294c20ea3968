// Temporary segment labels (lib/parallel/segment_labels.hpp): every
// subsegment gets the ends of the input segment it lies on, the halves of a
// split subsegment keep them, and restore() gives back the original indices.

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "geometry/predicates.hpp"
#include "mesh/insert.hpp"
#include "mesh/pool.hpp"
#include "mesh/split_subsegment.hpp"
#include "parallel/segment_labels.hpp"
#include "refine/refine_support.hpp"

namespace gpdr::parallel::testing {

namespace {

using Key = std::pair<std::uint32_t, std::uint32_t>;

std::map<Key, std::uint32_t> segment_indices(const mesh::Mesh& m) {
    std::map<Key, std::uint32_t> out;
    m.subsegments().for_each(
        [&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& info) {
            out[{mesh::index(a), mesh::index(b)}] = info.segment;
        });
    return out;
}

// Whether every subsegment lies on the segment between its label's ends
// (collinear, inside the ends' box).
void check_labels(const mesh::Mesh& m, const SegmentLabels& labels) {
    const auto ends = labels.ends();
    m.subsegments().for_each(
        [&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& info) {
            REQUIRE(info.segment != mesh::SubsegmentInfo::no_segment);
            REQUIRE(2 * std::size_t{info.segment} + 1 < ends.size());
            const geometry::Point& p = m.point(ends[2 * info.segment]);
            const geometry::Point& q = m.point(ends[2 * info.segment + 1]);
            for (const mesh::VertexId v : {a, b}) {
                const geometry::Point& x = m.point(v);
                // Split points are rounded: nearly collinear, not exactly.
                const double cross = (q.x - p.x) * (x.y - p.y) - (q.y - p.y) * (x.x - p.x);
                const double len2 = (q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y);
                CHECK(cross * cross <= 1e-20 * len2 * len2);
                CHECK(x.x >= std::min(p.x, q.x) - 1e-12);
                CHECK(x.x <= std::max(p.x, q.x) + 1e-12);
                CHECK(x.y >= std::min(p.y, q.y) - 1e-12);
                CHECK(x.y <= std::max(p.y, q.y) + 1e-12);
            }
        });
}

}  // namespace

TEST_CASE("segment labels give every subsegment its segment's ends, through splits", "[parallel]") {
    triangulate::Pslg p;
    p.points = {{0, 0}, {4, 0}, {4, 3}, {2.2, 3}, {2, 0.5}, {1.8, 3}, {0, 3}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 0};
    mesh::Mesh m = refine::testing::cdt(p);
    const auto before = segment_indices(m);

    SECTION("no ends given: every subsegment is labelled") {
        SegmentLabels labels(m, {});
        CHECK(labels.ends().size() == 2 * before.size());
        check_labels(m, labels);
        // Refinement splits subsegments; the halves keep their labels.
        refine::RefineSettings s;
        s.criteria.min_angle_degrees = 25;
        s.criteria.max_area = 0.05;
        s.segment_ends = labels.ends();
        refine::RefineReport report;
        refine::refine_mesh(m, s, report);
        REQUIRE(report.segment_splits > 0);
        check_labels(m, labels);
        labels.restore();
        for (const auto& [key, segment] : segment_indices(m)) {
            CHECK(segment < p.segments.size() / 2);  // an input segment's index again
        }
    }
    SECTION("the caller's ends answer for every subsegment: nothing is labelled") {
        const auto given = refine::testing::segment_ends(p);
        SegmentLabels labels(m, given);
        CHECK(labels.ends().size() == given.size());
        CHECK(segment_indices(m) == before);
        labels.restore();
        CHECK(segment_indices(m) == before);
    }
}

TEST_CASE("segment labels cover a point set's hull edges and are removed again", "[parallel]") {
    mesh::Mesh m = refine::testing::point_set_mesh(refine::testing::random_points(200, 7));
    const auto before = segment_indices(m);
    SegmentLabels labels(m, {});
    check_labels(m, labels);
    labels.restore();
    CHECK(segment_indices(m) == before);
}

TEST_CASE("segment labels label a long chain of subsegments from one walk", "[parallel]") {
    // A 1000 x 1 rectangle whose bottom edge is split at x = 1, 2, ..., 600
    // by segment vertices: a chain of 601 subsegments between two corners,
    // longer than the 256 steps a walk from one subsegment may take.
    mesh::Mesh m = refine::testing::point_set_mesh({{0, 0}, {1000, 0}, {1000, 1}, {0, 1}});
    const mesh::VertexId left{0}, right{1};
    constexpr int splits = 600;
    {
        mesh::Pool pool(m);
        mesh::InsertBuffer buffer;
        mesh::VertexId from = left;
        for (int i = 1; i <= splits; ++i) {
            mesh::EdgeRef piece = mesh::EdgeRef::none();
            mesh::for_each_edge(m, [&](const mesh::EdgeView& e) {
                if (e.subsegment && std::minmax(e.from, e.to) == std::minmax(from, right))
                    piece = e.edge;
            });
            REQUIRE(!piece.is_none());
            const auto r = mesh::split_subsegment(pool, piece, {double(i), 0.0},
                                                  mesh::VertexKind::segment, buffer);
            REQUIRE(r.status == mesh::InsertStatus::inserted);
            from = r.vertex;
        }
    }
    const auto before = segment_indices(m);
    REQUIRE(before.size() == splits + 4);

    SegmentLabels labels(m, {});
    check_labels(m, labels);
    // One label per chain: the bottom's 601 pieces share one, whose ends are
    // the two corners; each other side has its own.
    CHECK(labels.ends().size() == 2 * 4);
    std::set<std::uint32_t> bottom;
    m.subsegments().for_each(
        [&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& info) {
            if (m.point(a).y == 0 && m.point(b).y == 0) bottom.insert(info.segment);
        });
    REQUIRE(bottom.size() == 1);
    const auto ends = labels.ends();
    const std::uint32_t label = *bottom.begin();
    CHECK(std::minmax(ends[2 * label], ends[2 * label + 1]) == std::minmax(left, right));
    labels.restore();
    CHECK(segment_indices(m) == before);
}

}  // namespace gpdr::parallel::testing
