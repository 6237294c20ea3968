// The switch reference of `gpdr -h` and of man/gpdr.1, checked against the
// parser: every switch letter and long option the parser accepts has an
// entry in both, and neither names a switch or long option the parser
// rejects.
//
// What the parser accepts is asked of the parser, not listed here.  Each
// printable ASCII character k is given to gpdr::parse_switches() as the
// cluster "-k": k is a switch unless the parser calls it an unknown switch.
// A switch works bare when "-k" parses, and takes a number when "-k2" parses
// as well and k does not stop the reading (as h does: "-h" followed by
// anything parses).  The long options are gpdr::long_option_names, the
// table the command line checks every "--name" against; each is also run
// through the built gpdr, which must know it, and which says whether it needs
// a value.
//
// Where the documents keep their switch reference, and how an entry looks:
//   - gpdr -h: from the line "Switches:" through every block (an unindented
//     header line and the indented lines under it) whose first indented line
//     is an entry; an entry is a line starting with two spaces and a dash.
//   - man/gpdr.1: the .SH OPTIONS section (its .SS subsections included); an
//     entry is the tag line after a .TP, read as text once the roff is undone
//     (".BI \-j n "\fR, \fP\-\-threads " n" reads "-jn, --threads n").
// An entry names its switches first, separated by ", ".  A switch is "-k"
// (bare), "-k[...]" (the number may be left out), "-k" and digits ("-o2":
// exactly that) or "-k" and a placeholder ("-jN": with a number).  A long
// option is "--name", followed by one word for its value when it takes one.
// Besides the entries, every "-k..." or "--name" written anywhere in those
// sections must be something the parser knows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <gpdr/errors.hpp>
#include <gpdr/options.hpp>
#include <gpdr/switches.hpp>

#include "../../apps/gpdr/command_line.hpp"
#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

// --- What the parser accepts.

enum class Parse { ok, unknown_switch, other_error };

// How parse_switches() takes `cluster`: accepted, refused as an unknown
// switch, or refused for another reason (a bad or missing number).
Parse parse(const std::string& cluster) {
    gpdr::Options options;
    try {
        gpdr::parse_switches(cluster, options);
        return Parse::ok;
    } catch (const gpdr::UsageError& e) {
        return std::string_view(e.what()).substr(0, 14) == "unknown switch" ? Parse::unknown_switch
                                                                            : Parse::other_error;
    }
}

struct SwitchForms {
    bool bare = false;      // "-k" alone
    bool numbered = false;  // "-k" followed at once by a number
};

// Every switch character parse_switches() accepts, with the forms it takes.
const std::map<char, SwitchForms>& parser_switches() {
    static const std::map<char, SwitchForms> switches = [] {
        std::vector<char> known;
        char rejected = 0;  // some character that is not a switch
        for (int c = 0x21; c < 0x7f; ++c) {
            const std::string cluster = {'-', static_cast<char>(c)};
            if (parse(cluster) == Parse::unknown_switch) {
                if (rejected == 0) rejected = static_cast<char>(c);
            } else {
                known.push_back(static_cast<char>(c));
            }
        }
        REQUIRE(rejected != 0);
        REQUIRE(!known.empty());
        const bool two_is_a_switch = std::count(known.begin(), known.end(), '2') != 0;
        std::map<char, SwitchForms> result;
        for (const char k : known) {
            const std::string bare = {'-', k};
            const bool stops = parse(bare + rejected) == Parse::ok;
            SwitchForms forms;
            forms.bare = parse(bare) == Parse::ok;
            forms.numbered = !stops && !two_is_a_switch && parse(bare + '2') == Parse::ok;
            result.emplace(k, forms);
        }
        return result;
    }();
    return switches;
}

// Every long option the command line accepts, and whether it needs a value.
const std::map<std::string, bool>& parser_long_options() {
    static const std::map<std::string, bool> options = [] {
        std::map<std::string, bool> result;
        TempDir dir;
        for (const std::string_view name_view : gpdr::long_option_names) {
            const std::string name(name_view);
            const auto r = run_gpdr(dir, name);
            INFO("gpdr " << name << " printed: " << r.err);
            CHECK(r.err.find("unknown option") == std::string::npos);
            CHECK(r.err.find("internal error") == std::string::npos);
            result.emplace(name, r.err.find(name + " needs a value") != std::string::npos);
        }
        REQUIRE(!result.empty());
        return result;
    }();
    return options;
}

// --- What a document says.

struct Entry {
    std::string name;   // "-jN", "-q[ANGLE]", "--threads"
    std::string value;  // for a long option: the word naming its value, if any
    std::string line;   // the entry as written, for messages
};

