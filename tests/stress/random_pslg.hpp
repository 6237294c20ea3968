#pragma once
// Random planar straight line graphs that are hard on segment insertion:
// few vertices on a small integer grid joined by segments that cross one
// another, overlap along shared lines and pass through vertices, then scaled
// and moved (by factors from 1e-5 to 1e6, offsets up to 1e6) so that the
// crossing points are not representable and their rounding matters.  Some
// carry hole points and region points.
//
// Everything is derived from the seed by the generator's own arithmetic (no
// standard distribution, whose output differs between libraries), so a seed
// names the same input on every machine.

#include <cstdint>
#include <string>

#include <gpdr/files.hpp>

namespace gpdr::stress {

enum class Family {
    dense,   // 6-20 vertices on a 4x4 to 7x7 grid, 8-30 segments
    sparse,  // 4-14 vertices on a 15x15 grid, 2-9 segments
};

const char* family_name(Family family);

struct RandomPslg {
    std::uint64_t seed = 0;
    Family family = Family::dense;
    double scale = 1, offset_x = 0, offset_y = 0;
    PolyFile poly;  // vertices numbered from 1 when written
};

// Even seeds give the dense family, odd ones the sparse family.
RandomPslg random_pslg(std::uint64_t seed);

// The PSLG as a .poly file, with `comment` (one line, no newline) as a `#`
// comment at its top.  Coordinates are written with 17 significant digits,
// so the file holds exactly the doubles that were generated.
std::string poly_text(const PolyFile& poly, const std::string& comment);

}  // namespace gpdr::stress
