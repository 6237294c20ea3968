// The refinement order's promises (docs/refinement-order.md), on the
// project's samples and the generated models of tests/data/models
// (scripts/make-models.py):
//   - refinement ends at 33 and 34 degrees on one and two threads, with a
//     mesh that passes the invariant checker and the segment conformity
//     check and meets the angle bound but where a small input angle
//     protects a triangle or a handful are left by precision;
//   - meshes stay near Triangle's size: triangle counts against Triangle
//     1.6's on the same input and switches (recorded below), bounded by
//     ratios, so that an order that inflates meshes fails;
//   - refining by size alone: no vertex encroaches a subsegment (Triangle's
//     lens of angle 0), so a mesh that meets the bound gains nothing.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gpdr/io.hpp>

#include "api/api_test_support.hpp"
#include "check/checker.hpp"
#include "cli/cli_support.hpp"
#include "mesh/traverse.hpp"
#include "parallel/refine_parallel.hpp"
#include "refine/quality.hpp"
#include "refine/refine.hpp"
#include "triangulate/conformity.hpp"
#include "triangulate/constrained.hpp"

using namespace gpdr;
namespace fs = std::filesystem;

namespace {

fs::path models() { return test::source_dir() / "tests" / "data" / "models"; }

struct Refined {
    triangulate::Pslg pslg;
    triangulate::CdtReport cdt;
    std::vector<mesh::VertexId> ends;
    mesh::Mesh mesh;
    refine::RefineSettings settings;
    refine::RefineReport report;
};

// The CDT of `file` refined with angle bound `angle` (0: none) and area bound
// `area` (<= 0: none) on `threads` threads (1: the sequential refiner), at
// quadtree granularity `granularity` (0: the default); the parallel
// layer's report in *parallel_report if given.
Refined refine_file(const fs::path& file, double angle, double area, unsigned threads,
                    unsigned granularity = 0, parallel::ParallelReport* parallel_report = nullptr) {
    Refined r;
    const auto read = io::read_poly(file.string(), ignore_warning);
    r.pslg = triangulate::pslg_from(read.data);
    for (const std::uint32_t v : r.pslg.segments) r.ends.push_back(mesh::VertexId{v});
    r.mesh = triangulate::constrained_delaunay(r.pslg, {}, r.cdt);
    r.settings.criteria.min_angle_degrees = angle;
    r.settings.criteria.max_area = area;
    r.settings.segment_ends = r.ends;
    if (threads == 1) {
        refine::refine_mesh(r.mesh, r.settings, r.report);
    } else {
        parallel::ParallelReport report;
        parallel::refine_parallel(r.mesh, r.settings, threads, granularity, report);
        r.report = report.refine;
        if (parallel_report != nullptr) *parallel_report = std::move(report);
    }
    return r;
}

std::size_t triangle_count(const mesh::Mesh& m) {
    std::size_t n = 0;
    mesh::for_each_triangle(m, [&](mesh::TriangleId, const mesh::Triangle&) { ++n; });
    return n;
}

// Models whose smallest input angle is large: nothing may be left there.
bool no_tiny_input_angles(const fs::path& file) {
    const std::string n = file.stem().string();
    return n == "channel" || n == "pipe-section" || n == "coastline" || n == "flow" || n == "pipe";
}

void check_terminates(const fs::path& file, double angle, unsigned threads) {
    INFO(file.filename().string() << " -q" << angle << " -j" << threads);
    Refined r = refine_file(file, angle, -1, threads);
    REQUIRE(r.report.stopped == refine::RefineReport::Stop::none);
    const auto problems = mesh::check_mesh(r.mesh);
    for (const auto& p : problems) INFO(p);
    REQUIRE(problems.empty());
    const auto conformity = triangulate::check_conformity(r.mesh, r.pslg, r.cdt);
    for (const auto& p : conformity) INFO(p);
    REQUIRE(conformity.empty());
    CHECK(r.report.left_other == 0);
    CHECK(r.report.left_precision <= 8);  // a handful
    if (no_tiny_input_angles(file)) CHECK(r.report.left_precision == 0);
    const refine::QualityTest quality(r.settings.criteria, refine::SegmentEnds{r.ends});
    std::size_t poor = 0;
    mesh::for_each_triangle(r.mesh, [&](mesh::TriangleId id, const mesh::Triangle& t) {
        const auto& a = r.mesh.point(t.v[0]);
        const auto& b = r.mesh.point(t.v[1]);
        const auto& c = r.mesh.point(t.v[2]);
        if (test::smallest_angle(a, b, c) >= angle - 1e-9) return;
        bool protected_angle = false;
        quality.assess(r.mesh, id, refine::QualityTest::measure(a, b, c), &protected_angle);
        if (!protected_angle) ++poor;
    });
    CHECK(poor <= r.report.left_precision);
}

// Triangle 1.6's triangle counts (measured with `triangle -Q -p...` on these
// files; the models come from scripts/make-models.py).
struct Reference {
    const char* file;  // under tests/data/models, or poly-samples with a leading '@'
    double angle;      // -q (0: none)
    double area;       // -a (<= 0: none)
    std::size_t triangle;
};
const Reference references[] = {
    {"channel", 30, -1, 488},
    {"channel", 34, -1, 751},
    {"pipe-section", 30, -1, 1204},
    {"pipe-section", 34, -1, 1490},
    {"coastline", 30, -1, 3172},
    {"coastline", 34, -1, 5678},
    {"star", 34, -1, 100},
    {"@flow", 33, -1, 4850},
    {"channel", 0, 0.4, 1591},
    {"pipe-section", 0, 0.4, 1146},
    {"coastline", 0, 4800, 1616},
    {"star", 0, 0.4, 324},
    {"@flow", 0, 0.3, 2018},
    {"@pipe", 0, 160, 2416},
    {"@pipe", 25, -1, 5862},
    {"@flow", 25, -1, 2454},
    {"channel", 25, -1, 369},
    // An angle bound above 30 degrees with an area bound: the order of the
    // triangles poor only by size decides the size too (a stack of them
    // gave 1.73 times Triangle's count on flow at 34 degrees).
    {"@flow", 34, 0.075, 10305},
    {"channel", 34, 0.1, 10136},
    {"coastline", 34, 1192.8, 8072},
    {"@pipe", 33, 40, 13230},
    // The same from 31 to 33 degrees, where two threads refine in the
    // quadtree (refine::max_quadtree_angle).
    {"@flow", 33, 0.075, 9250},
    {"channel", 33, 0.1, 6658},
    {"coastline", 33, 1192.8, 6602},
    {"star", 33, 0.01, 13250},
    {"pipe-section", 32, 0.1, 4319},
    {"crossing", 32, 0.02, 8323},
    {"@pipe", 31, 40, 11502},
};

// Triangle 1.6's counts with an area bound alone (about 50,000 triangles)
// and with -q20 (about 20,000), summed over the models: the order of the
// triangles poor only by size is what decides them.  Each model's ratio
// swings by about 1% with any change of order; the sums do not.
const Reference sized_references[] = {
    {"@flow", 0, 0.006, 77337},        {"@pipe", 0, 3.2, 54288},      {"channel", 0, 0.008, 75799},
    {"pipe-section", 0, 0.008, 53036}, {"coastline", 0, 95.4, 49507}, {"star", 0, 0.00761, 16155},
    {"@flow", 20, 0.015, 31244},       {"@pipe", 20, 8, 22488},       {"channel", 20, 0.02, 30248},
    {"pipe-section", 20, 0.02, 21036}, {"coastline", 20, 239, 19894}, {"star", 20, 0.019, 6503},
};

fs::path reference_file(const Reference& ref) {
    const std::string name = ref.file;
    return name[0] == '@' ? test::project_samples() / (name.substr(1) + ".poly")
                          : models() / (name + ".poly");
}

}  // namespace

