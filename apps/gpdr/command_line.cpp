// Reads argv.  Triangle's switches are clusters of letters with numbers glued
// on ("-pq30a.1"), which no option library parses the way Triangle does, so
// the app splits argv itself: clusters go to gpdr::parse_switches() in the
// library, and only the "--" long options go to CLI11, one at a time, so that
// a later setting replaces an earlier one whichever form it took.
#include "command_line.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <gpdr/errors.hpp>
#include <gpdr/file_names.hpp>
#include <gpdr/switches.hpp>

namespace gpdr::app {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

[[noreturn]] void unknown_long_option(std::string_view name) {
    std::string_view best;
    std::size_t best_distance = 4;  // more edits than this is no longer a typo
    for (const std::string_view candidate : long_option_names) {
        const bool prefix = name.size() >= 4 && candidate.substr(0, name.size()) == name;
        const std::size_t d = prefix ? 0 : edit_distance(name, candidate);
        if (d < best_distance) {
            best = candidate;
            best_distance = d;
        }
    }
    if (!best.empty())
        throw UsageError(fmt::format("unknown option {}; did you mean {}?", name, best));
    throw UsageError(fmt::format("unknown option {} (gpdr -h lists the options)", name));
}

// gpdr's long options, the names in long_option_names.  Each is parsed on its
// own (CLI11 wants its arguments reversed) and writes straight into the
// Options being built.
class LongOptions {
public:
    LongOptions(Options& options, CommandLine::Action& action) {
        app_.set_help_flag();  // -h is Triangle's; --help is declared below
        app_.allow_extras(false);
        app_.add_option_function<unsigned>(
            "--threads", [&options](const unsigned& n) { options.threads = n; },
            "worker threads (0: one per hardware thread)");
        app_.add_option_function<unsigned>(
            "--granularity", [&options](const unsigned& n) { options.granularity = n; },
            "quadtree granularity (0: built-in default)");
        app_.add_option_function<std::string>(
            "--placement",
            [&options](const std::string& name) { options.placement = parse_placement(name); },
            "Steiner point placement");
        app_.add_option_function<std::string>(
            "--unsuitable",
            [&options](const std::string& path) {
                if (path.empty())
                    throw UsageError("--unsuitable needs the path of a shared object");
                options.unsuitable_library = path;
                options.user_test = true;  // naming the test asks for it, as -u does
            },
            "shared object providing triunsuitable()");
        app_.add_flag_callback("--force", [&options] { options.force = true; });
        app_.add_flag_callback("--vtk", [&options] { options.write_vtk = true; });
        app_.add_flag_callback("--gmsh", [&options] { options.write_gmsh = true; });
        app_.add_flag_callback("--svg", [&options] { options.write_svg = true; });
        app_.add_flag_callback("--help", [&action] { action = CommandLine::Action::help; });
        app_.add_flag_callback("--version", [&action] { action = CommandLine::Action::version; });
    }

    // Parses the long option argv[i] (and its value); returns how many
    // arguments it used.
    int apply(int argc, const char* const* argv, int i) {
        const std::string_view arg = argv[i];
        const std::string_view name = arg.substr(0, arg.find('='));
        if (std::find(long_option_names.begin(), long_option_names.end(), name) ==
            long_option_names.end())
            unknown_long_option(name);
        const CLI::Option* option = app_.get_option_no_throw(std::string(name));
        if (option == nullptr)
            throw std::logic_error(fmt::format("{} is listed but not declared to CLI11", name));

        std::vector<std::string> group{std::string(arg)};
        const bool takes_value = option->get_items_expected_min() > 0;
        if (takes_value && name.size() == arg.size()) {
            if (i + 1 >= argc) throw UsageError(fmt::format("{} needs a value", name));
            group.emplace_back(argv[i + 1]);
        } else if (takes_value && arg.size() == name.size() + 1) {
            throw UsageError(fmt::format("{} needs a value after '='", name));
        }
        const int used = static_cast<int>(group.size());
        std::reverse(group.begin(), group.end());
        try {
            app_.parse(group);  // consumes `group`
        } catch (const CLI::ConversionError&) {
            const std::string_view value =
                used == 2 ? std::string_view(argv[i + 1]) : arg.substr(name.size() + 1);
            throw UsageError(fmt::format("{} needs a whole number, not '{}'", name, value));
        } catch (const CLI::ParseError& e) {
            const std::string_view what = e.what();
            if (what.find(name) != std::string_view::npos) throw UsageError(std::string(what));
            throw UsageError(fmt::format("{}: {}", name, what));
        }
        return used;
    }

private:
    CLI::App app_{"gpdr"};
};

}  // namespace

CommandLine parse_command_line(int argc, const char* const* argv) {
    CommandLine line;
    LongOptions long_options(line.options, line.action);
    bool names_only = false;  // after "--" every argument is a name
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (names_only || arg.empty() || arg.front() != '-') {
            line.options.input = std::string(arg);
        } else if (arg == "--") {
            names_only = true;
        } else if (arg.substr(0, 2) == "--") {
            i += long_options.apply(argc, argv, i) - 1;
        } else {
            parse_switches(arg, line.options);
            if (line.options.help) line.action = CommandLine::Action::help;
        }
        if (line.action != CommandLine::Action::run) return line;  // -h, --help, --version
    }
    if (line.options.input.empty()) {
        line.action = CommandLine::Action::usage;
        return line;
    }
    apply_input_name(line.options);
    // For the "# Generated by ..." line that ends every output file: the
    // command line as given, program name first, as Triangle writes it.
    for (int i = 0; i < argc; ++i) {
        if (i > 0) line.options.command += ' ';
        line.options.command += argv[i];
    }
    return line;
}

}  // namespace gpdr::app
