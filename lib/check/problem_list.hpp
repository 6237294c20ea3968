#pragma once
// The problems a check finds, as sentences, up to a limit; past it only
// counted, and finish() ends the list with "... and N more problems".
// Shared by the invariant checker (checker.cpp) and the check against the
// input (input_check.cpp).

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace gpdr::mesh {

class ProblemList {
public:
    explicit ProblemList(std::size_t limit) : limit_(limit) {}

    template <class... Args>
    void add(fmt::format_string<Args...> format, Args&&... args) {
        if (problems_.size() < limit_)
            problems_.push_back(fmt::format(format, std::forward<Args>(args)...));
        else
            ++dropped_;
    }

    // Appends another list's problems, as if they had been added here.
    void take(ProblemList& other) {
        for (auto& p : other.problems_) {
            if (problems_.size() < limit_)
                problems_.push_back(std::move(p));
            else
                ++dropped_;
        }
        dropped_ += other.dropped_;
    }

    std::vector<std::string> finish() {
        if (dropped_ > 0) problems_.push_back(fmt::format("... and {} more problems", dropped_));
        return std::move(problems_);
    }

private:
    std::size_t limit_;
    std::size_t dropped_ = 0;
    std::vector<std::string> problems_;
};

}  // namespace gpdr::mesh
