// Parallel refinement (lib/parallel): meshes from any thread count and
// granularity are valid and meet the bounds -j1 meets, with about as many
// triangles; the quadtree invariants (exact counters, relation (9) with
// effective sides, leaves tiling the root) and buffer-zone exclusivity hold
// after every leaf refinement in checked mode; a stress run over random
// point sets and PSLGs.  Run the whole file under ThreadSanitizer with
// scripts/test-tsan.sh.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <random>

#include "parallel/parallel_support.hpp"
#include "parallel/refine_parallel.hpp"
#include "parallel/worker.hpp"
#include "refine/refine_support.hpp"

namespace gpdr::parallel::testing {

namespace {

struct Result {
    std::size_t triangles = 0;
    std::size_t vertices = 0;
};

Result refine_checked(mesh::Mesh& m, const refine::RefineSettings& s, unsigned threads, unsigned g,
                      bool checked, ParallelReport* out = nullptr) {
    Schedule o = Schedule::rounds(threads, g != 0 ? g : refine::default_granularity);
    o.checked = checked;
    ParallelReport report;
    refine_parallel(m, s, o, report);
    INFO("threads " << threads << " g " << g << "\n" << joined(report.problems));
    CHECK(report.problems.empty());
    CHECK(report.refine.left_other == 0);
    CHECK(report.refine.stopped == refine::RefineReport::Stop::none);
    const auto outcome = examine(m, s);
    CHECK(outcome.bad_angles == 0);
    CHECK(outcome.too_big == 0);
    if (out) *out = std::move(report);
    return {outcome.triangles, report.refine.steiner_points};
}

}  // namespace

TEST_CASE("parallel refinement of a point set matches -j1's bounds and size", "[parallel]") {
    const auto points = random_points(300, 7);
    const auto s = settings_for(25, 2e-4);
    mesh::Mesh sequential = point_set_mesh(points);
    refine::RefineReport sr;
    refine::refine_mesh(sequential, s, sr);
    const double reference = double(sequential.count_triangles());

    for (unsigned threads : {1u, 2u, 3u, 4u}) {
        for (unsigned g : {1u, 2u, 4u}) {
            mesh::Mesh m = point_set_mesh(points);
            ParallelReport report;
            const Result r = refine_checked(m, s, threads, g, true, &report);
            INFO("threads " << threads << " g " << g << ": " << r.triangles << " triangles vs "
                            << reference);
            CHECK(std::abs(double(r.triangles) - reference) < 0.05 * reference);
            CHECK(report.checks > 0);
            CHECK(report.splits > 0);
            CHECK(report.leaves > 1);
            if (threads > 1) CHECK(report.workers.size() == threads);
        }
    }
}

TEST_CASE("parallel refinement of a PSLG with a hole and a small angle", "[parallel]") {
    const auto p = notched_square();
    auto s = settings_for(28, 1e-3);
    mesh::Mesh sequential = cdt(p);
    refine::RefineReport sr;
    refine::refine_mesh(sequential, s, sr);
    const double reference = double(sequential.count_triangles());
    for (unsigned threads : {1u, 2u, 4u}) {
        mesh::Mesh m = cdt(p);
        ParallelReport report;
        const Result r = refine_checked(m, s, threads, 2, true, &report);
        CHECK(std::abs(double(r.triangles) - reference) < 0.05 * reference);
        // Concurrency really happened on more than one thread.
        if (threads > 1) CHECK(report.most_concurrent > 1);
    }
}

TEST_CASE("idle leaves beside the leaves refined split too, and every invariant holds",
          "[parallel]") {
    // The root square is several times the unit square's size: the space
    // around the domain is large leaves that never get work, which the
    // workers refining the domain's edge split (Scheduler::take_balance_candidates).
    triangulate::Pslg p;
    p.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    const auto s = settings_for(20, 2e-4);
    for (unsigned threads : {1u, 2u, 3u}) {
        mesh::Mesh m = cdt(p);
        ParallelReport report;
        refine_checked(m, s, threads, 1, true, &report);
        INFO("threads " << threads << ": " << report.splits << " splits, " << report.checks
                        << " checks");
        CHECK(report.checks > 0);
        CHECK(report.balance_splits > 0);
        CHECK(report.balance_splits < report.splits);
    }
}

TEST_CASE("a round's split budget is the round before's work over 32, within its limits",
          "[parallel]") {
    CHECK(round_split_budget(0) == least_split_budget);
    CHECK(round_split_budget(32 * least_split_budget - 1) == least_split_budget);
    CHECK(round_split_budget(640000) == 20000);
    CHECK(round_split_budget(32 * split_budget) == split_budget);
    CHECK(round_split_budget(std::uint64_t{1} << 40) == split_budget);
}

TEST_CASE("the Steiner limit stops every worker with a valid mesh", "[parallel]") {
    mesh::Mesh m = point_set_mesh(random_points(200, 3));
    auto s = settings_for(30, 1e-4);
    s.steiner_limit = true;
    s.max_steiner = 500;
    const Schedule o = Schedule::rounds(3);
    ParallelReport report;
    refine_parallel(m, s, o, report);
    CHECK(report.refine.stopped == refine::RefineReport::Stop::steiner_limit);
    // Workers stop at their next check of the shared count: a few over at most.
    CHECK(report.refine.steiner_points >= 500);
    CHECK(report.refine.steiner_points < 500 + 64);
    const auto problems = mesh::check_mesh(m);
    INFO(joined(problems));
    CHECK(problems.empty());
}

TEST_CASE("timing report has one entry per worker and the API defaults", "[parallel]") {
    mesh::Mesh m = point_set_mesh(random_points(100, 11));
    ParallelReport report;
    refine_parallel(m, settings_for(20, 1e-3), 2, 0, report);
    CHECK(report.threads == 2);
    CHECK(report.granularity == refine::default_granularity);
    REQUIRE(report.workers.size() == 2);
    CHECK(report.workers[0].refining + report.workers[1].refining > 0);
    CHECK(report.assignments > 0);
}

TEST_CASE("stress: random point sets and PSLGs, -j2..-j8, -g1..-g5", "[parallel][stress]") {
    std::mt19937 rng(2024);
    int runs = 0;
    for (int i = 0; i < 240; ++i) {
        const unsigned threads = 2 + rng() % 7;
        const unsigned g = 1 + rng() % 5;
        const double angle = 20 + (rng() % 14);
        const bool pslg = i % 2 == 1;
        mesh::Mesh m =
            pslg ? cdt(random_pslg(static_cast<std::uint32_t>(i)))
                 : point_set_mesh(random_points(20 + rng() % 150, static_cast<std::uint32_t>(i)));
        const double area = pslg ? 2e-3 + 1e-3 * (rng() % 5) : 1e-3 + 1e-3 * (rng() % 3);
        if (const char* only = std::getenv("GPDR_STRESS_ONLY"); only && std::atoi(only) != i)
            continue;
        INFO("run " << i << (pslg ? " pslg" : " points") << " -j" << threads << " -g" << g << " -q"
                    << angle);
        // The quadtree verification after every leaf on one run in four.
        const char* jt = std::getenv("GPDR_STRESS_THREADS");
        refine_checked(m, settings_for(angle, area), jt ? unsigned(std::atoi(jt)) : threads, g,
                       i % 4 == 0);
        ++runs;
    }
    if (!std::getenv("GPDR_STRESS_ONLY")) CHECK(runs == 240);
}

}  // namespace gpdr::parallel::testing