struct Reference {
    std::vector<Entry> entries;
    std::vector<std::string> lines;  // the whole switch reference, as text
};

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// The switches an entry's text names: "-jN, --threads N       Refine ..."
// gives "-jN" and "--threads" (value "N").
std::vector<Entry> entries_of(const std::string& text) {
    std::vector<Entry> entries;
    std::size_t pos = text.find_first_not_of(" \t");
    while (pos < text.size() && text[pos] == '-') {
        std::size_t end = pos;
        while (end < text.size() && !is_blank(text[end]) && text[end] != ',') ++end;
        Entry entry{text.substr(pos, end - pos), "", text};
        // An optional value word: one blank, a word, then ", ", a wider gap
        // or the end of the text.
        std::size_t next = end;
        if (end + 1 < text.size() && text[end] == ' ' && !is_blank(text[end + 1])) {
            std::size_t word_end = end + 1;
            while (word_end < text.size() && !is_blank(text[word_end]) && text[word_end] != ',')
                ++word_end;
            const std::string_view after = std::string_view(text).substr(word_end);
            if (after.empty() || after.substr(0, 2) == ", " || after.substr(0, 2) == "  ") {
                entry.value = text.substr(end + 1, word_end - end - 1);
                next = word_end;
            }
        }
        entries.push_back(entry);
        if (text.compare(next, 3, ", -") != 0) break;
        pos = next + 2;
    }
    return entries;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The switch reference of gpdr -h's output.
Reference help_reference(const std::string& help) {
    const std::vector<std::string> lines = lines_of(help);
    const auto start = std::find(lines.begin(), lines.end(), "Switches:");
    REQUIRE(start != lines.end());
    const auto indented = [](const std::string& line) { return !line.empty() && line[0] == ' '; };
    const auto is_entry = [](const std::string& line) { return line.compare(0, 3, "  -") == 0; };
    Reference reference;
    for (auto header = start; header != lines.end();) {
        auto end = header + 1;
        while (end != lines.end() && indented(*end)) ++end;
        if (end == header + 1 || !is_entry(*(header + 1))) break;
        for (auto line = header; line != end; ++line) {
            reference.lines.push_back(*line);
            if (is_entry(*line))
                for (Entry& entry : entries_of(*line)) reference.entries.push_back(entry);
        }
        header = end;
        while (header != lines.end() && header->empty()) ++header;
    }
    return reference;
}

// A roff escape undone: fonts and \& vanish, \- is a dash, quotes are quotes,
// other special characters become a blank.
std::string roff_unescape(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '\\' || i + 1 == s.size()) {
            out += s[i];
            continue;
        }
        const char c = s[++i];
        if (c == 'f') {  // \fB, \f(BI, \f[BI]
            if (i + 1 < s.size() && s[i + 1] == '(')
                i += 3;
            else if (i + 1 < s.size() && s[i + 1] == '[')
                i = std::min(s.size() - 1, s.find(']', i));
            else
                i += 1;
        } else if (c == '(') {  // \(lq and the like
            const std::string_view special = s.substr(i + 1, 2);
            out += special == "lq" || special == "rq" || special == "dq" ? '"' : ' ';
            i += 2;
        } else if (c == '-' || c == '\\' || c == ' ' || c == '.') {
            out += c;
        } else if (c == 'e') {
            out += '\\';
        } else if (c != '&') {
            out += c;
        }
    }
    return out;
}

// One line of roff as the reader sees it: a font macro's arguments joined
// (with blanks for .B and .I, without for .BR and the other alternating
// ones), other requests' arguments as they are, comments as nothing.
std::string roff_text(const std::string& line) {
    if (line.empty() || (line[0] != '.' && line[0] != '\'')) return roff_unescape(line);
    if (line.compare(1, 2, "\\\"") == 0) return "";
    std::size_t pos = 1;
    while (pos < line.size() && !is_blank(line[pos])) ++pos;
    const std::string macro = line.substr(1, pos - 1);
    const bool alternating = macro == "BR" || macro == "BI" || macro == "IB" || macro == "IR" ||
                             macro == "RB" || macro == "RI";
    std::vector<std::string> arguments;
    while (pos < line.size()) {
        while (pos < line.size() && is_blank(line[pos])) ++pos;
        if (pos == line.size()) break;
        std::string argument;
        if (line[pos] == '"') {
            for (++pos; pos < line.size(); ++pos) {
                if (line[pos] == '"' && pos + 1 < line.size() && line[pos + 1] == '"') {
                    argument += '"';
                    ++pos;
                } else if (line[pos] == '"') {
                    ++pos;
                    break;
                } else {
                    argument += line[pos];
                }
            }
        } else {
            while (pos < line.size() && !is_blank(line[pos])) argument += line[pos++];
        }
        arguments.push_back(argument);
    }
    std::string joined;
    for (std::size_t i = 0; i < arguments.size(); ++i)
        joined += (i == 0 || alternating ? "" : " ") + arguments[i];
    return roff_unescape(joined);
}

