// Fuzz target: the .ele reader (io::read_ele).  The input is a .node file,
// a line "@@", and the .ele file; the vertices' count and numbering base
// come from the .node, as in a run with -r.  What it reads must be
// consistent and survive a write-then-read round trip.

#include <cstdint>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "fuzz/fuzz_checks.hpp"
#include "fuzz/round_trip.hpp"
#include "fuzz/scratch_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace gpdr;
    const auto parts = fuzz::split_parts(data, size, 2);
    if (parts.size() < 2) return 0;
    const std::string node_path = fuzz::write_scratch_file("in.node", parts[0]);
    const std::string ele_path = fuzz::write_scratch_file("in.ele", parts[1]);
    io::ReadResult<NodeSet> nodes;
    io::ReadResult<EleSet> read;
    try {
        nodes = io::read_node(node_path, ignore_warning, size % 2);
        read = io::read_ele(ele_path, nodes.base, nodes.data.size(), ignore_warning);
    } catch (const InputError&) {
        return 0;
    }
    fuzz::expect_base(read.base);
    fuzz::expect_indices(read.data, nodes.data.size());
    fuzz::expect_ele_round_trip(read, nodes.base, nodes.data.size());
    return 0;
}
