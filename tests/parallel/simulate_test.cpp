// The rounds recorded for the simulation of refinement across machines
// (parallel/round_record.hpp, docs/scaling.md): what the record holds is
// consistent with the rounds, recording changes nothing, and the ranks'
// figures are what their definitions say.  The simulation itself, on the
// graded pipe and the square, is a hidden test that prints a table:
//   build/tests/test_parallel "[.simulate]"
// (scripts/bench-schedule.sh with SIMULATE=1; GPDR_SIMULATE_C, _AREA and
// _G set the pipe's c, the square's area bound and the granularity).

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "parallel/parallel_support.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/round_record.hpp"
#include "parallel/rounds.hpp"
#include "refine/refine_support.hpp"

namespace gpdr::parallel::testing {

namespace {

// The graded square of determinism_test.cpp: much work near one corner.
int graded_corner(double* a, double* b, double* c, double area) {
    const double x = (a[0] + b[0] + c[0]) / 3, y = (a[1] + b[1] + c[1]) / 3;
    return area > 2e-5 * (std::sqrt(x * x + y * y) * 40 + 1) ? 1 : 0;
}

triangulate::Pslg unit_square() {
    triangulate::Pslg p;
    p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    return p;
}

}  // namespace

TEST_CASE("ranks by Morton order: shares and balance of a round made by hand",
          "[parallel][simulate]") {
    // Four leaves of level 1 in Morton order, 10, 30, 40 and 20 triangles.
    // Run A refines leaf 0 (work 6) with leaves 1 and 2 in its zone; run B
    // refines leaf 3 (work 2) with leaf 2 in its zone.
    RecordedRound round;
    round.leaves = {{{1, 0, 0}, 10}, {{1, 1, 0}, 30}, {{1, 0, 1}, 40}, {{1, 1, 1}, 20}};
    round.runs = {{0, {0, 1, 2}, 6}, {3, {2, 3}, 2}};
    for (std::size_t i = 1; i < round.leaves.size(); ++i)
        CHECK(round.leaves[i - 1].cell.morton() < round.leaves[i].cell.morton());

    // Two ranks: 100 triangles, 50 each; the leaves' middles lie at 5, 25,
    // 60 and 90: ranks 0, 0, 1, 1.
    CHECK(morton_owners(round, 2) == std::vector<std::uint32_t>{0, 0, 1, 1});
    const std::vector<RankRound> two = simulate_ranks({round}, 2);
    REQUIRE(two.size() == 1);
    CHECK(two[0].work == 8);
    CHECK(two[0].zone_triangles == 30 + 40 + 40);
    CHECK(two[0].remote_triangles == 40);  // A's leaf 2; B's leaf 2 is its own rank's
    CHECK(two[0].largest == 6);
    CHECK(two[0].balance == Approx(6.0 / 4.0));
    CHECK(two[0].share == Approx(40.0 / 110.0));

    // One rank: nothing is remote, and the balance is perfect.
    const std::vector<RankRound> one = simulate_ranks({round}, 1);
    CHECK(one[0].share == 0);
    CHECK(one[0].balance == 1);

    // Four ranks of 25: middles 5, 25, 60, 90 -> ranks 0, 1, 2, 3.
    CHECK(morton_owners(round, 4) == std::vector<std::uint32_t>{0, 1, 2, 3});
    const RankSummary s = summarise(simulate_ranks({round, round}, 4));
    CHECK(s.share.worst == 1.0);
    CHECK(s.balance.median == Approx(6.0 / 2.0));
    CHECK(s.work == 16);
    CHECK(s.speedup == Approx(16.0 / 12.0));
    CHECK(s.moved == 0);  // the same triangles, the same ranges

    // More triangles in leaf 0: two ranks of 90 now, whose middles lie at
    // 45, 105, 140 and 170: leaf 1 moves from rank 0 to rank 1.
    RecordedRound later = round;
    later.leaves[0].triangles = 90;
    CHECK(morton_owners(later, 2) == std::vector<std::uint32_t>{0, 1, 1, 1});
    const std::vector<RankRound> moved = simulate_ranks({round, later}, 2);
    CHECK(moved[0].moved_triangles == 0);
    CHECK(moved[1].moved_triangles == 30);
}

TEST_CASE("the recorded rounds hold each round's leaves, zones and work", "[parallel][simulate]") {
    refine::RefineSettings s = settings_for(20, 0);
    s.criteria.user_test = graded_corner;
    mesh::Mesh plain = cdt(unit_square());
    mesh::Mesh m = cdt(unit_square());
    const std::size_t start = m.count_triangles();

    Schedule o = Schedule::rounds(2, 2);
    ParallelReport without;
    refine_parallel(plain, s, o, without);
    CHECK(without.record.empty());
    o.record = true;
    o.checked = true;
    ParallelReport report;
    refine_parallel(m, s, o, report);
    INFO(joined(report.problems));
    CHECK(report.problems.empty());
    // Recording changes nothing.
    CHECK(report.rounds == without.rounds);
    CHECK(m.count_triangles() == plain.count_triangles());
    CHECK(m.triangle_end() == plain.triangle_end());

    REQUIRE(report.rounds.size() > 2);
    REQUIRE(report.record.size() == report.rounds.size());
    std::uint64_t work = 0, triangles_before = 0, shared = 0;
    for (std::size_t r = 0; r < report.record.size(); ++r) {
        INFO("round " << r);
        const RecordedRound& round = report.record[r];
        REQUIRE(round.runs.size() == report.rounds[r].size());
        // The leaves tile the root, in Morton order; every triangle is in one.
        double area = 0;
        std::uint64_t triangles = 0;
        for (std::size_t i = 0; i < round.leaves.size(); ++i) {
            area += std::ldexp(1.0, -2 * round.leaves[i].cell.level);
            triangles += round.leaves[i].triangles;
            if (i > 0) CHECK(round.leaves[i - 1].cell.morton() < round.leaves[i].cell.morton());
        }
        CHECK(area == Approx(1.0));
        // Refinement only ever adds triangles.
        if (r == 0) CHECK(triangles == start);
        CHECK(triangles >= triangles_before);
        triangles_before = triangles;
        // Each zone holds its leaf, and no other leaf of the round (zones
        // may share the leaves between two of the round's).
        std::vector<int> run_of(round.leaves.size(), -1);
        for (std::size_t i = 0; i < round.runs.size(); ++i) {
            REQUIRE(round.runs[i].leaf < round.leaves.size());
            CHECK(run_of[round.runs[i].leaf] == -1);
            run_of[round.runs[i].leaf] = static_cast<int>(i);
        }
        std::vector<int> zones_of(round.leaves.size(), 0);
        for (std::size_t i = 0; i < round.runs.size(); ++i) {
            const RecordedRun& run = round.runs[i];
            CHECK(run.work == report.rounds[r][i]);
            work += run.work;
            CHECK(std::find(run.zone.begin(), run.zone.end(), run.leaf) != run.zone.end());
            for (const std::uint32_t z : run.zone) {
                REQUIRE(z < round.leaves.size());
                CHECK((run_of[z] == -1 || z == run.leaf));
                if (++zones_of[z] == 2) ++shared;
            }
        }
    }
    CHECK(triangles_before <= m.count_triangles());
    CHECK(work == report.refine.triangles_created);
    // Leaves between two of a round's, in both their zones, are the rule's
    // gain over disjoint zones (scheduler.hpp).
    CHECK(shared > 0);

    const double parallelism = schedule_shape(report.rounds).parallelism();
    for (const unsigned ranks : {1u, 4u, 16u, 64u}) {
        INFO("ranks " << ranks);
        const std::vector<RankRound> rounds = simulate_ranks(report.record, ranks);
        REQUIRE(rounds.size() == report.record.size());
        for (std::size_t r = 0; r < rounds.size(); ++r) {
            const std::vector<std::uint32_t> owner = morton_owners(report.record[r], ranks);
            for (std::size_t i = 0; i < owner.size(); ++i) {
                CHECK(owner[i] < ranks);
                if (i > 0) CHECK(owner[i - 1] <= owner[i]);
            }
            CHECK(rounds[r].share >= 0);
            CHECK(rounds[r].share <= 1);
            CHECK(rounds[r].remote_triangles <= rounds[r].zone_triangles);
            CHECK(rounds[r].balance >= 1 - 1e-12);
            CHECK(rounds[r].balance <= ranks + 1e-9);
            if (ranks == 1) {
                CHECK(rounds[r].share == 0);
                CHECK(rounds[r].balance == 1);
                CHECK(rounds[r].moved_triangles == 0);
            }
        }
        const RankSummary sum = summarise(rounds);
        CHECK(sum.work == work);
        CHECK(sum.speedup <= ranks + 1e-9);
        CHECK(sum.speedup <= parallelism + 1e-9);
        if (ranks == 1) CHECK(sum.speedup == 1);
    }
}

// ---- the simulation (hidden) -------------------------------------------------

namespace {

double env_or(const char* name, double fallback) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != '\0' ? std::atof(v) : fallback;
}

// poly-samples/grading.c: the paper's grading function (10) around the
// pipe's centre, c set by GPDR_SIMULATE_C.
double grading_c = 1e-4;
int grading(double* org, double* dest, double* apex, double area) {
    const double x = (org[0] + dest[0] + apex[0]) / 3.0;
    const double y = (org[1] + dest[1] + apex[1]) / 3.0;
    const double dx = x - 200.0, dy = y - 200.0;
    return area > grading_c * (std::sqrt(dx * dx + dy * dy) + 1.0);
}

std::string fixed(double v, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    return text;
}

std::string general(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string three(const RoundStatistic& s, int digits) {
    return fixed(s.median, digits) + " / " + fixed(s.weighted, digits) + " / " +
           fixed(s.worst, digits);
}

// How the finished mesh uses its ids, for docs/scaling.md: the triangle
// slots up to the last chunk claimed and the vertex ids against what is
// live; the neighbour links that stay in their triangle's chunk of 2^16
// slots, or within 16 or 256 chunks of it; the corners within 2^16 and 2^24 ids
// of the median corner of their triangle's chunk; and the links between
// triangles whose centroids lie in different squares of an 8 x 8 grid over
// the mesh's bounding box (ids by region instead of by chunk).
void print_ids(const std::string& label, const mesh::Mesh& m) {
    constexpr unsigned bits = mesh::Mesh::triangle_chunk_bits;
    std::uint64_t live = 0, links = 0, same = 0, near16 = 0, near256 = 0, corners = 0, within16 = 0,
                  within24 = 0;
    std::vector<std::uint32_t> ids;
    std::uint32_t chunk = 0xFFFFFFFFu;
    const auto close_chunk = [&] {
        if (ids.empty()) return;
        std::vector<std::uint32_t> sorted = ids;
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        const std::int64_t median = sorted[sorted.size() / 2];
        for (const std::uint32_t v : ids) {
            const std::int64_t d = std::abs(std::int64_t{v} - median);
            ++corners;
            within16 += d < (1 << 16) ? 1 : 0;
            within24 += d < (1 << 24) ? 1 : 0;
        }
        ids.clear();
    };
    mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        ++live;
        const std::uint32_t c = mesh::index(id) >> bits;
        if (c != chunk) {
            close_chunk();
            chunk = c;
        }
        for (int k = 0; k < 3; ++k) {
            ids.push_back(mesh::index(t.v[k]));
            if (t.n[k].is_none()) continue;
            ++links;
            const std::int64_t d =
                std::int64_t{mesh::index(t.n[k].triangle()) >> bits} - std::int64_t{c};
            same += d == 0 ? 1 : 0;
            near16 += std::abs(d) <= 16 ? 1 : 0;
            near256 += std::abs(d) <= 256 ? 1 : 0;
        }
    });
    close_chunk();
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (std::uint32_t v = 0; v < m.vertex_end(); ++v) {
        if (m.kind(mesh::VertexId{v}) == mesh::VertexKind::unused) continue;
        const geometry::Point& q = m.point(mesh::VertexId{v});
        x0 = std::min(x0, q.x), y0 = std::min(y0, q.y), x1 = std::max(x1, q.x),
        y1 = std::max(y1, q.y);
    }
    const auto region = [&](mesh::TriangleId id) {
        const mesh::Triangle& t = m.triangle(id);
        double x = 0, y = 0;
        for (const mesh::VertexId v : t.v) x += m.point(v).x, y += m.point(v).y;
        const int i = std::clamp(static_cast<int>(8 * (x / 3 - x0) / (x1 - x0)), 0, 7);
        const int j = std::clamp(static_cast<int>(8 * (y / 3 - y0) / (y1 - y0)), 0, 7);
        return 8 * j + i;
    };
    std::uint64_t crossing = 0;
    mesh::for_each_triangle(m, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        for (int k = 0; k < 3; ++k)
            if (!t.n[k].is_none() && region(t.n[k].triangle()) != region(id)) ++crossing;
    });
    std::printf(
        "%s: %llu live triangles in %u triangle slots (%.3f a triangle), %u vertex ids; "
        "neighbour links in their chunk %.4f, within 16 chunks %.4f, within 256 %.4f; corners "
        "within 2^16 "
        "ids of their chunk's median %.4f, within 2^24 %.4f; links between 8 x 8 regions %.5f\n",
        label.c_str(), static_cast<unsigned long long>(live), m.triangle_end(),
        double(m.triangle_end()) / double(live), m.vertex_end(), double(same) / double(links),
        double(near16) / double(links), double(near256) / double(links),
        double(within16) / double(corners), double(within24) / double(corners),
        double(crossing) / double(links));
    std::fflush(stdout);
}