// The switch reference of the man page: its OPTIONS section.
Reference man_reference(const std::string& page) {
    const std::vector<std::string> lines = lines_of(page);
    const auto start = std::find(lines.begin(), lines.end(), ".SH OPTIONS");
    REQUIRE(start != lines.end());
    Reference reference;
    bool tag_next = false;
    for (auto line = start; line != lines.end(); ++line) {
        if (line != start && line->compare(0, 4, ".SH ") == 0) break;
        const std::string text = roff_text(*line);
        reference.lines.push_back(text);
        if (tag_next)
            for (Entry& entry : entries_of(text)) reference.entries.push_back(entry);
        tag_next = *line == ".TP" || line->compare(0, 4, ".TP ") == 0;
    }
    return reference;
}

// Every switch cluster ("-pq30", "-q" from "-q[ANGLE]") and long option
// ("--threads" from "--threads=4") written in `text`.  A dash counts where it
// starts a word: at the start, or after a blank or an opening mark.
void find_mentions(const std::string& text, std::vector<std::string>& clusters,
                   std::vector<std::string>& long_options) {
    const auto starts_word = [&](std::size_t i) {
        return i == 0 || std::string_view(" \t([{,;/\"'`").find(text[i - 1]) != std::string::npos;
    };
    for (std::size_t i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != '-' || !starts_word(i)) continue;
        std::size_t end = i + 1;
        if (text[i + 1] == '-' && i + 2 < text.size() &&
            std::isalpha(static_cast<unsigned char>(text[i + 2]))) {
            end = i + 2;
            while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) ||
                                         text[end] == '-' || text[end] == '_'))
                ++end;
            long_options.push_back(text.substr(i, end - i));
        } else if (std::isalpha(static_cast<unsigned char>(text[i + 1])) || text[i + 1] == '?') {
            while (end < text.size() && !is_blank(text[end]) &&
                   std::string_view("[]),;\"'`").find(text[end]) == std::string::npos)
                ++end;
            std::string cluster = text.substr(i, end - i);
            while (cluster.size() > 2 && (cluster.back() == '.' || cluster.back() == ':'))
                cluster.pop_back();
            clusters.push_back(cluster);
        }
        i = end - 1;
    }
}

bool all_digits(std::string_view s) {
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// (a) every switch and long option the parser accepts has an entry, in each
// form it takes; (b) every entry and every mention is one the parser accepts.
void check_reference(const std::string& document, const Reference& reference) {
    const auto& switches = parser_switches();
    const auto& long_options = parser_long_options();
    INFO("the switch reference of " << document);
    REQUIRE(!reference.entries.empty());

    std::map<char, SwitchForms> documented;
    std::set<std::string> documented_long;
    for (const Entry& entry : reference.entries) {
        INFO("the entry \"" << entry.line << "\"");
        const std::string& name = entry.name;
        if (name.compare(0, 2, "--") == 0) {
            const auto found = long_options.find(name);
            if (found == long_options.end()) {
                FAIL_CHECK(name << " is not a long option of gpdr");
                continue;
            }
            documented_long.insert(name);
            if (found->second && entry.value.empty())
                FAIL_CHECK(name << " takes a value, and the entry names none");
            if (!found->second && !entry.value.empty())
                FAIL_CHECK(name << " takes no value, and the entry names one");
            continue;
        }
        if (name.size() < 2) {
            FAIL_CHECK("\"" << name << "\" names no switch");
            continue;
        }
        const char letter = name[1];
        const std::string suffix = name.substr(2);
        const auto found = switches.find(letter);
        if (found == switches.end()) {
            FAIL_CHECK("-" << letter << " is not a switch of gpdr");
            continue;
        }
        const SwitchForms forms = found->second;
        SwitchForms& seen = documented[letter];
        if (suffix.empty()) {
            if (!forms.bare) FAIL_CHECK("-" << letter << " does not work without a number");
            seen.bare = true;
        } else if (suffix.front() == '[') {
            if (!forms.bare) FAIL_CHECK("-" << letter << " does not work without a number");
            if (!forms.numbered) FAIL_CHECK("-" << letter << " takes no number");
            seen.bare = seen.numbered = true;
        } else if (all_digits(suffix)) {
            if (parse(name) != Parse::ok) FAIL_CHECK("the parser rejects " << name);
            seen.numbered = true;
        } else {
            if (!forms.numbered) FAIL_CHECK("-" << letter << " takes no number");
            seen.numbered = true;
        }
    }

    for (const auto& [letter, forms] : switches) {
        INFO("the parser's switch -" << letter);
        CHECK((forms.bare || forms.numbered));
        const auto found = documented.find(letter);
        if (found == documented.end()) {
            FAIL_CHECK("-" << letter << " has no entry");
            continue;
        }
        if (forms.bare && !found->second.bare) FAIL_CHECK("no entry for -" << letter << " alone");
        if (forms.numbered && !found->second.numbered)
            FAIL_CHECK("no entry for -" << letter << " with a number");
    }
    for (const auto& [name, takes_value] : long_options) {
        INFO("the parser's long option " << name);
        if (documented_long.count(name) == 0) FAIL_CHECK(name << " has no entry");
    }

    for (const std::string& line : reference.lines) {
        std::vector<std::string> clusters;
        std::vector<std::string> mentioned_long;
        find_mentions(line, clusters, mentioned_long);
        INFO("the line \"" << line << "\"");
        for (const std::string& cluster : clusters)
            if (parse(cluster) == Parse::unknown_switch)
                FAIL_CHECK(cluster << " names a switch letter gpdr does not know");
        for (const std::string& name : mentioned_long)
            if (long_options.count(name) == 0) FAIL_CHECK(name << " is not a long option of gpdr");
    }
}

}  // namespace

