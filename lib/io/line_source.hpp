#pragma once
// The lines of one input file, in order, whatever kind of file it is.
//
// A regular file is mapped, not copied: its pages come from the page cache
// as the reader reaches them and can be dropped again behind it, so a large
// file costs its parsed values and not a second copy of its text.  Anything
// else (a pipe, a fifo, a device) is read as its bytes arrive, into a buffer
// that holds the current line and what the last read brought after it, so
// that memory stays small however long the input runs: /dev/zero is
// refused at its first line after one read, /dev/urandom within its first
// few lines.
//
// Every line is checked as it is reached, the same way for both kinds, so a
// file gives the same lines and the same errors from a pipe as from disk:
//   - a NUL byte is an error (no text file of Triangle's holds one; it is
//     the first sign of a binary file or a device);
//   - a line longer than max_line_bytes is an error, so that an endless
//     comment or run of blanks cannot grow the buffer without bound.
// Within one line the first offence in byte order is reported: a NUL byte
// among its first max_line_bytes bytes, else its length.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>

#include "io/content_hash.hpp"

namespace gpdr::io::detail {

class LineSource {
public:
    struct Borrowed {};  // tag of the constructor over bytes in memory

    static constexpr std::size_t max_line_bytes = std::size_t{1} << 20;
    // The least one read() asks a stream for: the buffer holds the current
    // line and this much room behind it.
    static constexpr std::size_t read_bytes = std::size_t{1} << 16;

    // InputError on line 0 if the file cannot be opened or is a folder;
    // `why_needed`, when not empty, is appended to its reason.
    LineSource(const std::string& path, std::string_view why_needed);
    // The lines of `bytes`, a piece of a mapped file that starts at a line
    // start (one slice of a file read on several threads): not owned,
    // checked like a regular file's, numbered from 1.
    LineSource(const std::string& path, std::string_view bytes, Borrowed);
    ~LineSource();
    LineSource(const LineSource&) = delete;
    LineSource& operator=(const LineSource&) = delete;

    // Moves to the next line.  False at the end of the file (line() then
    // stays the last line's number).  InputError on the offending line for
    // a NUL byte or an overlong line, on line 0 if a read fails.
    bool next_line() {
        // The common case, inline: the next line whole in memory, not too
        // long, and already searched for NUL bytes (one search covers many
        // lines).  Anything else takes the general path.
        const auto* newline =
            static_cast<const char*>(std::memchr(next_, '\n', std::size_t(end_ - next_)));
        if (newline == nullptr || std::size_t(newline - next_) > max_line_bytes ||
            (nul_ != nullptr ? nul_ < newline : nul_scanned_ <= newline))
            return next_line_slowly();
        ++line_;
        line_begin_ = next_;
        line_end_ = newline;
        next_ = newline_scanned_ = newline + 1;
        return true;
    }
    // The current line, without its '\n'; valid until the next call.
    std::string_view text() const noexcept {
        return {line_begin_, std::size_t(line_end_ - line_begin_)};
    }
    // The current line's number (1-based; 0 before the first).
    std::size_t line() const noexcept { return line_; }

    // Whether the file's size was known when it was opened (a regular file).
    bool sized() const noexcept { return !stream_; }
    // The bytes after the current line that are in memory: the whole rest
    // of a regular file; of a stream, what has been read but not reached.
    std::size_t bytes_at_hand() const noexcept { return std::size_t(end_ - next_); }
    // The offset in the file of the byte after the current line.
    std::uint64_t offset() const noexcept { return dropped_ + std::uint64_t(next_ - base_); }
    // The bytes read so far (a regular file: its size).
    std::uint64_t bytes_read() const noexcept { return dropped_ + std::uint64_t(end_ - base_); }

    // Reaches the end of the file, checking every line left as next_line()
    // does (a stream is read to its end), and returns the hash of all of the
    // file's bytes: hash_bytes() over the file, for either kind (or the
    // value given to adopt_hash()).
    std::uint64_t finish();

    // For a regular file: all of its bytes, mapped.
    std::string_view bytes() const noexcept { return {base_, std::size_t(end_ - base_)}; }
    // For a regular file: goes on as if line `line` had just been read and
    // ended before byte `offset` (the lines in between were read and checked
    // elsewhere: by the threads of a parallel read).
    void resume_at(std::uint64_t offset, std::size_t line) noexcept;
    // For a regular file: the hash of its bytes, computed elsewhere (on
    // another thread, while this one parsed), for finish() to return.
    void adopt_hash(std::uint64_t hash) noexcept {
        adopted_hash_ = hash;
        hash_adopted_ = true;
    }

private:
    // next_line() for every case: a line cut by the end of a stream's
    // buffer, the last line, a line to check for NUL bytes or length.
    bool next_line_slowly();
    [[noreturn]] void fail_at(std::size_t line, std::string reason) const;
    // Checks the bytes [b, e) of line `line`; `e` may be the end of what a
    // stream has read so far.
    void check(const char* b, const char* e, std::size_t line);
    // The first NUL byte before `to` and at or after the next line, if any.
    const char* first_nul_before(const char* to) noexcept;
    // Makes room behind the current partial line and reads more of a
    // stream; sets eof_ when it ends.
    void refill();

    std::string path_;
    bool stream_ = false;
    int fd_ = -1;              // a stream's descriptor, closed by the destructor
    void* mapping_ = nullptr;  // a regular file's bytes, unmapped by the destructor
    std::size_t mapping_size_ = 0;
    std::unique_ptr<char[]> buffer_;  // a stream's bytes
    std::size_t capacity_ = 0;

    const char* base_ = "";     // the mapping or the buffer
    const char* end_ = base_;   // the end of the bytes in memory
    const char* next_ = base_;  // the start of the line after the current one
    const char* line_begin_ = base_;
    const char* line_end_ = base_;
    const char* newline_scanned_ = base_;  // no '\n' in [next_, newline_scanned_)
    const char* nul_scanned_ = base_;      // [next_, nul_scanned_) searched for NUL...
    const char* nul_ = nullptr;            // ... and this is the first one found there
    bool eof_ = true;                      // no more bytes will come
    std::uint64_t dropped_ = 0;            // a stream's bytes consumed and dropped from the buffer
    std::size_t line_ = 0;
    ContentHasher hasher_;  // a stream's bytes, as they are read
    std::uint64_t adopted_hash_ = 0;
    bool hash_adopted_ = false;
};

}  // namespace gpdr::io::detail