// Refines `m` in recorded rounds and prints its rows of the table.
void simulate(const std::string& label, const triangulate::Pslg& p, const refine::RefineSettings& s,
              unsigned g) {
    if (std::getenv("GPDR_SIMULATE_IDS") != nullptr) {
        // The sequential schedule's ids too (-j1).
        mesh::Mesh one = cdt(p);
        ParallelReport sequential;
        refine_parallel(one, s, Schedule::sequential(Schedule::Why::one_thread, g), sequential);
        print_ids(label + ", -j1", one);
    }
    mesh::Mesh m = cdt(p);
    Schedule o = Schedule::rounds(2, g);
    o.record = true;
    ParallelReport report;
    refine_parallel(m, s, o, report);
    REQUIRE(report.problems.empty());
    const std::size_t triangles = m.count_triangles();
    if (std::getenv("GPDR_SIMULATE_IDS") != nullptr)
        for (std::size_t r = 0; r < report.record.size(); ++r) {
            const RecordedRound& round = report.record[r];
            std::uint64_t live = 0, work = 0;
            for (const RecordedLeaf& l : round.leaves) live += l.triangles;
            for (const RecordedRun& run : round.runs) work += run.work;
            std::printf(
                "%s, round %zu: %zu leaves, %zu runs, work %llu, %llu live triangles, "
                "%u triangle slots, %u vertex ids\n",
                label.c_str(), r, round.leaves.size(), round.runs.size(),
                static_cast<unsigned long long>(work), static_cast<unsigned long long>(live),
                round.triangle_end, round.vertex_end);
        }
    for (const unsigned ranks : {4u, 16u, 64u}) {
        const RankSummary sum = summarise(simulate_ranks(report.record, ranks));
        std::printf(
            "| %s | %zu | %zu | %u | %s | %s | %s | %s | %s / %s |\n", label.c_str(), triangles,
            report.record.size(), ranks, three(sum.share, 2).c_str(), three(sum.balance, 1).c_str(),
            fixed(double(sum.remote) / double(sum.work), 2).c_str(),
            fixed(double(sum.moved) / double(sum.work), 2).c_str(), fixed(sum.speedup, 1).c_str(),
            fixed(predicted_speedup(report.rounds, ranks), 1).c_str());
    }
    print_ids(label + ", rounds", m);
}

}  // namespace