TEST_CASE("gpdr -h documents exactly the switches the parser accepts", "[cli][switch_reference]") {
    TempDir dir;
    const auto r = run_gpdr(dir, "-h");
    REQUIRE(r.status == 0);
    check_reference("gpdr -h", help_reference(r.out));
}

TEST_CASE("man/gpdr.1 documents exactly the switches the parser accepts",
          "[cli][switch_reference]") {
    const std::string page = TempDir::slurp(source_dir() / "man" / "gpdr.1");
    REQUIRE(!page.empty());
    check_reference("man/gpdr.1", man_reference(page));
}

TEST_CASE("the switch reference reader sees what a reader sees", "[cli][switch_reference]") {
    SECTION("entries") {
        const auto entries = entries_of("  -jN, --threads N       Refine with N threads");
        REQUIRE(entries.size() == 2);
        CHECK(entries[0].name == "-jN");
        CHECK(entries[1].name == "--threads");
        CHECK(entries[1].value == "N");
        const auto one = entries_of("  -q[ANGLE] Quality mesh: no angle below ANGLE");
        REQUIRE(one.size() == 1);
        CHECK(one[0].name == "-q[ANGLE]");
        const auto flag = entries_of("  --help                 The same as -h.");
        REQUIRE(flag.size() == 1);
        CHECK(flag[0].value.empty());
        CHECK(entries_of("  -h, -H, -?").size() == 3);
    }
    SECTION("roff") {
        CHECK(roff_text(".BI \\-j n \"\\fR, \\fP\\-\\-threads \" n") == "-jn, --threads n");
        CHECK(roff_text(".BI \\-q [angle]") == "-q[angle]");
        CHECK(roff_text(".BR \\-h \", \" \\-H \", \" \\-?") == "-h, -H, -?");
        CHECK(roff_text(".BI \\-\\-unsuitable \" lib.so\"") == "--unsuitable lib.so");
        CHECK(roff_text("(\\fB\\-\\-threads=4\\fR).") == "(--threads=4).");
    }
    SECTION("mentions") {
        std::vector<std::string> clusters;
        std::vector<std::string> long_options;
        find_mentions("(-VV, -VVV) -q[ANGLE] 1e-5 180 - 2 off-centre -aa0.5. --threads=4", clusters,
                      long_options);
        CHECK(clusters == std::vector<std::string>{"-VV", "-VVV", "-q", "-aa0.5"});
        CHECK(long_options == std::vector<std::string>{"--threads"});
    }
    SECTION("the parser's answers") {
        const auto& switches = parser_switches();
        // The parser is asked, not listed: these only show that asking works.
        REQUIRE(switches.count('q') == 1);
        CHECK(switches.at('q').bare);
        CHECK(switches.at('q').numbered);
        REQUIRE(switches.count('o') == 1);
        CHECK(!switches.at('o').bare);
        CHECK(switches.at('o').numbered);
        REQUIRE(switches.count('h') == 1);
        CHECK(!switches.at('h').numbered);
    }
}
