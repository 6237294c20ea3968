// Reads one cluster of Triangle switch letters into Options.
//
// Follows Triangle 1.6's parsecommandline() (as its documentation and
// behaviour describe it): letters are read left to right; q and a take the
// number that follows at once, S a run of digits, o only the digit 2; Y and V
// count.  Where gpdr deliberately differs (man/gpdr.1, DEVIATIONS FROM
// TRIANGLE):
//   - an unknown letter is an error, not silently skipped, because a typo that
//     goes unnoticed gives a wrong mesh;
//   - a number after q or a may carry an exponent when the 'e' is followed by a
//     digit or by a sign and a digit ("-a1e-5"), otherwise 'e' is the switch;
//   - a malformed number ("-q3.2.1") or an out-of-range one ("-q70", "-a0",
//     "-a-1") is an error instead of a silent misreading;
//   - j, g and P followed at once by digits are gpdr's thread count,
//     granularity and placement; bare, they keep Triangle's meaning.
// Triangle's own `quality` flag is also raised by -a, -u and -D (and an
// .area input): they all ask for refinement.  Options records only what was
// typed (quality means -q, with its angle), so whoever runs the job derives
// "refine at all" from quality, area_limit, regional_area, user_test and
// conforming_delaunay together.
#include <gpdr/switches.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string>

#include <fmt/format.h>

#include <gpdr/errors.hpp>

namespace gpdr {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_sign(char c) { return c == '-' || c == '+'; }

// Every letter parse_switches() knows, for suggestions.
constexpr std::string_view known_letters = "prqauAcDjevngBPNEIOXzoYSiFlsCQVh";

// Reads one cluster; `text` has no leading '-', `shown` is the cluster as
// the user typed it, for messages.
class ClusterReader {
public:
    ClusterReader(std::string_view text, std::string_view shown, Options& options,
                  SwitchDialect dialect)
        : text_(text), shown_(shown), options_(options), dialect_(dialect) {}

    void run() {
        while (pos_ < text_.size()) {
            letter_start_ = pos_;
            const char letter = text_[pos_++];
            if (!apply(letter)) return;  // 'h': Triangle stops there
        }
    }

private:
    // Applies one letter (and the number after it); false to stop reading.
    bool apply(char letter) {
        switch (letter) {
            case 'p':
                options_.poly = true;
                break;
            case 'r':
                options_.refine = true;
                break;
            case 'q':
                read_min_angle();
                break;
            case 'a':
                read_area();
                break;
            case 'u':
                options_.user_test = true;
                break;
            case 'A':
                options_.region_attributes = true;
                break;
            case 'c':
                options_.convex_hull = true;
                break;
            case 'D':
                options_.conforming_delaunay = true;
                break;
            case 'j':
                if (digit_follows())
                    options_.threads = read_count<unsigned>('j');
                else
                    options_.jettison = true;
                break;
            case 'e':
                options_.write_edges = true;
                break;
            case 'v':
                options_.write_voronoi = true;
                break;
            case 'n':
                options_.write_neighbours = true;
                break;
            case 'g':
                if (digit_follows())
                    options_.granularity = read_count<unsigned>('g');
                else
                    options_.write_off = true;
                break;
            case 'B':
                options_.no_boundary_markers = true;
                break;
            case 'P':
                if (digit_follows())
                    read_placement();
                else
                    options_.no_poly_output = true;
                break;
            case 'N':
                options_.no_node_output = true;
                break;
            case 'E':
                options_.no_ele_output = true;
                break;
            case 'I':
                options_.no_iteration_numbers = true;
                break;
            case 'O':
                options_.ignore_holes = true;
                break;
            case 'X':
                options_.no_exact = true;
                break;
            case 'z':
                options_.zero_based = true;
                break;
            case 'o':
                read_order();
                break;
            // Triangle counts every Y but only tells 1 from "more than 1".
            case 'Y':
                options_.no_segment_splitting = std::min(options_.no_segment_splitting + 1, 2);
                break;
            case 'S':
                options_.steiner_limit = true;
                options_.max_steiner = digit_follows() ? read_count<std::uint64_t>('S') : 0;
                break;
            case 'i':
                options_.incremental = true;
                break;
            case 'F':
                options_.sweepline = true;
                break;
            case 'l':
                options_.vertical_cuts = true;
                break;
            case 's':
                options_.split_segments = true;
                break;
            case 'C':
                options_.check = true;
                break;
            case 'Q':
                options_.quiet = true;
                break;
            case 'V':
                ++options_.verbosity;
                break;
            case 'h':
            case 'H':
            case '?':
                if (library()) break;  // Triangle's library has no help to print
                options_.help = true;
                return false;
            case 'w':
            case 'W':
                if (library())
                    fail(fmt::format("-{}", letter), ": ",
                         "Triangle's weighted Delaunay triangulations are not supported");
                unknown(letter);
            case 'L':
                // Triangle's parser takes L for D; its library users may rely on it.
                if (!library()) unknown(letter);
                options_.conforming_delaunay = true;
                break;
            default:
                // Triangle's library skips what it does not know (the braces of
                // "Qz{a0.2}", a leading '-'); the program reports it.
                if (!library()) unknown(letter);
        }
        return true;
    }

