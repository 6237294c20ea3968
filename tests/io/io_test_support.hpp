#pragma once
// Helpers for the io tests: read an input the way gpdr's command line would
// (the extension picks the files), collect warnings, and compare data sets
// bit for bit.

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include <gpdr/diagnostics.hpp>
#include <gpdr/io.hpp>

#include "cli/cli_support.hpp"

namespace gpdr::test {

struct WarningLog {
    std::vector<Warning> warnings;
    WarningSink sink() {
        return [this](const Warning& w) { warnings.push_back(w); };
    }
};

inline std::string without_extension(const std::string& name) {
    return name.substr(0, name.rfind('.'));
}

// Reads `input` (in `dir`) with the readers gpdr uses for it:
// .node; .poly (maybe with its .node); .ele = .node + .ele;
// .area = .node + .ele + .area.
inline void read_as_cli(const TempDir& dir, const std::string& input, const WarningSink& warn) {
    const std::string path = (dir / input).string();
    const std::string ext = input.substr(input.rfind('.'));
    const std::string stem = (dir / without_extension(input)).string();
    if (ext == ".node") {
        io::read_node(path, warn);
    } else if (ext == ".poly") {
        io::read_poly(path, warn);
    } else {
        const auto nodes = io::read_node(stem + ".node", warn);
        const auto ele = io::read_ele(stem + ".ele", nodes.base, nodes.data.size(), warn);
        if (ext == ".area") io::read_area(stem + ".area", nodes.base, ele.data.size(), warn);
    }
}

// Bit-exact equality of doubles (tells -0.0 from 0.0).
inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
    return true;
}

}  // namespace gpdr::test
