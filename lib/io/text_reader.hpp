#pragma once
// A cursor over the data lines and fields of one of Triangle's text files,
// mapped or read as it arrives (line_source.hpp: the two kinds of file, and
// the NUL byte and line length checks every line passes).
//
// Follows Triangle's reading rules (readline/findfield in triangle.c, as its
// documentation describes them): `#` starts a comment running to the end of
// the line, lines with no data are skipped, fields are separated by blanks.
// Numbers are parsed with std::from_chars, never with iostreams.  gpdr is
// stricter than Triangle in one way on purpose: a field that is read must be
// a whole number token ("1.5abc" or "x" is an InputError, where Triangle
// reads a prefix or skips the text), so typos cannot turn into silent zeros.
// One comma may end a field ("50, 2, 0, 0"): Triangle reads such files, and
// "50,2" stays an error (Triangle would read 50 and lose the 2).
//
// Deviation: numbers accept an exponent (1e-5) and an out-of-range value
// reads the way strtod reads it (underflow towards 0, overflow to infinity,
// which is then refused), like Triangle's strtod; a leading '+' is accepted.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <gpdr/diagnostics.hpp>
#include <gpdr/errors.hpp>

#include "io/line_source.hpp"

namespace gpdr::io::detail {

class TextReader {
public:
    // Values that the lines of a stream may leave out, beyond one per two
    // bytes read, before the file is refused (see real_or).
    static constexpr std::uint64_t left_out_slack = std::uint64_t{1} << 20;

    // Opens the file.  A missing or unreadable file is an InputError on line
    // 0; `why_needed`, when not empty, is appended to its reason (used by
    // .poly files that take their vertices from a .node file).
    explicit TextReader(std::string path, std::string_view why_needed = {});
    // The lines of `bytes`, one slice of a mapped file starting at a line
    // start, numbered from 1 (parallel_vertices.cpp adds the lines before).
    TextReader(std::string path, std::string_view bytes, LineSource::Borrowed);

    const std::string& path() const noexcept { return path_; }

    // Moves to the next line holding data.  Returns false at the end of the
    // file; line() is then the line after the last one.
    bool next_line();
    // The current line's number (1-based); after the end, last line + 1.
    std::size_t line() const noexcept { return line_; }

    // Whether the file's size is known: a regular file, not a stream.
    bool sized() const noexcept { return source_.sized(); }
    // Bytes known to follow the current line: the rest of a regular file;
    // of a stream, only those already read (a lower bound).
    std::size_t remaining_bytes() const noexcept { return source_.bytes_at_hand(); }
    // How many of `count` entries to reserve room for: no more than the
    // known bytes could hold at `min_bytes_per_entry` bytes each, so that a
    // count read from a stream, which count() cannot refuse up front, never
    // reserves memory the data has not paid for; vectors grow from there.
    std::size_t reserve_hint(std::size_t count, std::size_t min_bytes_per_entry) const noexcept {
        return std::min(count, remaining_bytes() / min_bytes_per_entry + 1);
    }

    // Reads the rest of the file, checking its lines as next_line() does (a
    // stream is read to its end), runs the checks that require_rest()
    // deferred, and returns the hash of the whole file's bytes
    // (content_hash.hpp), the same for a stream as for a regular file.
    std::uint64_t finish();

    // For a regular file: its bytes, and the offset of the byte after the
    // current line.
    std::string_view bytes() const noexcept { return source_.bytes(); }
    std::uint64_t offset() const noexcept { return source_.offset(); }
    // For a regular file: goes on after line `line`, which ends before byte
    // `offset`, its lines up to there read by other threads (see
    // LineSource::resume_at), and with `hash` as the file's content hash.
    void resume_at(std::uint64_t offset, std::size_t line, std::uint64_t hash) noexcept {
        source_.resume_at(offset, line);
        source_.adopt_hash(hash);
        line_ = line;
        pos_ = data_end_ = nullptr;
    }

    // The current line claims that at least `bytes` bytes follow it (a
    // header's counts); if not, InputError on this line with
    // `reason(bytes that follow)`.  Checked at once for a regular file, by
    // finish() for a stream, whose size is known only at its end.
    void require_rest(std::uint64_t bytes, std::function<std::string(std::uint64_t)> reason);

    // True when the current line has another field.
    bool has_field();
    // The next field as a signed integer.  Fields written as integral reals
    // ("3.0", "1e2") are accepted; "3.5" is not.  Missing or malformed: error
    // "<what> is missing" / "<what> '<token>' is not an integer".
    std::int64_t integer(std::string_view what);
    // The next field as a finite real.
    double real(std::string_view what);
    // Optional forms: the default when the line has no more fields.  A
    // stream may leave out at most left_out_slack reals plus one per
    // two bytes read so far (a real read takes two bytes or more, a digit and
    // a separator): a header's counts, which cannot be checked against a
    // stream's size up front, then cannot make a few bytes fill memory with
    // default values.
    std::int64_t integer_or(std::int64_t fallback, std::string_view what);
    double real_or(double fallback, std::string_view what);

    // An element count from a header: not negative, and, if large and the
    // file regular, not more entries than the rest of the file could hold
    // at `min_bytes_per_entry` bytes each.  From a stream a large count is
    // accepted: the readers reserve with reserve_hint() and report the file
    // ending early where it does.
    std::size_t count(std::string_view what, std::size_t min_bytes_per_entry = 2);

    [[noreturn]] void fail(std::string reason) const;
    [[noreturn]] void fail_at(std::size_t line, std::string reason) const;
    void warn(const WarningSink& sink, std::string message) const;

private:
    // A require_rest() claim on a stream, checked by finish().
    struct RestClaim {
        std::size_t line;
        std::uint64_t from;  // offset of the byte after the claiming line
        std::uint64_t bytes;
        std::function<std::string(std::uint64_t)> reason;
    };

    std::string_view token();  // the next field, without consuming it
    // Counts a value a stream's line left out; InputError past the bound.
    void count_left_out(std::string_view what);
    void skip_blanks() noexcept;

    std::string path_;
    LineSource source_;
    const char* pos_ = nullptr;       // cursor inside the current line
    const char* data_end_ = nullptr;  // end of the current line's data (comment cut off)
    std::size_t line_ = 0;
    bool at_end_ = false;
    std::uint64_t left_out_ = 0;  // reals a stream's lines left out (real_or)
    std::vector<RestClaim> claims_;
};

// Tracks the ids in the first column: reports the first one that is not the
// expected base + k once per file (Triangle ignores them; a jump usually
// means a hand-edited file lost or gained a line).
class IdChecker {
public:
    IdChecker(std::string_view kind, int base) : kind_(kind), base_(base) {}
    void check(TextReader& in, std::int64_t id, std::size_t k, const WarningSink& warn);
    // Stops further reports (the caller already warned about the numbering).
    void silence() noexcept { warned_ = true; }
    // The warning check() gives for `id` where `expected` was expected.
    static std::string jump_message(std::string_view kind, std::int64_t id, std::int64_t expected);

private:
    std::string_view kind_;
    int base_;
    bool warned_ = false;
};

}  // namespace gpdr::io::detail
