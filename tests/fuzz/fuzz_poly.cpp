// Fuzz target: the .poly reader (io::read_poly).  The input is the .poly
// file, optionally followed by a line "@@" and the .node file of the same
// name, which a .poly whose vertex count is 0 takes its vertices from.
// What it reads must be consistent and survive a write-then-read round trip.

#include <cstdint>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "fuzz/fuzz_checks.hpp"
#include "fuzz/round_trip.hpp"
#include "fuzz/scratch_files.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace gpdr;
    const auto parts = fuzz::split_parts(data, size, 2);
    const std::string path = fuzz::write_scratch_file("in.poly", parts[0]);
    if (parts.size() > 1)
        fuzz::write_scratch_file("in.node", parts[1]);
    else
        fuzz::remove_scratch_file("in.node");
    io::ReadResult<PolyFile> read;
    try {
        read = io::read_poly(path, ignore_warning, size % 2);
    } catch (const InputError&) {
        return 0;
    }
    const PolyFile& poly = read.data;
    fuzz::expect_base(read.base);
    fuzz::expect_consistent(poly.nodes);
    fuzz::expect_indices(poly.segments, poly.nodes.size());
    fuzz::expect(poly.holes.size() % 2 == 0, "an odd number of hole coordinates");
    fuzz::expect_poly_round_trip(read);
    return 0;
}
