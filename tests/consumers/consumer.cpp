// A C++ program built against an installed gpdr: gpdr/*.hpp and libgpdr.a,
// found by CMake or pkg-config.  Meshes the unit square in memory.
#include <cstdio>

#include <gpdr/memory_job.hpp>
#include <gpdr/switches.hpp>

int main() {
    gpdr::Options options;
    gpdr::parse_switches("-q30a0.01Q", options);
    gpdr::MeshInput input;
    input.nodes.xy = {0, 0, 1, 0, 1, 1, 0, 1};
    const gpdr::MemoryJobResult result =
        gpdr::run_job_in_memory(options, std::move(input), gpdr::ignore_warning);
    std::printf("consumer.cpp: %zu triangles\n", result.mesh.triangles.size());
    return result.mesh.triangles.size() >= 100 ? 0 : 1;
}
