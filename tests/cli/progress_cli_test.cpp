// The progress line: a run of a few seconds on a terminal shows it on
// standard error and erases it before the results; the same run with
// standard error going to a file, on a dumb terminal, or with -Q, shows none.  The terminal is
// a pseudo-terminal made with forkpty(), which, unlike script(1), needs no
// standard input of its own (CI has none).

#include <catch2/catch.hpp>

#include <cerrno>
#include <string>
#include <vector>

#include <fcntl.h>
#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

struct TerminalRun {
    int status = -1;       // exit status, -1 if killed
    std::string terminal;  // everything the terminal received
};

// Runs gpdr in `dir` with a pseudo-terminal as its standard input, output and
// error, or with standard error sent to the file `stderr_file` when given,
// and TERM set to `term` (whatever the test's own environment says).
TerminalRun run_on_terminal(const TempDir& dir, const std::vector<std::string>& args,
                            const std::string& stderr_file = "", const char* term = "xterm") {
    int master = -1;
    winsize size{};
    size.ws_row = 24;
    size.ws_col = 80;
    const pid_t pid = ::forkpty(&master, nullptr, nullptr, &size);
    REQUIRE(pid >= 0);
    if (pid == 0) {
        if (::chdir(dir.path().c_str()) != 0) ::_exit(127);
        ::setenv("TERM", term, 1);
        if (!stderr_file.empty()) {
            const int fd = ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd < 0 || ::dup2(fd, 2) < 0) ::_exit(127);
        }
        std::string exe = GPDR_EXE;
        std::vector<std::string> copies = args;
        std::vector<char*> argv{exe.data()};
        for (std::string& a : copies) argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execv(exe.c_str(), argv.data());
        ::_exit(127);
    }
    TerminalRun r;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(master, buffer, sizeof buffer);
        if (n > 0) {
            r.terminal.append(buffer, static_cast<std::size_t>(n));
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            break;  // EIO: the child closed its side of the terminal
        }
    }
    ::close(master);
    int status = 0;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// About 8.6 million triangles on one thread, with no files written: two
// seconds of refining on the project's 2-core VM, twice the second after
// which the line shows, so that refining still shows it on a faster machine
// (half the triangles refine in under a second there).
const std::vector<std::string> long_run{"-j1", "-pq20a0.02", "-NEP", "pipe.poly"};

}  // namespace

TEST_CASE("a long run on a terminal shows a progress line and erases it", "[cli][progress]") {
    TempDir dir;
    fs::copy_file(project_samples() / "pipe.poly", dir / "pipe.poly");
    std::vector<std::string> args = long_run;
    args.insert(args.begin(), "-V");  // statistics on stdout after the run
    const TerminalRun r = run_on_terminal(dir, args);
    INFO(r.terminal);
    REQUIRE(r.status == 0);
    const std::size_t shown = r.terminal.rfind("\rgpdr: ");
    REQUIRE(shown != std::string::npos);
    CHECK(r.terminal.find("\rgpdr: refining, about ") != std::string::npos);
    // Refining shows the mesh growing: not the count of zero it would show
    // if the vertex count were read from nowhere.
    CHECK(r.terminal.find("\rgpdr: refining, about 0 triangles") == std::string::npos);
    // Erased (carriage return, erase to the end of the line) after the last
    // update, before the results are printed.
    const std::size_t erased = r.terminal.rfind("\r\x1b[K");
    const std::size_t verdict = r.terminal.find("Read milliseconds:");
    REQUIRE(erased != std::string::npos);
    REQUIRE(verdict != std::string::npos);
    CHECK(shown < erased);
    CHECK(erased < verdict);
    // Never wider than the terminal.
    for (std::size_t at = 0; (at = r.terminal.find("\rgpdr: ", at)) != std::string::npos; ++at)
        CHECK(r.terminal.find("\x1b[K", at) - at - 1 <= 79);
}

TEST_CASE("no progress line off a terminal, on a dumb one, or with -Q", "[cli][progress]") {
    TempDir dir;
    fs::copy_file(project_samples() / "pipe.poly", dir / "pipe.poly");
    SECTION("standard error to a file") {
        const std::string log = (dir / "stderr.log").string();
        const TerminalRun r = run_on_terminal(dir, long_run, log);
        REQUIRE(r.status == 0);
        CHECK(r.terminal.find("gpdr: ") == std::string::npos);
        CHECK(r.terminal.find('\x1b') == std::string::npos);
        const std::string err = TempDir::slurp(log);
        CHECK(err.find('\r') == std::string::npos);
        CHECK(err.find("gpdr: refining") == std::string::npos);
    }
    SECTION("a dumb terminal") {
        const TerminalRun r = run_on_terminal(dir, long_run, "", "dumb");
        REQUIRE(r.status == 0);
        CHECK(r.terminal.empty());
    }
    SECTION("-Q") {
        std::vector<std::string> args = long_run;
        args.insert(args.begin(), "-Q");
        const TerminalRun r = run_on_terminal(dir, args);
        REQUIRE(r.status == 0);
        CHECK(r.terminal.empty());
    }
}