TEST_CASE("simulated ranks: buffer zones across ranks and balance, graded pipe and square",
          "[.simulate][parallel]") {
    const auto g = static_cast<unsigned>(env_or("GPDR_SIMULATE_G", refine::default_granularity));
    grading_c = env_or("GPDR_SIMULATE_C", 1e-4);
    const double area = env_or("GPDR_SIMULATE_AREA", 1e-7);
    std::printf(
        "| input | triangles | rounds | ranks | zone triangles on another rank: median / "
        "weighted / worst | balance: median / weighted / worst | fetched per triangle made | "
        "moved per triangle made | speed-up: ranks / threads |\n"
        "|---|---:|---:|---:|---|---|---:|---:|---|\n");

    const triangulate::Pslg pipe =
        refine::testing::read_poly(std::string(GPDR_SOURCE_DIR) + "/poly-samples/pipe.poly");
    refine::RefineSettings s = settings_for(20, 0);
    s.checked = false;
    s.criteria.user_test = grading;
    s.segment_ends = refine::testing::segment_ends(pipe);
    simulate("graded pipe, c = " + general(grading_c) + ", -g" + std::to_string(g), pipe, s, g);

    refine::RefineSettings q = settings_for(30, area);
    q.checked = false;
    simulate("unit square, -q30 -a" + general(area) + ", -g" + std::to_string(g), unit_square(), q,
             g);
}

}  // namespace gpdr::parallel::testing
