// Fuzz target: the .area reader (io::read_area).  The input is an .ele
// file, a line "@@", and the .area file; the triangle count comes from the
// .ele, as in a run with -ra (its corners may name any of a million
// vertices).  What it reads must be one bound per triangle, and survive a
// write-then-read round trip.

#include <cmath>
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
    const std::string ele_path = fuzz::write_scratch_file("in.ele", parts[0]);
    const std::string area_path = fuzz::write_scratch_file("in.area", parts[1]);
    const int base = static_cast<int>(size % 2);
    io::ReadResult<AreaSet> read;
    try {
        const auto ele = io::read_ele(ele_path, base, std::size_t{1} << 20, ignore_warning);
        read = io::read_area(area_path, base, ele.data.size(), ignore_warning);
        fuzz::expect(read.data.size() == ele.data.size(), "area bounds not one per triangle");
    } catch (const InputError&) {
        return 0;
    }
    for (double a : read.data) fuzz::expect(!std::isnan(a), "an area bound that is not a number");
    fuzz::expect_area_round_trip(read.data, base);
    return 0;
}
