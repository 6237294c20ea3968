// The gpdr executable's command line: help, usage, version, errors as
// "gpdr: ..." with exit status 1 and no files left behind, the long options,
// and the messages of a successful run ("Wrote", -Q, -V, -C, warnings).
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

const char* const square_node =
    "# the unit square\n"
    "4 2 0 0\n"
    "1 0 0\n"
    "2 1 0\n"
    "3 1 1\n"
    "4 0 1\n";

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// True when some line, leading blanks removed, starts with `token` followed
// by a blank, a comma, '[' or the end of the line.
bool has_entry(const std::string& text, const std::string& token) {
    for (const std::string& line : lines_of(text)) {
        const auto start = line.find_first_not_of(' ');
        if (start == std::string::npos || line.compare(start, token.size(), token) != 0) continue;
        const auto after = start + token.size();
        if (after == line.size() || line[after] == ' ' || line[after] == ',' || line[after] == '[')
            return true;
    }
    return false;
}

bool starts_with(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

TEST_CASE("gpdr -h lists every switch and long option, exit status 0", "[cli][command_line]") {
    TempDir dir;
    const auto r = run_gpdr(dir, "-h");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    for (const std::string letter :
         {"-p", "-r",  "-q",  "-a",  "-u",  "-A",           "-c",      "-D",     "-j",       "-e",
          "-v", "-n",  "-g",  "-B",  "-P",  "-N",           "-E",      "-I",     "-O",       "-X",
          "-z", "-o2", "-Y",  "-S",  "-i",  "-F",           "-l",      "-s",     "-C",       "-Q",
          "-V", "-h",  "-jN", "-gN", "-PN", "--unsuitable", "--force", "--help", "--version"}) {
        INFO("switch " << letter);
        CHECK(has_entry(r.out, letter));
    }
    for (const std::string option : {"--threads", "--granularity", "--placement"}) {
        INFO("option " << option);
        CHECK(r.out.find(option) != std::string::npos);
    }
    CHECK(dir.files().empty());

    CHECK(run_gpdr(dir, "--help").out == r.out);
    const auto stops = run_gpdr(dir, "-ph -k");  // as Triangle, -h acts at once
    CHECK(stops.status == 0);
    CHECK(stops.out == r.out);
}

TEST_CASE("gpdr with no input prints a short usage, exit status 0", "[cli][command_line]") {
    TempDir dir;
    for (const std::string args : {"", "-pq30", "-V -Q"}) {
        INFO("args: " << args);
        const auto r = run_gpdr(dir, args);
        CHECK(r.status == 0);
        CHECK(starts_with(r.out, "Usage: gpdr"));
        CHECK(r.err.empty());
    }
    CHECK(dir.files().empty());
}

TEST_CASE("gpdr --version names the version", "[cli][command_line]") {
    TempDir dir;
    const auto r = run_gpdr(dir, "--version");
    CHECK(r.status == 0);
    CHECK(starts_with(r.out, "gpdr "));
    CHECK(r.out.find_first_of("0123456789") != std::string::npos);
    CHECK(lines_of(r.out).size() == 1);
}

TEST_CASE("command-line errors: gpdr: message, exit status 1, no files", "[cli][command_line]") {
    struct Bad {
        std::string args;
        std::string says;  // the message must contain this
    };
    const std::vector<Bad> rows = {
        {"-pk sq.node", "-k"},
        {"-x sq.node", "-X"},
        {"-q70 sq.node", "-q70"},
        {"-a0 sq.node", "greater than zero"},
        {"-a-1 sq.node", "-a-1"},
        {"-o3 sq.node", "-o2"},
        {"-P5 sq.node", "placement"},
        {"-threads 4 sq.node", "--threads"},
        {"--placement bad sq.node", "bad"},
        {"--placement=7 sq.node", "placement"},
        {"--threads many sq.node", "--threads"},
        {"--thread 4 sq.node", "--threads"},
        {"--frobnicate sq.node", "--frobnicate"},
        {"sq.node --threads", "--threads"},
        {"-rI sq.node", "-I"},
        {"-I sq.1.ele", "-I"},
        {"- sq.node", "'-'"},
    };
    for (const Bad& bad : rows) {
        INFO("gpdr " << bad.args);
        TempDir dir;
        dir.write("sq.node", square_node);
        const auto r = run_gpdr(dir, bad.args);
        CHECK(r.status == 1);
        CHECK(starts_with(r.err, "gpdr: "));
        CHECK(r.err.find(bad.says) != std::string::npos);
        CHECK(lines_of(r.err).size() == 1);
        CHECK(r.out.empty());
        CHECK(dir.files() == std::vector<std::string>{"sq.node"});
    }
}

TEST_CASE("a missing input file is an error, not a crash", "[cli][command_line]") {
    TempDir dir;
    const auto r = run_gpdr(dir, "-Q nothere.node");
    CHECK(r.status == 1);
    CHECK(starts_with(r.err, "gpdr: "));
    CHECK(r.err.find("nothere") != std::string::npos);
    CHECK(dir.files().empty());
}

TEST_CASE("a run prints each file it wrote; -Q silences it", "[cli][command_line]") {
    TempDir dir;
    dir.write("sq.node", square_node);
    const auto r = run_gpdr(dir, "sq");
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const auto lines = lines_of(r.out);
    CHECK(std::find(lines.begin(), lines.end(), "Wrote sq.1.node") != lines.end());
    CHECK(std::find(lines.begin(), lines.end(), "Wrote sq.1.ele") != lines.end());
    CHECK(dir.exists("sq.1.node"));
    CHECK(dir.exists("sq.1.ele"));

    const auto quiet = run_gpdr(dir, "-Q sq.node");
    CHECK(quiet.status == 0);
    CHECK(quiet.out.empty());
    CHECK(quiet.err.empty());

    // Long options and gpdr's numbered switches are accepted on a real run.
    const auto threads = run_gpdr(dir, "-Q -j2 -g4 -P0 --threads 1 --placement=off-centre sq.node");
    CHECK(threads.status == 0);
    CHECK(threads.err.empty());
}

TEST_CASE("switch -V prints statistics, -C the check's verdict", "[cli][command_line]") {
    TempDir dir;
    dir.write("sq.node", square_node);
    const auto plain = run_gpdr(dir, "sq.node");
    const auto verbose = run_gpdr(dir, "-V sq.node");
    REQUIRE(verbose.status == 0);
    CHECK(lines_of(verbose.out).size() > lines_of(plain.out).size());

    const auto checked = run_gpdr(dir, "-C sq.node");
    CHECK(checked.status == 0);
    CHECK(checked.out.find("Check: no problems found") != std::string::npos);
    CHECK(checked.err.empty());
}

TEST_CASE("warnings go to stderr as gpdr: FILE: warning:, silenced by -Q", "[cli][command_line]") {
    TempDir dir;
    // Vertex 5 repeats vertex 3: Triangle and gpdr both warn and go on.
    dir.write("dup.node", "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 1 1\n");
    const auto r = run_gpdr(dir, "dup.node");
    CHECK(r.status == 0);
    CHECK(starts_with(r.err, "gpdr: dup.node"));
    CHECK(r.err.find(": warning: ") != std::string::npos);
    CHECK(r.out.find("Wrote dup.1.node") != std::string::npos);

    const auto quiet = run_gpdr(dir, "-Q dup.node");
    CHECK(quiet.status == 0);
    CHECK(quiet.err.empty());
}
