// A run killed while it writes its output (SIGTERM, SIGINT, SIGHUP) removes
// its temporary files and dies of the same signal, leaving the files of an
// earlier run exactly as they were.

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <string>
#include <thread>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

namespace {

bool has_temporary(const TempDir& dir) {
    for (const auto& entry : fs::directory_iterator(dir.path()))
        if (entry.path().filename().string().find(".gpdr-") != std::string::npos) return true;
    return false;
}

// Starts gpdr in `dir` with its output streams discarded.
pid_t start_gpdr(const TempDir& dir, const std::vector<std::string>& args) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (::chdir(dir.path().c_str()) != 0) ::_exit(127);
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(null, 2);
        std::vector<char*> argv;
        std::string exe = GPDR_EXE;
        argv.push_back(exe.data());
        std::vector<std::string> copies = args;
        for (std::string& a : copies) argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execv(exe.c_str(), argv.data());
        ::_exit(127);
    }
    return pid;
}

}  // namespace

TEST_CASE("a run killed while writing leaves no temporary and the old files", "[cli][kill]") {
    const int signal = GENERATE(SIGTERM, SIGINT, SIGHUP);
    TempDir dir;
    fs::copy_file(project_samples() / "pipe.poly", dir / "pipe.poly");
    const std::vector<std::string> old_files{"pipe.1.node", "pipe.1.ele", "pipe.1.poly"};
    for (const auto& name : old_files) dir.write(name, "an earlier result\n");

    // About 1.2 million triangles: the output takes long enough to be
    // caught while its temporaries exist.  The test waits for the first
    // temporary, then sends the signal.
    const pid_t pid = start_gpdr(dir, {"-Q", "-j1", "-pq20a0.1", "pipe.poly"});
    REQUIRE(pid > 0);
    bool caught = false;
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (std::chrono::steady_clock::now() < deadline) {
        if (has_temporary(dir)) {
            ::kill(pid, signal);
            caught = true;
            break;
        }
        if (::waitpid(pid, &status, WNOHANG) == pid) break;  // finished before
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (caught) REQUIRE(::waitpid(pid, &status, 0) == pid);
    INFO("signal " << signal);
    REQUIRE(caught);  // the output was seen being written
    CHECK(WIFSIGNALED(status));
    if (WIFSIGNALED(status)) CHECK(WTERMSIG(status) == signal);
    CHECK(!has_temporary(dir));
    for (const auto& name : old_files) CHECK(dir.read(name) == "an earlier result\n");
}
