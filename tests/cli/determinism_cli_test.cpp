// The same files for any thread count: gpdr -j2, -j3 and -j8 (twice) write
// byte-identical files for the samples and models, with angle and area
// bounds, regions, attributes, a triunsuitable() plug-in and the files for
// other programs; and each mesh passes -C's check.

#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

struct Run {
    std::string input;     // a path under the source tree
    std::string switches;  // without -j
};

// Every file of the run, by name, with its bytes.
std::vector<std::pair<std::string, std::string>> files_of(const TempDir& dir,
                                                          const std::string& stem) {
    std::vector<std::pair<std::string, std::string>> files;
    for (const std::string& name : dir.files())
        if (name.rfind(stem + ".1.", 0) == 0) files.emplace_back(name, dir.read(name));
    return files;
}

}  // namespace

TEST_CASE("gpdr writes the same bytes on any number of threads", "[cli][determinism]") {
    const std::vector<Run> runs = {
        {"poly-samples/flow.poly", "-pq30a0.05C --vtk --gmsh"},
        {"poly-samples/pipe.poly", "-pq33C"},
        {"poly-samples/pipe.poly", "-pa2C"},
        {"tests/data/face.poly", "-pq25a0.0005AenC"},
        {"tests/data/letter.poly", "-pq30a0.001C"},
        {"tests/data/models/channel.poly", "-pq34C"},
        {"tests/data/models/crossing.poly", "-pq28a0.01C"},
        {"tests/data/nested_hex.poly", "-pq20a0.001Ao2C --svg"},
    };
    for (const Run& r : runs) {
        const fs::path input = source_dir() / r.input;
        const std::string name = input.filename().string();
        const std::string stem = input.stem().string();
        INFO(r.input << " " << r.switches);
        std::vector<std::pair<std::string, std::string>> expected;
        for (const char* threads : {"-j2", "-j3", "-j8", "-j8"}) {
            INFO(threads);
            TempDir dir;
            fs::copy_file(input, dir / name);
            const RunResult result = run_gpdr(dir, "-Q " + r.switches + " " + threads + " " + name);
            INFO(result.err);
            REQUIRE(result.status == 0);
            const auto files = files_of(dir, stem);
            REQUIRE(files.size() >= 3);
            if (expected.empty()) {
                expected = files;
                continue;
            }
            REQUIRE(files.size() == expected.size());
            for (std::size_t i = 0; i < files.size(); ++i) {
                INFO(files[i].first);
                CHECK(files[i].first == expected[i].first);
                CHECK(files[i].second == expected[i].second);
            }
        }
    }
}

TEST_CASE("a triunsuitable() plug-in's mesh is the same on any number of threads",
          "[cli][determinism][plugin]") {
    // The graded pipe's plug-in (poly-samples/grading.c), coarser.
    TempDir lib;
    const std::string compile = "cc -O2 -shared -fPIC -DGRADING_C=0.1 -o '" +
                                (lib / "grading.so").string() + "' '" +
                                (project_samples() / "grading.c").string() + "' -lm 2>&1";
    REQUIRE(std::system("command -v cc >/dev/null 2>&1") == 0);  // (setup.sh installs one)
    REQUIRE(std::system(compile.c_str()) == 0);
    const fs::path plugin = lib / "grading.so";
    std::string expected;
    for (const char* threads : {"-j2", "-j5"}) {
        TempDir dir;
        fs::copy_file(project_samples() / "pipe.poly", dir / "pipe.poly");
        const RunResult result =
            run_gpdr(dir, std::string("-Qpq20 ") + threads + " --unsuitable '" + plugin.string() +
                              "' pipe.poly");
        INFO(result.err);
        REQUIRE(result.status == 0);
        const std::string ele = dir.read("pipe.1.ele") + dir.read("pipe.1.node");
        if (expected.empty())
            expected = ele;
        else
            CHECK(ele == expected);
    }
}

