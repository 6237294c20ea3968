#pragma once
// Field checks shared by the readers of Triangle's files: header counts of
// attributes and markers, boundary markers, and indices validated against
// the numbering base and the number of entries they refer to.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "io/text_reader.hpp"

namespace gpdr::io::detail {

// Indices are stored as 32-bit values with 0xffffffff reserved as "none".
inline void check_index_capacity(TextReader& in, std::size_t count, std::string_view what) {
    if (count >= std::numeric_limits<std::uint32_t>::max())
        in.fail(fmt::format("{} {} are more than gpdr's limit of {}", count, what,
                            std::numeric_limits<std::uint32_t>::max() - 1));
}

// "<#attributes>" of a header, for `entries` entries.  Missing attribute
// values read as 0 (as in Triangle), but a file may not declare more values
// than it could hold: every value takes at least two bytes (a digit and a
// separator; the file's last may lack its separator), so entries x
// attributes must fit in half the bytes after the header.  Otherwise a tiny
// file could declare a million attributes per vertex, every one of them
// stored, interpolated and written out.  A regular file is checked here; a
// stream once it has been read to its end (TextReader::require_rest), and
// while it is read TextReader::real_or bounds the values it leaves out by
// the bytes read so far, so that memory stays in proportion to them.
inline std::uint32_t attribute_count(TextReader& in, std::size_t entries, std::string_view what) {
    const std::int64_t n = in.integer_or(0, what);
    if (n < 0) in.fail(fmt::format("{} {} is negative", what, n));
    // values <= (rest + 1) / 2, rounded down, is rest >= 2 x values - 1.
    const std::uint64_t holders = std::max<std::uint64_t>(entries, 1);
    const double values = double(n) * double(holders);
    const std::uint64_t need = n == 0             ? 0
                               : values >= 0x1p62 ? std::numeric_limits<std::uint64_t>::max()
                                                  : 2 * static_cast<std::uint64_t>(n) * holders - 1;
    in.require_rest(need, [=](std::uint64_t rest) {
        return fmt::format(
            "{} {} is impossible: {} entries of {} values need at least {:.0f} bytes, and the "
            "rest of the file has {}",
            what, n, entries, n, 2.0 * values, rest);
    });
    if (n >= std::numeric_limits<std::uint32_t>::max())
        in.fail(fmt::format("{} {} is more than gpdr's limit of {}", what, n,
                            std::numeric_limits<std::uint32_t>::max() - 1));
    return static_cast<std::uint32_t>(n);
}

// "<#markers>" of a header: 0 or 1 (missing: 0).
inline bool marker_count(TextReader& in, std::string_view what) {
    const std::int64_t n = in.integer_or(0, what);
    if (n != 0 && n != 1) in.fail(fmt::format("{} must be 0 or 1, not {}", what, n));
    return n == 1;
}

// A boundary marker (missing: 0, as in Triangle).
inline int marker(TextReader& in, std::string_view what) {
    const std::int64_t m = in.integer_or(0, what);
    if (m < std::numeric_limits<int>::min() || m > std::numeric_limits<int>::max())
        in.fail(fmt::format("{} {} is out of range", what, m));
    return static_cast<int>(m);
}

// An index into a list of `count` entries numbered from `base`; stored 0-based.
inline std::uint32_t checked_index(TextReader& in, std::int64_t i, int base, std::size_t count,
                                   std::string_view what, std::string_view entries) {
    if (i < base || static_cast<std::uint64_t>(i - base) >= count) {
        if (count == 0)
            in.fail(fmt::format("{} {} is out of range: there are no {}", what, i, entries));
        in.fail(fmt::format("{} {} is out of range: {} are numbered {} to {}", what, i, entries,
                            base, static_cast<std::int64_t>(count) - 1 + base));
    }
    return static_cast<std::uint32_t>(i - base);
}

inline std::uint32_t index_in(TextReader& in, int base, std::size_t count, std::string_view what,
                              std::string_view entries) {
    return checked_index(in, in.integer(what), base, count, what, entries);
}

inline std::uint32_t vertex_index(TextReader& in, int base, std::size_t vertex_count,
                                  std::string_view what) {
    return index_in(in, base, vertex_count, what, "vertices");
}

}  // namespace gpdr::io::detail
