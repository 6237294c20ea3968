#pragma once
// The progress line gpdr shows on a terminal during a long run: one line on
// standard error, rewritten in place a few times a second with what the run
// is doing (reading, triangulating, refining with the triangles so far and
// their rate, preparing the output, writing with the files done), and
// erased when the run ends.
// Only a terminal gets it (never a pipe or a log file), never with -Q, and
// only once the run has taken about a second, so short runs print nothing
// more than before.

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

#include <gpdr/options.hpp>
#include <gpdr/progress.hpp>

namespace gpdr::app {

// Whether a run with these options, writing to `err`, shows progress.
bool wants_progress_line(const Options& options, std::FILE* err);

// The text of the line for a snapshot, `stage_seconds` into its stage,
// with `stage_start_vertices` the vertices when the stage began.
std::string progress_text(const Progress::Snapshot& s, double stage_seconds,
                          std::uint64_t stage_start_vertices);

class ProgressLine {
public:
    // Starts the thread that draws `progress` on `err` once `delay` has
    // passed, every `period`.
    ProgressLine(const Progress& progress, std::FILE* err,
                 std::chrono::milliseconds delay = std::chrono::milliseconds(1000),
                 std::chrono::milliseconds period = std::chrono::milliseconds(200));
    // Stops the thread and erases the line.
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // Runs `print` (which writes whole lines on `err`, a warning) with the
    // progress line erased first, so the two do not mix; the line comes
    // back at the next update.
    void interrupt(const std::function<void()>& print);

private:
    void run(std::chrono::milliseconds delay, std::chrono::milliseconds period);
    void erase();  // with mutex_ held

    const Progress& progress_;
    std::FILE* err_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    bool shown_ = false;
    std::thread thread_;
};

}  // namespace gpdr::app
