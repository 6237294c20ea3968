// FormatThreads: pieces of a file's text formatted on several threads and
// written in order (format_threads.hpp).  One lock guards the bookkeeping of
// every file; it is held only to claim a piece (and, for data read in order,
// to read that piece's part of it) and to mark one finished, a few hundred
// times per file, never while a piece is formatted or written.

#include "io/format_threads.hpp"

#include <algorithm>

namespace gpdr::io {

// One file whose pieces are being formatted: it lives on its writer's
// stack, listed in jobs_ until no other thread can reach it.
struct FormatThreads::Job {
    const Pieces* pieces = nullptr;
    std::size_t claimed = 0;               // pieces handed out (the next one to claim)
    std::size_t written = 0;               // pieces appended to the file
    std::size_t in_flight = 0;             // pieces being formatted now
    std::vector<fmt::memory_buffer> text;  // per slot: a piece's text
    std::vector<char> done;                // per slot: formatted, not yet written
    std::exception_ptr failure;

    bool claimable(std::size_t window) const noexcept {
        return !failure && claimed < pieces->count && claimed < written + window;
    }
};

FormatThreads::FormatThreads(unsigned threads)
    : threads_(std::max(1u, threads)), window_(std::size_t{threads_} + 2) {}

void FormatThreads::file_done() {
    const std::lock_guard lock(mutex_);
    ++files_done_;
    changed_.notify_all();
}

bool FormatThreads::format_one(Job& job, std::unique_lock<std::mutex>& lock) {
    if (!job.claimable(window_)) return false;
    const std::size_t piece = job.claimed++;
    const std::size_t slot = piece % window_;
    ++job.in_flight;
    try {
        // Data read in order is read here, with the lock held: the claims,
        // and so the reads, come in piece order.
        if (job.pieces->prepare) job.pieces->prepare(piece, slot);
        lock.unlock();
        fmt::memory_buffer& text = job.text[slot];
        text.clear();
        job.pieces->format(piece, slot, text);
        lock.lock();
        job.done[slot] = 1;
    } catch (...) {
        if (!lock.owns_lock()) lock.lock();
        if (!job.failure) job.failure = std::current_exception();
    }
    --job.in_flight;
    changed_.notify_all();
    return true;
}

void FormatThreads::help() {
    std::unique_lock lock(mutex_);
    while (files_done_ < files_) {
        const auto open = std::find_if(jobs_.begin(), jobs_.end(),
                                       [this](const Job* j) { return j->claimable(window_); });
        if (open == jobs_.end())
            changed_.wait(lock);
        else
            format_one(**open, lock);
    }
}

void FormatThreads::write_pieces(OutputTransaction::File& file, const Pieces& pieces) {
    run(&file, pieces);
}

void FormatThreads::run_pieces(const Pieces& pieces) { run(nullptr, pieces); }

void FormatThreads::run(OutputTransaction::File* file, const Pieces& pieces) {
    Job job;
    job.pieces = &pieces;
    job.text.resize(window_);
    job.done.assign(window_, 0);
    std::unique_lock lock(mutex_);
    jobs_.push_back(&job);
    changed_.notify_all();
    while (job.written < pieces.count && !job.failure) {
        const std::size_t slot = job.written % window_;
        if (job.done[slot] != 0) {
            // No other thread touches this slot until `written` passes it.
            lock.unlock();
            try {
                if (file != nullptr) file->append(job.text[slot].data(), job.text[slot].size());
            } catch (...) {
                lock.lock();
                job.failure = std::current_exception();
                break;
            }
            lock.lock();
            job.done[slot] = 0;
            ++job.written;
            changed_.notify_all();
        } else if (!format_one(job, lock)) {
            changed_.wait(lock);
        }
    }
    // Once unlisted, with no piece in flight, no other thread can reach the job.
    changed_.wait(lock, [&job] { return job.in_flight == 0; });
    jobs_.erase(std::find(jobs_.begin(), jobs_.end(), &job));
    if (job.failure) std::rethrow_exception(job.failure);
}

}  // namespace gpdr::io
