#pragma once
// What a run is doing while it runs, for a program that shows progress (gpdr
// on a terminal).  The library only records it and never prints: a stage
// change or a finished file is one relaxed atomic store, and the count of
// vertices during refinement (kept by the refining threads in batches) is
// read only when the program asks, from a thread of its own, so recording
// costs nothing measurable.

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>

namespace gpdr {

class Progress {
public:
    // preparing: between the finished mesh and the first file (-C's check,
    // the arrays, -V's statistics).
    enum class Stage : int {
        starting,
        reading,
        triangulating,
        refining,
        preparing,
        writing,
        finished
    };

    struct Snapshot {
        Stage stage = Stage::starting;
        std::uint64_t input_vertices = 0;  // known once reading is done
        // The mesh's vertices so far while refining, and as refinement left
        // them afterwards (0 when there was none).
        std::uint64_t vertices = 0;
        std::uint64_t files_done = 0, files_total = 0;  // while writing
    };

    // Any thread, at any time.
    Snapshot snapshot() const {
        Snapshot s;
        s.stage = static_cast<Stage>(stage_.load(std::memory_order_relaxed));
        s.input_vertices = input_vertices_.load(std::memory_order_relaxed);
        s.files_done = files_done_.load(std::memory_order_relaxed);
        s.files_total = files_total_.load(std::memory_order_relaxed);
        const std::lock_guard lock(watch_mutex_);
        s.vertices = watched_ ? watched_() : last_count_;
        return s;
    }

    // ---- the library's side --------------------------------------------
    void enter(Stage stage) noexcept {
        stage_.store(static_cast<int>(stage), std::memory_order_relaxed);
    }
    void set_input_vertices(std::uint64_t n) noexcept {
        input_vertices_.store(n, std::memory_order_relaxed);
    }
    void set_files(std::uint64_t total) noexcept {
        files_done_.store(0, std::memory_order_relaxed);
        files_total_.store(total, std::memory_order_relaxed);
    }
    void file_done() noexcept { files_done_.fetch_add(1, std::memory_order_relaxed); }
    // While refinement runs, snapshot() asks `count` for the vertices so far
    // (it must be safe to call from another thread); unwatch() before what it
    // reads goes away.
    void watch(std::function<std::uint64_t()> count) {
        const std::lock_guard lock(watch_mutex_);
        watched_ = std::move(count);
    }
    void unwatch() noexcept {
        const std::lock_guard lock(watch_mutex_);
        if (watched_) last_count_ = watched_();
        watched_ = nullptr;
    }

private:
    std::atomic<int> stage_{0};
    std::atomic<std::uint64_t> input_vertices_{0};
    std::atomic<std::uint64_t> files_done_{0}, files_total_{0};
    mutable std::mutex watch_mutex_;
    std::function<std::uint64_t()> watched_;
    std::uint64_t last_count_ = 0;  // what watched_ said last, once unwatched
};

}  // namespace gpdr
