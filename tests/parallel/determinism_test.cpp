// The rounds (parallel/rounds.hpp): the refined mesh, down
// to its vertex ids, triangle slots and their generations, is the same for
// any number of threads and from run to run; and the rounds it records
// measure the work they claim.  Run under ThreadSanitizer too
// (scripts/test-tsan.sh).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "mesh/traverse.hpp"
#include "parallel/parallel_support.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/rounds.hpp"
#include "refine/refine_support.hpp"

namespace gpdr::parallel::testing {

namespace {

template <class T>
void append(std::string& bytes, const T& value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.append(raw, sizeof(T));
}

// Everything of the mesh that ids show: each vertex's point and kind by id,
// each live slot's triangle (corners, neighbours, flags, region, generation)
// by slot, the subsegments with their markers and segments.
std::string snapshot(const mesh::Mesh& m) {
    std::string bytes;
    append(bytes, m.vertex_end());
    append(bytes, m.triangle_end());
    for (std::uint32_t v = 0; v < m.vertex_end(); ++v) {
        append(bytes, m.point(mesh::VertexId{v}));
        append(bytes, m.kind(mesh::VertexId{v}));
    }
    mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        append(bytes, id);
        append(bytes, t.v);
        append(bytes, t.n);
        append(bytes, t.flags);
        append(bytes, t.region);
        append(bytes, t.generation);
    });
    std::vector<std::tuple<std::uint32_t, std::uint32_t, int, std::uint32_t>> subsegments;
    m.subsegments().for_each(
        [&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& s) {
            subsegments.emplace_back(index(a), index(b), s.marker, s.segment);
        });
    std::sort(subsegments.begin(), subsegments.end());
    for (const auto& s : subsegments) append(bytes, s);
    return bytes;
}

// triunsuitable() of a graded mesh: triangles must be smaller near (0, 0)
// (the graded pipe's grading, in miniature).  Pure, so thread-safe.
int graded(double* a, double* b, double* c, double area) {
    const double x = (a[0] + b[0] + c[0]) / 3, y = (a[1] + b[1] + c[1]) / 3;
    return area > 2e-5 * (std::sqrt(x * x + y * y) * 40 + 1) ? 1 : 0;
}

struct Case {
    std::string name;
    triangulate::Pslg pslg;  // empty: the point set
    refine::RefineSettings settings;
    unsigned granularity = 0;
};

std::vector<Case> cases() {
    std::vector<Case> c;
    c.push_back({"notched square -q30 -a", notched_square(), settings_for(30, 1e-3)});
    c.push_back({"notched square -q33", notched_square(), settings_for(33, 0)});
    c.push_back({"notched square -a alone", notched_square(), settings_for(0, 5e-4)});
    c.push_back({"notched square -q20 -a -g2", notched_square(), settings_for(20, 3e-4), 2});
    for (std::uint32_t seed : {1u, 2u, 3u})
        c.push_back(
            {"random PSLG " + std::to_string(seed), random_pslg(seed), settings_for(25, 2e-3)});
    Case user{"random PSLG 4, graded by -u", random_pslg(4), settings_for(20, 0)};
    user.settings.criteria.user_test = graded;
    c.push_back(user);
    c.push_back({"point set -q20 -a -g1", {}, settings_for(20, 2e-4), 1});
    return c;
}

mesh::Mesh start(const Case& c) {
    return c.pslg.points.empty() ? point_set_mesh(random_points(300, 5)) : cdt(c.pslg);
}

ParallelReport refine_on(mesh::Mesh& m, const Case& c, unsigned threads) {
    Schedule o =
        Schedule::rounds(threads, c.granularity != 0 ? c.granularity : refine::default_granularity);
    o.checked = threads == 3;  // the quadtree verified after every round, once per case
    ParallelReport report;
    refine_parallel(m, c.settings, o, report);
    INFO(joined(report.problems));
    CHECK(report.problems.empty());
    return report;
}

}  // namespace

