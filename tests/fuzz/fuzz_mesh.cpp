// Fuzz target: reading a mesh to refine (-r), the way a run reads it
// (read_input): the input is the .node, .ele, .area and .poly files in
// that order, separated by lines "@@".  An .area part that is there and
// not empty adds bare -a, a .poly part -p; the vertices number from 0 or 1
// as the input's length is even or odd (-z's default).  The read input
// must be consistent: every corner in range, one area bound per triangle.
// (A -rp segment's endpoints are checked against the .poly's own vertices
// when it has some; that they name vertices of the .node is checked when the
// mesh is rebuilt, from_triangles.hpp.)

#include <cstdint>

#include <gpdr/errors.hpp>
#include <gpdr/file_names.hpp>
#include <gpdr/options.hpp>

#include "api/job_stages.hpp"
#include "fuzz/fuzz_checks.hpp"
#include "fuzz/scratch_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace gpdr;
    const auto parts = fuzz::split_parts(data, size, 4);
    const char* const names[] = {"in.node", "in.ele", "in.area", "in.poly"};
    for (std::size_t i = 0; i < 4; ++i) {
        if (i < parts.size())
            fuzz::write_scratch_file(names[i], parts[i]);
        else
            fuzz::remove_scratch_file(names[i]);
    }
    Options options;
    options.refine = true;
    options.regional_area = parts.size() > 2 && !parts[2].empty();
    options.poly = parts.size() > 3 && !parts[3].empty();
    options.zero_based = size % 2 == 0;
    options.input = fuzz::scratch_path("in");
    api::Input in;
    try {
        in = api::read_input(options, file_names(options), ignore_warning);
    } catch (const InputError&) {
        return 0;
    }
    const std::size_t n = in.nodes.data.size();
    fuzz::expect_base(in.nodes.base);
    fuzz::expect_consistent(in.nodes.data);
    fuzz::expect(in.triangles.has_value(), "-r read no triangles");
    fuzz::expect_indices(*in.triangles, n);
    if (options.regional_area)
        fuzz::expect(in.areas && in.areas->size() == in.triangles->size(),
                     "-ra read no area bound per triangle");
    if (options.poly) fuzz::expect(in.poly.has_value(), "-rp read no .poly");
    return 0;
}
