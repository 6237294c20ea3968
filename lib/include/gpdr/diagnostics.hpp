#pragma once
// Warnings travel from the library to the application through a sink: the
// library calls it, the application decides whether and how to print.

#include <cstddef>
#include <functional>
#include <string>

namespace gpdr {

struct Warning {
    std::string file;      // empty when not about a file
    std::size_t line = 0;  // 0 when not about one line
    std::string message;
};

using WarningSink = std::function<void(const Warning&)>;

// A sink that drops everything (for callers that do not care).
inline void ignore_warning(const Warning&) {}

}  // namespace gpdr