TEST_CASE("above 33 degrees every thread count writes one thread's mesh", "[cli][determinism]") {
    // Meshes where the quadtree's order gave 1.1 to 3.5 times one thread's
    // triangles (max_quadtree_angle).
    const std::vector<Run> runs = {
        {"tests/data/models/channel.poly", "-pq34a0.02"},
        {"poly-samples/flow.poly", "-pq34a0.075"},
        {"tests/data/models/crossing.poly", "-pq33.5a0.002"},
    };
    for (const Run& r : runs) {
        const fs::path input = source_dir() / r.input;
        const std::string name = input.filename().string();
        INFO(r.input << " " << r.switches);
        std::string expected;
        for (const char* threads : {"-j1", "-j2"}) {
            TempDir dir;
            fs::copy_file(input, dir / name);
            const RunResult result = run_gpdr(dir, "-Q " + r.switches + " " + threads + " " + name);
            INFO(result.err);
            REQUIRE(result.status == 0);
            const std::string stem = input.stem().string();
            const std::string mesh = dir.read(stem + ".1.node") + dir.read(stem + ".1.ele");
            if (expected.empty())
                expected = mesh;
            else
                CHECK(mesh == expected);
        }
    }
}

TEST_CASE("with -V, gpdr says which refiner an angle bound gets", "[cli][determinism]") {
    // Up to 33 degrees the quadtree's rounds (whose -V report names the
    // rounds), above it the sequential refiner, whatever -j says.
    const fs::path input = source_dir() / "poly-samples" / "flow.poly";
    const std::string one_thread = "Refinement on one thread, in Triangle's order";
    for (const char* angle : {"30", "33", "33.01", "34"}) {
        INFO("-q" << angle);
        TempDir dir;
        fs::copy_file(input, dir / "flow.poly");
        const RunResult result = run_gpdr(dir, std::string("-pVq") + angle + "a0.01 -j2 flow.poly");
        INFO(result.err);
        REQUIRE(result.status == 0);
        const bool sequential = std::stod(angle) > 33.0;
        CHECK((result.out.find(one_thread) != std::string::npos) == sequential);
        CHECK((result.out.find("rounds refining") != std::string::npos) == !sequential);
        if (sequential)
            CHECK(result.out.find("the angle bound is above 33 degrees") != std::string::npos);
        else
            CHECK(result.out.find("Refinement in rounds over the quadtree on 2 threads") !=
                  std::string::npos);
    }
}

TEST_CASE("with -V, gpdr says why a run refines on one thread", "[cli][determinism]") {
    const fs::path input = source_dir() / "poly-samples" / "flow.poly";
    const std::pair<const char*, const char*> cases[] = {
        {"-pVq30a0.01 -j1", "Refinement on one thread, in Triangle's order: -j1"},
        {"-pVq30a0.01S100 -j2", "Refinement on one thread, in Triangle's order: -S"},
    };
    for (const auto& [switches, said] : cases) {
        INFO(switches);
        TempDir dir;
        fs::copy_file(input, dir / "flow.poly");
        const RunResult result = run_gpdr(dir, std::string(switches) + " flow.poly");
        INFO(result.err);
        REQUIRE(result.status == 0);
        CHECK(result.out.find(said) != std::string::npos);
        CHECK(result.out.find("rounds refining") == std::string::npos);
    }
}

TEST_CASE("gpdr refuses --nondeterministic: every thread count writes the same files",
          "[cli][determinism]") {
    TempDir dir;
    fs::copy_file(source_dir() / "poly-samples" / "flow.poly", dir / "flow.poly");
    const RunResult result = run_gpdr(dir, "-pq30 --nondeterministic flow.poly");
    CHECK(result.status == 1);
    CHECK(result.err.find("it writes the same files for every thread count from 2 up") !=
          std::string::npos);
    CHECK(dir.files() == std::vector<std::string>{"flow.poly"});
}