TEST_CASE("refinement ends at 33 and 34 degrees on every sample and model, on 1 and 2 threads",
          "[api][refine][order]") {
    std::vector<fs::path> files = test::poly_files(test::project_samples());
    for (const auto& f : test::poly_files(models())) files.push_back(f);
    for (const auto& f : test::poly_files(test::test_data())) files.push_back(f);
    for (const auto& file : files)
        for (const double angle : {33.0, 34.0})
            for (const unsigned threads : {1u, 2u}) check_terminates(file, angle, threads);
}

TEST_CASE("one thread's meshes are as small as Triangle's", "[api][refine][order]") {
    for (const Reference& ref : references) {
        const Refined r = refine_file(reference_file(ref), ref.angle, ref.area, 1);
        const double ratio = double(triangle_count(r.mesh)) / double(ref.triangle);
        INFO(ref.file << " -q" << ref.angle << " -a" << ref.area << ": " << triangle_count(r.mesh)
                      << " triangles, Triangle " << ref.triangle);
        // Measured: 0.86-1.04 with an angle bound, 0.93-1.02 with -a alone.
        CHECK(ratio <= (ref.angle > 0 ? 1.10 : 1.03));
    }
}

TEST_CASE("two threads' meshes stay near one thread's", "[api][refine][order]") {
    for (const Reference& ref : references) {
        // (Above max_quadtree_angle every thread count runs the sequential
        // refiner: "above 33 degrees every thread count writes one thread's
        // mesh".)
        if (ref.angle == 0 || ref.angle > refine::max_quadtree_angle) continue;
        const Refined one = refine_file(reference_file(ref), ref.angle, ref.area, 1);
        const Refined two = refine_file(reference_file(ref), ref.angle, ref.area, 2);
        const double ratio = double(triangle_count(two.mesh)) / double(triangle_count(one.mesh));
        INFO(ref.file << " -q" << ref.angle << ": -j2 " << triangle_count(two.mesh) << ", -j1 "
                      << triangle_count(one.mesh));
        // Measured: 1.000 on every reference with an angle bound alone (the
        // root refines these small meshes alone, in -j1's order), 0.988-1.020
        // with -a at 31-33 degrees; 0.96-1.14 on the generated models at
        // 31-33 degrees with -a for 2,000 to 400,000 triangles
        // (docs/refinement-order.md).
        CHECK(ratio <= (ref.angle <= 30 ? 1.03 : 1.15));
    }
}

