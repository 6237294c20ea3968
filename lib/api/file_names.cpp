// Input and output file names, as Triangle 1.6 derives them from the one
// name on its command line (its documentation, "Command line switches" and
// -I; its parsecommandline() behaviour for the details below).
//
// Differences from Triangle's C code that cannot change a name Triangle
// would produce: the iteration number is incremented as a decimal string,
// so a number past 2^31 does not overflow, and leading zeros are dropped as
// Triangle's printf("%d") drops them.
#include <gpdr/file_names.hpp>

#include <string>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

namespace gpdr {
namespace {

bool strip_suffix(std::string& name, std::string_view suffix) {
    if (name.size() < suffix.size() ||
        std::string_view(name).substr(name.size() - suffix.size()) != suffix)
        return false;
    name.resize(name.size() - suffix.size());
    return true;
}

// "0099" -> "100": digits only, no sign.
std::string decimal_successor(std::string_view digits) {
    std::size_t first = digits.find_first_not_of('0');
    std::string n(first == std::string_view::npos ? std::string_view("0") : digits.substr(first));
    for (std::size_t i = n.size(); i-- > 0;) {
        if (n[i] != '9') {
            ++n[i];
            return n;
        }
        n[i] = '0';
    }
    return "1" + n;
}

void check_not_refining_with_I(const Options& options, const InputName& name) {
    if (options.no_iteration_numbers && (options.refine || name.refine))
        throw UsageError(
            "-I cannot be used when refining (-r, or an .ele or .area input): the output "
            "files would replace the mesh being refined");
}

}  // namespace

InputName split_input_name(std::string_view input) {
    InputName name;
    name.base = std::string(input);
    // Triangle's order; each test looks at what the previous one left.
    strip_suffix(name.base, ".node");
    if (strip_suffix(name.base, ".poly")) name.poly = true;
    if (strip_suffix(name.base, ".ele")) name.refine = true;
    if (strip_suffix(name.base, ".area")) {
        name.refine = true;
        name.regional_area = true;
    }
    return name;
}

std::string next_output_base(std::string_view input_base) {
    // The last '.' that is neither the first nor the last character.
    std::size_t dot = std::string_view::npos;
    for (std::size_t i = 1; i + 1 < input_base.size(); ++i)
        if (input_base[i] == '.') dot = i;
    if (dot != std::string_view::npos) {
        const std::string_view tail = input_base.substr(dot + 1);
        if (tail.find_first_not_of("0123456789") == std::string_view::npos)
            return fmt::format("{}{}", input_base.substr(0, dot + 1), decimal_successor(tail));
    }
    return fmt::format("{}.1", input_base);
}

void apply_input_name(Options& options) {
    if (options.input.empty()) throw UsageError("no input file named");
    const InputName name = split_input_name(options.input);
    check_not_refining_with_I(options, name);
    options.poly = options.poly || name.poly;
    options.refine = options.refine || name.refine;
    options.regional_area = options.regional_area || name.regional_area;
}

FileNames file_names(const Options& options) {
    if (options.input.empty()) throw UsageError("no input file named");
    const InputName name = split_input_name(options.input);
    check_not_refining_with_I(options, name);

    FileNames f;
    f.input_base = name.base;
    f.output_base = options.no_iteration_numbers ? name.base : next_output_base(name.base);

    f.in_node = f.input_base + ".node";
    f.in_poly = f.input_base + ".poly";
    f.in_ele = f.input_base + ".ele";
    f.in_area = f.input_base + ".area";

    const std::string& out = f.output_base;
    f.out_node = out + ".node";
    f.out_ele = out + ".ele";
    if (!options.no_iteration_numbers) f.out_poly = out + ".poly";
    f.out_edge = out + ".edge";
    f.out_neigh = out + ".neigh";
    f.out_v_node = out + ".v.node";
    f.out_v_edge = out + ".v.edge";
    f.out_off = out + ".off";
    f.out_vtu = out + ".vtu";
    f.out_msh = out + ".msh";
    f.out_svg = out + ".svg";
    return f;
}

}  // namespace gpdr
