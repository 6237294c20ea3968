#pragma once
// The texts gpdr prints about itself: the short usage (no input named), the
// full help (-h, --help) and the version line (--version).

#include <string>

namespace gpdr::app {

std::string usage_text();
std::string help_text();
std::string version_text();

}  // namespace gpdr::app
