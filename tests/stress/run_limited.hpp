#pragma once
// Running a program with a time limit: a run that outlives it is killed, so
// a hang becomes a result instead of a stuck test.

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace gpdr::stress {

struct LimitedRun {
    bool timed_out = false;
    int exit_status = -1;  // when it exited
    int signal = 0;        // when a signal ended it (other than our kill)
    double seconds = 0;
};

// Runs `arguments` (the program first) in `folder`, its standard output and
// error going to the files named, its input from /dev/null.
inline LimitedRun run_limited(const std::vector<std::string>& arguments, const std::string& folder,
                              const std::string& out_path, const std::string& err_path,
                              double time_limit) {
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec.  The child dies
        // with its parent, so a killed test or script leaves no hung mesher.
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        const int in = open("/dev/null", O_RDONLY);
        const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in < 0 || out < 0 || err < 0 || chdir(folder.c_str()) != 0) _exit(127);
        dup2(in, 0);
        dup2(out, 1);
        dup2(err, 2);
        execv(argv[0], argv.data());
        _exit(127);
    }
    LimitedRun run;
    if (pid < 0) return run;
    int status = 0;
    auto pause = std::chrono::microseconds(200);
    for (;;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        run.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (done == pid) break;
        if (run.seconds > time_limit) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            run.timed_out = true;
            return run;
        }
        std::this_thread::sleep_for(pause);
        if (pause < std::chrono::milliseconds(5)) pause *= 2;
    }
    if (WIFEXITED(status)) run.exit_status = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
    return run;
}

}  // namespace gpdr::stress