TEST_CASE("above 30 degrees with an area bound, leaves split and refine side by side",
          "[api][refine][order]") {
    // Triangles poor only by size wait by their shortest edge there, as in
    // -j1, but only within a leaf's own levels (PoorKind::size_edges), so
    // that a leaf splits once its size work is its children's.  In the
    // window of the triangles poor by their angle, the root kept nearly all
    // the work: one leaf a round.
    const fs::path flow = test::project_samples() / "flow.poly";
    for (const double angle : {31.0, 33.0}) {
        parallel::ParallelReport two;
        const Refined one = refine_file(flow, angle, 0.005, 1);
        const Refined r = refine_file(flow, angle, 0.005, 2, 0, &two);
        std::uint64_t work = 0, span = 0;
        for (const auto& round : two.rounds) {
            for (const std::uint64_t w : round) work += w;
            if (!round.empty()) span += *std::max_element(round.begin(), round.end());
        }
        const double ratio = double(triangle_count(r.mesh)) / double(triangle_count(one.mesh));
        INFO("-q" << angle << " -a0.005: work / span " << double(work) / double(span) << ", -j2 "
                  << triangle_count(r.mesh) << ", -j1 " << triangle_count(one.mesh));
        REQUIRE(span != 0);
        CHECK(double(work) / double(span) >= 1.5);
        CHECK(ratio <= 1.15);
        CHECK(mesh::check_mesh(r.mesh).empty());
    }
}

TEST_CASE("a leaf that cannot split yet takes its triangles in one thread's order",
          "[api][refine][order]") {
    // At -g1 the windows are narrow, so that these small models have work
    // below the root's window while large triangles keep the root from
    // splitting, as a coastline of 100,000 segments has at -g5
    // (Worker::refine_while_blocked).
    for (const auto& file : test::poly_files(models())) {
        for (const double angle : {25.0, 30.0}) {
            const Refined one = refine_file(file, angle, -1, 1);
            const Refined two = refine_file(file, angle, -1, 2, 1);
            INFO(file.filename().string()
                 << " -q" << angle << " -g1: -j2 " << triangle_count(two.mesh) << ", -j1 "
                 << triangle_count(one.mesh));
            // Measured: 1.000 on every model.  With the window alone: the
            // coastline 1.03 and 1.13, the channel 1.13 and 1.33.
            CHECK(double(triangle_count(two.mesh)) / double(triangle_count(one.mesh)) <= 1.01);
            CHECK(mesh::check_mesh(two.mesh).empty());
        }
    }
}

TEST_CASE("triangles poor only by size are taken in about Triangle's order",
          "[api][refine][order]") {
    for (const double angle : {0.0, 20.0}) {
        std::size_t ours = 0, theirs = 0;
        for (const Reference& ref : sized_references) {
            if (ref.angle != angle) continue;
            ours += triangle_count(refine_file(reference_file(ref), ref.angle, ref.area, 1).mesh);
            theirs += ref.triangle;
        }
        INFO("-q" << angle << " with -a: " << ours << " triangles, Triangle " << theirs);
        // Measured: 1.0002 with -a alone, 0.9987 with -q20.  Taking each
        // insertion's triangles newest first from the size bin, without
        // sorting them (queue_size_only), gave 1.0060 and 1.0060.
        CHECK(double(ours) / double(theirs) <= 1.003);
    }
}

TEST_CASE("refining by size alone leaves a mesh that meets the bound as it is",
          "[api][refine][order]") {
    for (const auto& file : test::poly_files(models())) {
        INFO(file.filename().string());
        // The bound: the largest triangle of the mesh -a gives, which that
        // mesh meets; refining it again must add nothing (no vertex
        // encroaches a subsegment without an angle bound).
        Refined r = refine_file(file, 0, -1, 1);
        double largest = 0;
        mesh::for_each_triangle(r.mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
            largest = std::max(
                largest, refine::QualityTest::measure(r.mesh.point(t.v[0]), r.mesh.point(t.v[1]),
                                                      r.mesh.point(t.v[2]))
                             .area);
        });
        refine::RefineSettings settings = r.settings;
        settings.criteria.max_area = largest;
        refine::RefineReport again;
        refine::refine_mesh(r.mesh, settings, again);
        CHECK(again.steiner_points == 0);
    }
}
