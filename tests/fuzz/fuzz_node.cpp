// Fuzz target: the .node reader (io::read_node).  The input is the file.
// What it reads must be consistent, and must read back the same after
// write_node() wrote it: the writer and the reader agree on every value
// the reader accepts.

#include <cstdint>
#include <string_view>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "fuzz/fuzz_checks.hpp"
#include "fuzz/round_trip.hpp"
#include "fuzz/scratch_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace gpdr;
    const std::string path =
        fuzz::write_scratch_file("in.node", {reinterpret_cast<const char*>(data), size});
    io::ReadResult<NodeSet> read;
    try {
        read = io::read_node(path, ignore_warning, size % 2);
    } catch (const InputError&) {
        return 0;
    }
    fuzz::expect_base(read.base);
    fuzz::expect_consistent(read.data);
    fuzz::expect_node_round_trip(read);
    return 0;
}
