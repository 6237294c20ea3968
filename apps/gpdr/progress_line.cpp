// The terminal's progress line (progress_line.hpp).  It is drawn with a
// carriage return and "erase to the end of the line" (ESC [ K), which every
// terminal gpdr is likely to meet understands, and never wider than 79
// columns, so that it does not wrap.

#include "progress_line.hpp"

#include <algorithm>
#include <cstdlib>
#include <string_view>

#include <unistd.h>

#include <fmt/format.h>

namespace gpdr::app {
namespace {

// 1234 -> "1234", 1234567 -> "1.23M", in the style of the line.
std::string count(double n) {
    if (n >= 1e9) return fmt::format("{:.2f}G", n / 1e9);
    if (n >= 1e6) return fmt::format("{:.2f}M", n / 1e6);
    if (n >= 1e4) return fmt::format("{:.1f}k", n / 1e3);
    return fmt::format("{:.0f}", n);
}

}  // namespace

bool wants_progress_line(const Options& options, std::FILE* err) {
    // A "dumb" terminal (an editor's shell buffer) would print the escape
    // sequence as text.
    const char* term = std::getenv("TERM");
    if (term != nullptr && std::string_view(term) == "dumb") return false;
    return !options.quiet && ::isatty(::fileno(err)) == 1;
}

std::string progress_text(const Progress::Snapshot& s, double stage_seconds,
                          std::uint64_t stage_start_vertices) {
    const std::string time = fmt::format("{:.1f} s", stage_seconds);
    switch (s.stage) {
        case Progress::Stage::starting:
        case Progress::Stage::reading:
            return fmt::format("gpdr: reading, {}", time);
        case Progress::Stage::triangulating:
            return fmt::format("gpdr: triangulating {} vertices, {}",
                               count(double(s.input_vertices)), time);
        case Progress::Stage::refining: {
            // A triangulation has about two triangles per vertex: the count
            // is estimated from the vertices, which the refining threads
            // count in one atomic, rather than counted.
            const double triangles = 2.0 * double(s.vertices);
            const double added =
                2.0 * double(s.vertices - std::min(s.vertices, stage_start_vertices));
            const double rate = stage_seconds > 0 ? added / stage_seconds : 0;
            return fmt::format("gpdr: refining, about {} triangles ({} a second), {}",
                               count(triangles), count(rate), time);
        }
        case Progress::Stage::preparing:
            if (s.vertices == 0) return fmt::format("gpdr: preparing the output, {}", time);
            return fmt::format("gpdr: preparing the output, about {} triangles, {}",
                               count(2.0 * double(s.vertices)), time);
        case Progress::Stage::writing:
            if (s.files_total == 0) return fmt::format("gpdr: writing, {}", time);
            return fmt::format("gpdr: writing, {} of {} files done, {}", s.files_done,
                               s.files_total, time);
        case Progress::Stage::finished:
            break;
    }
    return {};
}

ProgressLine::ProgressLine(const Progress& progress, std::FILE* err,
                           std::chrono::milliseconds delay, std::chrono::milliseconds period)
    : progress_(progress), err_(err) {
    thread_ = std::thread([this, delay, period] { run(delay, period); });
}

ProgressLine::~ProgressLine() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
    const std::lock_guard lock(mutex_);
    erase();
}

void ProgressLine::erase() {
    if (!shown_) return;
    std::fputs("\r\x1b[K", err_);
    std::fflush(err_);
    shown_ = false;
}

void ProgressLine::interrupt(const std::function<void()>& print) {
    const std::lock_guard lock(mutex_);
    erase();
    print();
}

void ProgressLine::run(std::chrono::milliseconds delay, std::chrono::milliseconds period) {
    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    auto stage = Progress::Stage::starting;
    clock::time_point stage_start = start;
    std::uint64_t stage_start_vertices = 0;
    std::unique_lock lock(mutex_);
    for (;;) {
        if (wake_.wait_for(lock, period, [this] { return stop_; })) return;
        const Progress::Snapshot s = progress_.snapshot();
        const clock::time_point now = clock::now();
        if (s.stage != stage) {
            stage = s.stage;
            stage_start = now;
            stage_start_vertices = s.vertices;
        }
        if (now - start < delay || s.stage == Progress::Stage::finished) continue;
        std::string text = progress_text(
            s, std::chrono::duration<double>(now - stage_start).count(), stage_start_vertices);
        if (text.size() > 79) text.resize(79);
        fmt::print(err_, "\r{}\x1b[K", text);
        std::fflush(err_);
        shown_ = true;
    }
}

}  // namespace gpdr::app