    bool library() const { return dialect_ == SwitchDialect::library; }

    bool digit_follows() const { return pos_ < text_.size() && is_digit(text_[pos_]); }
    bool char_is(std::size_t at, bool (*test)(char)) const {
        return at < text_.size() && test(text_[at]);
    }
    bool digit_or_dot_at(std::size_t at) const {
        return at < text_.size() && (is_digit(text_[at]) || text_[at] == '.');
    }

    // The real number that starts at pos_, consumed: Triangle's run of digits
    // and dots, with gpdr's optional exponent, and a sign that Triangle would
    // not read (taken only so that "-a-1" gets a message about the value).
    std::string_view take_real() {
        const std::size_t start = pos_;
        std::size_t i = pos_;
        if (char_is(i, is_sign) && digit_or_dot_at(i + 1)) ++i;
        while (digit_or_dot_at(i)) ++i;
        if (i < text_.size() && text_[i] == 'e' &&
            (char_is(i + 1, is_digit) || (char_is(i + 1, is_sign) && char_is(i + 2, is_digit)))) {
            i += is_sign(text_[i + 1]) ? 2 : 1;
            while (char_is(i, is_digit)) ++i;
        }
        pos_ = i;
        return text_.substr(start, i - start);
    }

    double to_double(char letter, std::string_view number) const {
        std::string_view digits = number;
        if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
        double value = 0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (ec == std::errc::result_out_of_range)
            fail(fmt::format("-{}{}", letter, number), ": ", "the number is out of range");
        if (ec != std::errc{} || end != digits.data() + digits.size())
            fail(fmt::format("-{}{}", letter, number), ": ",
                 fmt::format("'{}' is not a number", number));
        return value;
    }

    void read_min_angle() {
        options_.quality = true;
        if (!(digit_or_dot_at(pos_) || (char_is(pos_, is_sign) && digit_or_dot_at(pos_ + 1)))) {
            options_.min_angle = 20.0;  // Triangle's default for a bare q
            return;
        }
        const std::string_view number = take_real();
        const double angle = to_double('q', number);
        if (!(angle >= 0.0 && angle < 60.0))
            fail(fmt::format("-q{}", number), ": ",
                 "the minimum angle must be at least 0 and below 60 degrees (no triangle has "
                 "all its angles above 60)");
        options_.min_angle = angle;
    }

    void read_area() {
        if (!(digit_or_dot_at(pos_) || (char_is(pos_, is_sign) && digit_or_dot_at(pos_ + 1)))) {
            options_.regional_area = true;  // bare a: bounds from .poly regions or .area
            return;
        }
        const std::string_view number = take_real();
        const double area = to_double('a', number);
        if (!(area > 0.0))
            fail(fmt::format("-a{}", number), ": ", "the maximum area must be greater than zero");
        options_.area_limit = true;
        options_.max_area = area;
    }

    template <class Unsigned>
    Unsigned read_count(char letter) {
        const std::size_t start = pos_;
        while (char_is(pos_, is_digit)) ++pos_;
        const std::string_view number = text_.substr(start, pos_ - start);
        Unsigned value = 0;
        const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
        if (ec != std::errc{} || end != number.data() + number.size())
            fail(fmt::format("-{}{}", letter, number), ": ",
                 fmt::format("the number is too large (at most {})",
                             std::numeric_limits<Unsigned>::max()));
        return value;
    }

