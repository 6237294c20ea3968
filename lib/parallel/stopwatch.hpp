#pragma once
// Wall-clock seconds, for what -V reports: the stages' times and each
// thread's.  The one timer of the library.

#include <chrono>

namespace gpdr::parallel {

class Stopwatch {
public:
    // Seconds since the last lap (or since construction); starts a new lap.
    double lap() {
        const Clock::time_point now = Clock::now();
        const double s = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        return s;
    }
    // Seconds since the last lap, which goes on.
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - last_).count(); }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point last_ = Clock::now();
};

}  // namespace gpdr::parallel
