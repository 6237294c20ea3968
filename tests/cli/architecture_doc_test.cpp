// docs/architecture.md against the tree: every file it quotes in backticks
// exists, and every function it quotes as `name()` is defined or declared
// somewhere in lib/, apps/ or capi/.  A document that names what is gone
// sends the next engineer looking for it.
//
// A quoted file is a word ending in a source, script, document or sample
// extension; with a '/', a path from the repository's root, from lib/,
// lib/include/ or docs/ (the folders the document writes paths from);
// without one, a file of that name anywhere in the tree.  A quoted function is a word of
// letters, digits, '_' and "::" ending in "()"; its last component must
// appear as a whole word in the sources.

#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

// The backticked spans of a Markdown text (code blocks included: their
// lines are quoted names too, and a span never crosses a line).
std::vector<std::string> quoted(const std::string& text) {
    std::vector<std::string> spans;
    std::string::size_type at = 0;
    while ((at = text.find('`', at)) != std::string::npos) {
        const auto end = text.find('`', at + 1);
        if (end == std::string::npos) break;
        const std::string span = text.substr(at + 1, end - at - 1);
        if (span.find('\n') == std::string::npos) spans.push_back(span);
        at = end + 1;
    }
    return spans;
}

bool is_file_name(const std::string& s) {
    static const std::regex file(R"(^[A-Za-z0-9_./-]+\.(hpp|cpp|h|c|md|sh|py|poly|node|txt)$)");
    return std::regex_match(s, file);
}

// The sources' text, and the names of every file in the tree.
struct Tree {
    std::string sources;
    std::set<std::string> file_names;
};

const Tree& tree() {
    static const Tree t = [] {
        Tree t;
        for (const char* folder :
             {"lib", "apps", "capi", "tests", "scripts", "docs", "man", "poly-samples", "cmake"}) {
            const fs::path root = source_dir() / folder;
            if (!fs::exists(root)) continue;
            for (const auto& entry : fs::recursive_directory_iterator(root)) {
                if (!entry.is_regular_file()) continue;
                t.file_names.insert(entry.path().filename().string());
                const std::string f(folder);
                const std::string ext = entry.path().extension().string();
                if ((f == "lib" || f == "apps" || f == "capi") &&
                    (ext == ".hpp" || ext == ".cpp" || ext == ".h" || ext == ".c"))
                    t.sources += TempDir::slurp(entry.path()) + "\n";
            }
        }
        for (const auto& entry : fs::directory_iterator(source_dir()))
            if (entry.is_regular_file()) t.file_names.insert(entry.path().filename().string());
        return t;
    }();
    return t;
}

bool file_exists(const std::string& name) {
    if (name.find('/') == std::string::npos) return tree().file_names.count(name) != 0;
    for (const fs::path& base : {source_dir(), source_dir() / "lib",
                                 source_dir() / "lib" / "include", source_dir() / "docs"})
        if (fs::exists(base / name)) return true;
    return false;
}

// Whether `word` appears in the sources with no identifier character
// either side.
bool in_sources(const std::string& word) {
    const std::string& s = tree().sources;
    const auto ident = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    for (auto at = s.find(word); at != std::string::npos; at = s.find(word, at + 1)) {
        const bool before = at > 0 && ident(s[at - 1]);
        const bool after = at + word.size() < s.size() && ident(s[at + word.size()]);
        if (!before && !after) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("docs/architecture.md quotes only files and functions that exist", "[cli][docs]") {
    const std::string text = TempDir::slurp(source_dir() / "docs" / "architecture.md");
    REQUIRE(text.size() > 10000);
    static const std::regex function(
        R"(^([A-Za-z_][A-Za-z0-9_]*::)*([A-Za-z_][A-Za-z0-9_]*)\(\)$)");
    std::size_t files = 0, functions = 0;
    for (const std::string& span : quoted(text)) {
        std::smatch m;
        if (is_file_name(span)) {
            ++files;
            INFO("file `" << span << "`");
            CHECK(file_exists(span));
        } else if (std::regex_match(span, m, function)) {
            ++functions;
            INFO("function `" << span << "`");
            CHECK(in_sources(m[2].str()));
        }
    }
    // The document quotes many of both: a reader that found none is broken.
    CHECK(files > 50);
    CHECK(functions > 10);
}

TEST_CASE("the architecture check finds a name that is gone", "[cli][docs]") {
    CHECK_FALSE(in_sources("run_threads_that_never_was"));
    CHECK_FALSE(file_exists("parallel/never_was.hpp"));
    CHECK(file_exists("parallel/schedule.hpp"));
    CHECK(in_sources("choose_schedule"));
    CHECK(quoted("a `b.hpp` c `d()` e") == std::vector<std::string>{"b.hpp", "d()"});
}