    void read_placement() {
        const std::size_t start = pos_;
        const unsigned value = read_count<unsigned>('P');
        if (value > 2)
            fail(fmt::format("-P{}", text_.substr(start, pos_ - start)), ": ",
                 "the placement must be 0 (circumcentre), 1 (off-centre) or 2 (optimisation)");
        options_.placement = static_cast<Placement>(value);
    }

    void read_order() {
        if (pos_ < text_.size() && text_[pos_] == '2') {
            ++pos_;
            options_.order = 2;
            return;
        }
        fail("-o", ": ",
             "write -o2 for six-node (second-order) triangles; there is no other order");
    }

    [[noreturn]] void unknown(char letter) const {
        const unsigned char u = static_cast<unsigned char>(letter);
        const char other_case = std::isupper(u) ? static_cast<char>(std::tolower(u))
                                                : static_cast<char>(std::toupper(u));
        std::string advice = "gpdr -h lists the switches";
        if (is_digit(letter)) {
            advice =
                "a number must follow its switch with no space (q, a, S, o2, j, g, P take "
                "numbers)";
        } else if (letter == '-') {
            advice = "write switches together (-pq) or apart (-p -q)";
        } else if (letter == 'w' || letter == 'W') {
            advice = "Triangle's undocumented weighted triangulations are not supported";
        } else if (letter == 'L') {
            advice = "did you mean -l or -D?";
        } else if (other_case != letter &&
                   known_letters.find(other_case) != std::string_view::npos) {
            advice = fmt::format("did you mean -{}?", other_case);
        }
        const std::string what = letter == '-' ? std::string("'-'")
                                 : (u >= 0x20 && u < 0x7f)
                                     ? fmt::format("-{}", letter)
                                     : fmt::format("byte 0x{:02x}", unsigned{u});
        fail("unknown switch " + what, "; ", advice);
    }

    // The long option the whole cluster looks like ("-threads", "-vers"),
    // or empty.
    std::string_view long_option_hint() const {
        std::string_view word = text_;
        while (!word.empty() && word.front() == '-') word.remove_prefix(1);
        const auto eq = word.find('=');
        if (eq != std::string_view::npos) word = word.substr(0, eq);
        if (word.size() < 3) return {};
        for (std::string_view name : long_option_names) {
            name.remove_prefix(2);  // "--"
            if (name.substr(0, word.size()) == word) return name;
        }
        return {};
    }

    // Every message names the switch ("-q70"), then the whole cluster when
    // the switch was one of several, then why; a cluster that looks like a
    // long option typed with one dash gets that suggestion instead.
    [[noreturn]] void fail(const std::string& subject, std::string_view separator,
                           std::string_view why) const {
        std::string message = subject;
        if (letter_start_ != 0 || pos_ != text_.size()) message += fmt::format(" in {}", shown_);
        if (const auto name = long_option_hint(); !name.empty())
            message += fmt::format("{}did you mean --{}?", separator, name);
        else
            message += fmt::format("{}{}", separator, why);
        throw UsageError(message);
    }

    std::string_view text_;
    std::string_view shown_;
    Options& options_;
    SwitchDialect dialect_;
    std::size_t pos_ = 0;           // the next character to read
    std::size_t letter_start_ = 0;  // where the switch being read starts
};

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

void parse_switches(std::string_view cluster, Options& options, SwitchDialect dialect) {
    if (cluster.empty()) return;
    std::string_view text = cluster;
    if (dialect == SwitchDialect::program) {
        if (cluster == "-")
            throw UsageError(
                "'-' alone is not a switch (gpdr reads named files, not standard input)");
        if (text.front() == '-') text.remove_prefix(1);
    }
    ClusterReader(text, cluster, options, dialect).run();
}

Placement parse_placement(std::string_view name) {
    const std::string n = lower(name);
    if (n == "0" || n == "circumcentre" || n == "circumcenter") return Placement::circumcentre;
    if (n == "1" || n == "off-centre" || n == "off-center" || n == "offcentre" || n == "offcenter")
        return Placement::off_centre;
    if (n == "2" || n == "optimisation" || n == "optimization") return Placement::optimisation;
    throw UsageError(fmt::format(
        "unknown placement '{}': use circumcentre (0), off-centre (1) or optimisation (2)", name));
}

std::string_view placement_name(Placement placement) {
    switch (placement) {
        case Placement::circumcentre:
            return "circumcentre";
        case Placement::off_centre:
            return "off-centre";
        case Placement::optimisation:
            return "optimisation";
    }
    return "unknown";
}

}  // namespace gpdr
