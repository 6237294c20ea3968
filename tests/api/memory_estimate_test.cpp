// The memory a run may use (MemAvailable, cgroup limits: parsed from the
// files' text, so that no test depends on this machine) and the refusal of a
// run whose area bounds call for a mesh larger than that.

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include <gpdr/errors.hpp>
#include <gpdr/options.hpp>

#include "api/memory_available.hpp"
#include "api/memory_estimate.hpp"
#include "refine/area_demand.hpp"
#include "triangulate/constrained.hpp"

using namespace gpdr;
using namespace gpdr::api;

namespace {

constexpr std::uint64_t GB = 1000 * 1000 * 1000;

const char* const meminfo =
    "MemTotal:       24577432 kB\n"
    "MemFree:        22104816 kB\n"
    "MemAvailable:   23751148 kB\n"
    "Buffers:          112740 kB\n";

// The unit square [0,2]x[0,1]'s constrained Delaunay triangulation (two
// triangles, area 2).
mesh::Mesh rectangle() {
    triangulate::Pslg p;
    p.points = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    p.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    triangulate::CdtReport report;
    return triangulate::constrained_delaunay(p, {}, report);
}

refine::RefineSettings with_area(double bound) {
    refine::RefineSettings s;
    s.criteria.max_area = bound;
    return s;
}

}  // namespace

TEST_CASE("MemAvailable is read from /proc/meminfo's text", "[api][memory]") {
    CHECK(parse_mem_available(meminfo) == std::uint64_t{23751148} * 1024);
    CHECK(parse_mem_available("MemAvailable: 5 kB") == std::uint64_t{5120});
    CHECK(parse_mem_available("MemAvailable:\t123\n") == std::uint64_t{123});
    CHECK_FALSE(parse_mem_available("MemTotal: 100 kB\nMemFree: 50 kB\n"));
    CHECK_FALSE(parse_mem_available("MemAvailable: lots\n"));
    CHECK_FALSE(parse_mem_available(""));
}

TEST_CASE("cgroup memory limits are read as v2 and v1 write them", "[api][memory]") {
    CHECK(parse_cgroup_limit("4294967296\n") == std::uint64_t{4294967296});
    CHECK_FALSE(parse_cgroup_limit("max\n"));                  // v2: no limit
    CHECK_FALSE(parse_cgroup_limit("9223372036854771712\n"));  // v1: no limit
    CHECK_FALSE(parse_cgroup_limit(""));
    CHECK_FALSE(parse_cgroup_limit("12 kB"));
}

TEST_CASE("/proc/self/cgroup names the groups whose limits apply", "[api][memory]") {
    SECTION("cgroup v2 alone") {
        const CgroupPaths g = parse_proc_self_cgroup("0::/user.slice/run-42.scope\n");
        CHECK(g.unified == "/user.slice/run-42.scope");
        CHECK_FALSE(g.memory_v1);
        const std::vector<std::string> files = cgroup_limit_files(g, "/sys/fs/cgroup");
        const std::vector<std::string> expected = {
            "/sys/fs/cgroup/user.slice/run-42.scope/memory.max",
            "/sys/fs/cgroup/user.slice/memory.max",
            "/sys/fs/cgroup/memory.max",
            "/sys/fs/cgroup/unified/user.slice/run-42.scope/memory.max",
            "/sys/fs/cgroup/unified/user.slice/memory.max",
            "/sys/fs/cgroup/unified/memory.max",
        };
        CHECK(files == expected);
    }
    SECTION("cgroup v1 with the memory controller among others") {
        const CgroupPaths g = parse_proc_self_cgroup(
            "9:name=systemd:/\n5:cpu,cpuacct:/\n4:memory,hugetlb:/docker/ab:c\n0::/\n");
        CHECK(g.memory_v1 == "/docker/ab:c");  // a ':' in the path stays
        CHECK(g.unified == "/");
        const std::vector<std::string> files = cgroup_limit_files(g, "/cg");
        const std::vector<std::string> expected = {
            "/cg/memory.max",
            "/cg/unified/memory.max",
            "/cg/memory/docker/ab:c/memory.limit_in_bytes",
            "/cg/memory/docker/memory.limit_in_bytes",
            "/cg/memory/memory.limit_in_bytes",
        };
        CHECK(files == expected);
    }
    SECTION("nothing usable") {
        const CgroupPaths g = parse_proc_self_cgroup("garbage\n3:cpu:/\n");
        CHECK_FALSE(g.unified);
        CHECK_FALSE(g.memory_v1);
        CHECK(cgroup_limit_files(g, "/sys/fs/cgroup").empty());
    }
}

TEST_CASE("this machine's available memory is found", "[api][memory]") {
    // Linux always has /proc/meminfo with MemAvailable (since 3.14).
    const auto available = memory_available();
    REQUIRE(available);
    CHECK(*available > 0);
}

TEST_CASE("the memory estimate follows the area bounds", "[api][memory]") {
    const mesh::Mesh m = rectangle();
    Options o;
    o.input = "box.poly";
    SECTION("an angle bound alone gives no estimate") {
        o.quality = true;
        CHECK_FALSE(estimate_memory(o, m, refine::RefineSettings{}, 0).known);
    }
    o.area_limit = true;
    o.max_area = 1e-6;
    const MemoryEstimate plain = estimate_memory(o, m, with_area(1e-6), 0);
    REQUIRE(plain.known);
    CHECK(plain.triangles == Approx(refine::AreaDemand::fill * 2e6));
    CHECK(plain.bytes == Approx(plain.triangles * bytes_per_triangle));
    SECTION("outputs built from neighbours cost more") {
        o.write_neighbours = true;
        CHECK(estimate_memory(o, m, with_area(1e-6), 0).bytes ==
              Approx(plain.triangles * bytes_per_triangle_with_neighbours));
    }
    SECTION("vertex attributes cost more") {
        CHECK(estimate_memory(o, m, with_area(1e-6), 3).bytes > plain.bytes);
    }
    SECTION("-S caps the triangles at two per Steiner point") {
        o.steiner_limit = true;
        o.max_steiner = 100;
        CHECK(estimate_memory(o, m, with_area(1e-6), 0).triangles == Approx(202));
    }
}

TEST_CASE("a run whose mesh exceeds the memory available is refused", "[api][memory]") {
    const mesh::Mesh m = rectangle();
    Options o;
    o.input = "box.poly";
    o.area_limit = true;
    o.max_area = 5e-11;  // 2 / 5e-11 = 4e10 triangles at the bound
    const MemoryEstimate e = estimate_memory(o, m, with_area(o.max_area), 0);
    REQUIRE(e.bytes > 1000.0 * GB);
    try {
        refuse_beyond_memory(o, e, 20 * GB);
        FAIL("not refused");
    } catch (const ResourceError& error) {
        const std::string what = error.what();
        CHECK(what ==
              "box.poly: -a5e-11 would make about 6.0e10 triangles (~3.8 TB), more "
              "than the 20 GB of memory available");
    }
    // Enough memory, unknown memory, or --force: no refusal.
    CHECK_NOTHROW(refuse_beyond_memory(o, e, std::uint64_t(e.bytes) + 1));
    CHECK_NOTHROW(refuse_beyond_memory(o, e, std::nullopt));
    o.force = true;
    CHECK_NOTHROW(refuse_beyond_memory(o, e, 20 * GB));
}
