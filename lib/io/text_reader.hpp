#pragma once
// A cursor over one of Triangle's text files, mapped (or read) into memory
// at once.
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

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <gpdr/diagnostics.hpp>
#include <gpdr/errors.hpp>

namespace gpdr::io::detail {

// The bytes of one input file.  A regular file is mapped, not copied: its
// pages come from the page cache as the reader reaches them and can be
// dropped again behind it, so a large file costs its parsed values and not
// a second copy of its text.  Anything else (a pipe, a device) is read into
// memory, at most max_unsized_bytes of it: /dev/zero is an error, not a
// machine out of memory.
class FileText {
public:
    static constexpr std::size_t max_unsized_bytes = std::size_t{1} << 30;

    // InputError on line 0 if the file cannot be read, or is not regular
    // and longer than `cap`; `why_needed` is appended to the reason.
    FileText(const std::string& path, std::string_view why_needed,
             std::size_t cap = max_unsized_bytes);
    ~FileText();
    FileText(const FileText&) = delete;
    FileText& operator=(const FileText&) = delete;

    const char* data() const noexcept { return data_; }
    std::size_t size() const noexcept { return size_; }

private:
    const char* data_ = "";
    std::size_t size_ = 0;
    void* mapping_ = nullptr;  // munmap'ed by the destructor
    std::string owned_;        // the bytes of a file that is not mapped
};

class TextReader {
public:
    // Reads the whole file.  A missing or unreadable file is an InputError on
    // line 0; `why_needed`, when not empty, is appended to its reason (used by
    // .poly files that take their vertices from a .node file).
    explicit TextReader(std::string path, std::string_view why_needed = {});

    const std::string& path() const noexcept { return path_; }

    // Moves to the next line holding data.  Returns false at the end of the
    // file; line() is then the line after the last one.
    bool next_line();
    // The current line's number (1-based); after the end, last line + 1.
    std::size_t line() const noexcept { return line_; }
    // Bytes after the current line: what the rest of the file can hold.
    std::size_t remaining_bytes() const noexcept;
    // A hash of the whole file's bytes (content_hash.hpp), for the run stamp.
    std::uint64_t content_hash() const noexcept;

    // True when the current line has another field.
    bool has_field();
    // The next field as a signed integer.  Fields written as integral reals
    // ("3.0", "1e2") are accepted; "3.5" is not.  Missing or malformed: error
    // "<what> is missing" / "<what> '<token>' is not an integer".
    std::int64_t integer(std::string_view what);
    // The next field as a finite real.
    double real(std::string_view what);
    // Optional forms: the default when the line has no more fields.
    std::int64_t integer_or(std::int64_t fallback, std::string_view what);
    double real_or(double fallback, std::string_view what);

    // An element count from a header: not negative, and, if large, not more
    // entries than the rest of the file could hold at `min_bytes_per_entry`
    // bytes each (so nothing is ever reserved from an unchecked count).
    std::size_t count(std::string_view what, std::size_t min_bytes_per_entry = 2);

    [[noreturn]] void fail(std::string reason) const;
    [[noreturn]] void fail_at(std::size_t line, std::string reason) const;
    void warn(const WarningSink& sink, std::string message) const;

private:
    std::string_view token();  // the next field, without consuming it
    void skip_blanks() noexcept;

    std::string path_;
    FileText text_;
    const char* pos_ = nullptr;       // cursor inside the current line
    const char* data_end_ = nullptr;  // end of the current line's data (comment cut off)
    const char* next_ = nullptr;      // start of the next line
    std::size_t line_ = 0;
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

private:
    std::string_view kind_;
    int base_;
    bool warned_ = false;
};

}  // namespace gpdr::io::detail
