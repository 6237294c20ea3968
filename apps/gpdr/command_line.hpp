#pragma once
// argv -> what gpdr should do: Triangle's switch clusters (lib's
// parse_switches), gpdr's long options (CLI11), and the input name.

#include <gpdr/options.hpp>

namespace gpdr::app {

struct CommandLine {
    enum class Action {
        run,      // mesh options.input
        usage,    // no input named: the short usage, exit status 0 (as Triangle)
        help,     // -h or --help: the full help, exit status 0
        version,  // --version
    };
    Action action = Action::run;
    Options options;  // with the switches the input's extension implies applied
};

// Reads argv in order.  An argument starting with "--" is a long option (its
// value is the next argument unless written --name=value); any other
// argument starting with '-' is a cluster of switch letters; everything else,
// and everything after a lone "--", names the input (the last one wins).
// -h / --help and --version stop the reading at once, as Triangle's -h does.
// Throws gpdr::UsageError for anything it cannot understand.
CommandLine parse_command_line(int argc, const char* const* argv);

}  // namespace gpdr::app
