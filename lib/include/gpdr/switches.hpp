#pragma once
// Triangle's switch letters: one command-line argument such as "-pq30a0.1"
// read into gpdr::Options, left to right, as Triangle 1.6's parsecommandline()
// reads it, with the deviations gpdr documents (README, man page): an
// unknown letter is an error, q/a numbers may carry an exponent, and -jN,
// -gN, -PN are gpdr's own numbered switches.

#include <array>
#include <string_view>

#include <gpdr/options.hpp>

namespace gpdr {

// Who wrote the switches: a command line (the gpdr program), or a program
// calling Triangle's library (triangulate(), capi/), which reads them as
// Triangle's library does where the two differ:
//   - a character that is not a switch is skipped, not an error ("Qz{a0.2}",
//     a leading '-');
//   - h, H and ? do nothing;
//   - L means D, as in Triangle's parser;
//   - w and W (Triangle's weighted triangulations) are errors naming them.
// Numbers are read the same way in both: locale-independently, with the
// program's exponents and range checks.
enum class SwitchDialect { program, library };

// Applies one cluster of switch letters, with or without its leading '-', to
// `options`.  Several clusters apply in turn ("-p" then "-q30" equals
// "-pq30"); a later value replaces an earlier one.  Stops at 'h' (also 'H'
// or '?') after setting options.help, as Triangle prints its help at once.
// Throws UsageError naming the cluster for an unknown letter, a malformed
// number, or a value out of range (-q outside [0, 60), -a not above zero,
// -P other than 0, 1, 2).
void parse_switches(std::string_view cluster, Options& options,
                    SwitchDialect dialect = SwitchDialect::program);

// gpdr's long options, the only "--name" arguments the program accepts (it
// declares each to its option parser, apps/gpdr/command_line.cpp); a
// cluster that looks like one of them typed with one dash ("-threads") gets
// it suggested.  gpdr -h and man/gpdr.1 document each one
// (tests/cli/switch_reference_test.cpp).
inline constexpr std::array<std::string_view, 10> long_option_names = {
    "--threads", "--granularity", "--placement", "--unsuitable", "--force",
    "--vtk",     "--gmsh",        "--svg",       "--help",       "--version"};

// Long options gpdr refuses with a reason of their own rather than as
// unknown ones.
struct RefusedOption {
    std::string_view name;
    std::string_view reason;
};
inline constexpr std::array<RefusedOption, 1> refused_long_options = {{
    {"--nondeterministic",
     "--nondeterministic: gpdr has no schedule that depends on the threads' timing; it writes "
     "the same files for every thread count from 2 up (and -j1 refines on one thread, in "
     "Triangle's order)"},
}};

// A placement strategy by name ("circumcentre", "off-centre",
// "optimisation", American spellings too) or number ("0", "1", "2"), as
// --placement takes it.  Throws UsageError for anything else.
Placement parse_placement(std::string_view name);

// The placement's name as parse_placement() reads it and the help prints it.
std::string_view placement_name(Placement placement);

}  // namespace gpdr
