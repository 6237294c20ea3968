#pragma once
// Formatting one file's lines on several threads.  A large file's lines are
// cut into pieces of a fixed number of lines; any thread of a FormatThreads
// formats a piece into a buffer of its own, and the thread writing the file
// appends the finished pieces in order.  The text of a line depends only on
// the line, so the bytes are those one thread writes, whatever the timing.
//
// The threads are shared by the files of one output stage: a thread that
// has no file left to start (write_outputs.cpp) calls help() and formats
// pieces of the files still being written, so -jN keeps N threads busy
// until the last file is done, and never runs more than N.  Only a window of
// pieces past the last one written may be formatted ahead, which bounds the
// memory to a few pieces per thread.

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include <fmt/format.h>
#include <gpdr/io.hpp>

#include "io/output_file.hpp"

namespace gpdr::io {

class FormatThreads {
public:
    // `threads` in all, the writers' own included.
    explicit FormatThreads(unsigned threads);
    FormatThreads(const FormatThreads&) = delete;
    FormatThreads& operator=(const FormatThreads&) = delete;

    unsigned threads() const noexcept { return threads_; }
    // Pieces formatted ahead of the one written next: what a writer
    // prepares per-piece storage for.
    std::size_t window() const noexcept { return window_; }

    // help() returns once `files` writers have called file_done(); set
    // before any thread helps.
    void expect_files(std::size_t files) noexcept { files_ = files; }
    // A writer has returned (written its file or failed).
    void file_done();
    // Formats pieces of the files being written until every file is done.
    void help();

    // How one file's pieces are made.  prepare(piece, slot) runs on one
    // thread at a time, in piece order (for data that can only be read in
    // order, such as an EleSource; it may be empty); format(piece, slot,
    // text) then runs on any thread, for different pieces at once.  `slot`
    // is piece % window(): storage prepare fills for format to read.
    struct Pieces {
        std::size_t count = 0;
        std::function<void(std::size_t piece, std::size_t slot)> prepare;
        std::function<void(std::size_t piece, std::size_t slot, fmt::memory_buffer& text)> format;
    };
    // Formats every piece (this thread too) and appends them to `file` in
    // order; returns when all are written, rethrowing the first failure.
    void write_pieces(OutputTransaction::File& file, const Pieces& pieces);
    // The same for work whose pieces write no text (a pass over a mesh
    // whose results each piece keeps): returns when every piece is done.
    void run_pieces(const Pieces& pieces);

private:
    struct Job;
    // write_pieces() into `file`, or run_pieces() when it is null.
    void run(OutputTransaction::File* file, const Pieces& pieces);
    // With the lock held: claims and prepares the next piece of `job` if
    // the window allows, then formats it without the lock.  False if there
    // was nothing to claim.
    bool format_one(Job& job, std::unique_lock<std::mutex>& lock);

    unsigned threads_;
    std::size_t window_;
    std::size_t files_ = 0;
    std::size_t files_done_ = 0;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::vector<Job*> jobs_;  // the files being written, in the order they started
};

namespace detail {

// Lines per piece: large enough that claiming one costs nothing beside
// formatting it, small enough that two threads share a file of a few
// hundred thousand lines.
inline constexpr std::size_t lines_per_piece = 16384;

// Writes `count` lines, line(i, text) appending line i to `text`: on the
// threads of `threads` when there are (pieces in order), else straight into
// the file's buffer on this thread.
template <class Line>
void put_lines(OutputTransaction::File& file, FormatThreads* threads, std::size_t count,
               const Line& line) {
    if (threads == nullptr || threads->threads() < 2 || count <= lines_per_piece) {
        auto& text = file.buffer();
        for (std::size_t i = 0; i < count; ++i) {
            line(i, text);
            file.flush_if_full();
        }
        return;
    }
    FormatThreads::Pieces pieces;
    pieces.count = (count + lines_per_piece - 1) / lines_per_piece;
    pieces.format = [&](std::size_t piece, std::size_t, fmt::memory_buffer& text) {
        const std::size_t end = std::min(count, (piece + 1) * lines_per_piece);
        for (std::size_t i = piece * lines_per_piece; i < end; ++i) line(i, text);
    };
    threads->write_pieces(file, pieces);
}

}  // namespace detail
}  // namespace gpdr::io