TEST_CASE("the rounds give the same mesh, ids and all, on any number of threads",
          "[parallel][determinism]") {
    for (const Case& c : cases()) {
        INFO(c.name);
        mesh::Mesh first = start(c);
        const ParallelReport one = refine_on(first, c, 1);
        const std::string expected = snapshot(first);
        const auto outcome = examine(first, c.settings);
        CHECK(outcome.bad_angles == 0);
        CHECK(outcome.too_big == 0);
        CHECK(one.rounds.size() > 0);
        for (unsigned threads : {2u, 3u, 8u, 8u}) {
            INFO("threads " << threads);
            mesh::Mesh m = start(c);
            const ParallelReport report = refine_on(m, c, threads);
            CHECK(report.rounds == one.rounds);
            CHECK(report.refine.steiner_points == one.refine.steiner_points);
            CHECK(snapshot(m) == expected);
        }
    }
}

TEST_CASE("the recorded rounds measure the work they claim", "[parallel][determinism]") {
    // A graded unit square: much work near one corner, little elsewhere.
    triangulate::Pslg p;
    p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    refine::RefineSettings s = settings_for(20, 0);
    s.criteria.user_test = graded;
    mesh::Mesh m = cdt(p);
    const Schedule o = Schedule::rounds(2, 2);
    ParallelReport report;
    refine_parallel(m, s, o, report);
    REQUIRE(report.rounds.size() > 2);

    // Every triangle refinement made was made in some leaf's run, and counted once.
    std::uint64_t work = 0, span = 0, runs = 0;
    for (const auto& round : report.rounds) {
        std::uint64_t largest = 0;
        for (const std::uint64_t w : round) {
            work += w;
            largest = std::max(largest, w);
        }
        span += largest;
        runs += round.size();
    }
    CHECK(work == report.refine.triangles_created);
    CHECK(runs == report.assignments);

    const ScheduleShape shape = schedule_shape(report.rounds);
    CHECK(shape.rounds == report.rounds.size());
    CHECK(shape.work == work);
    const double recomputed = double(work) / double(span);
    CHECK(std::abs(shape.parallelism() - recomputed) <= 0.01 * recomputed);
    CHECK(shape.parallelism() > 1.0);
    CHECK(shape.fewest <= shape.median);
    CHECK(shape.median <= shape.most);

    // One worker gains nothing; more never lose; none beats work / span.
    CHECK(std::abs(predicted_speedup(report.rounds, 1) - 1.0) < 1e-12);
    double before = 1.0;
    for (unsigned workers : {2u, 4u, 16u, 64u}) {
        const double s_w = predicted_speedup(report.rounds, workers);
        CHECK(s_w >= before - 1e-12);
        CHECK(s_w <= shape.parallelism() + 1e-9);
        CHECK(s_w <= workers + 1e-9);
        before = s_w;
    }
}

TEST_CASE("a round's lanes claim ids side by side, so one long run keeps them dense",
          "[parallel][determinism]") {
    // A star of 60,000 segments under -q30 alone: its slivers keep the root
    // from splitting, and the root's one run makes every triangle (194,030)
    // on one lane, which claims chunk after chunk of ids besides the slots
    // the initial triangulation's dead triangles leave it.  With each of
    // the 64 lanes taking every 64th chunk for the whole refinement, its
    // chunks would lie 64 apart: ids 64 times the triangles, which met the
    // limit of 2^30 ids at about 16 million.
    triangulate::Pslg p;
    constexpr std::uint32_t n = 60000;
    for (std::uint32_t i = 0; i < n; ++i) {
        const double a = 2 * 3.141592653589793 * i / n;
        const double r =
            1 + 0.25 * std::sin(7 * a) + 0.1 * std::sin(113 * a) + 0.03 * std::sin(1031 * a);
        p.points.push_back({r * std::cos(a), r * std::sin(a)});
        p.segments.push_back(i);
        p.segments.push_back((i + 1) % n);
    }
    mesh::Mesh m = cdt(p);
    const std::uint64_t before = m.triangle_end();
    const std::uint64_t live_before = m.count_triangles();
    const Schedule o = Schedule::rounds(2);
    ParallelReport report;
    refine::RefineSettings s = settings_for(30, 0);
    s.checked = false;
    refine_parallel(m, s, o, report);
    REQUIRE(report.rounds.size() == 1);
    REQUIRE(m.count_triangles() > mesh::Mesh::TriangleTable::chunk_size);
    // The new ids: the mesh's growth, less the dead slots reused, plus the
    // unused end of the lane's last chunk.
    CHECK(m.triangle_end() <=
          before + (m.count_triangles() - live_before) + mesh::Mesh::TriangleTable::chunk_size);
}

}  // namespace gpdr::parallel::testing
