#pragma once
// Support for CLI tests: run the built gpdr in a scratch folder and look at
// its exit status, its output streams and the files it left.

#include <sys/wait.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace gpdr::test {

namespace fs = std::filesystem;

// A scratch folder, removed with everything in it when the test ends.
class TempDir {
public:
    TempDir() {
        std::random_device rd;
        for (;;) {
            path_ = fs::temp_directory_path() / ("gpdr-test-" + std::to_string(rd()));
            if (fs::create_directory(path_)) break;
        }
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const fs::path& path() const { return path_; }
    fs::path operator/(const std::string& name) const { return path_ / name; }

    void write(const std::string& name, const std::string& contents) const {
        std::ofstream(path_ / name, std::ios::binary) << contents;
    }
    bool exists(const std::string& name) const { return fs::exists(path_ / name); }
    std::string read(const std::string& name) const { return slurp(path_ / name); }

    // Names of the regular files in the folder, sorted.
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(path_))
            if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    static std::string slurp(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }

private:
    fs::path path_;
};

struct RunResult {
    int status = -1;  // exit status, or -1 if killed by a signal
    std::string out;
    std::string err;
};

// Runs `program <args>` with `dir` as the working folder.  `args` is passed
// to the shell as written, so quote names with blanks.
inline RunResult run_program(const TempDir& dir, const fs::path& program, const std::string& args) {
    const auto out = dir / ".stdout";
    const auto err = dir / ".stderr";
    const std::string command = "cd '" + dir.path().string() + "' && '" + program.string() + "' " +
                                args + " >'" + out.string() + "' 2>'" + err.string() +
                                "' </dev/null";
    const int raw = std::system(command.c_str());
    RunResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = TempDir::slurp(out);
    r.err = TempDir::slurp(err);
    fs::remove(out);
    fs::remove(err);
    return r;
}

// Runs the built gpdr.
inline RunResult run_gpdr(const TempDir& dir, const std::string& args) {
    return run_program(dir, GPDR_EXE, args);
}

inline fs::path source_dir() { return GPDR_SOURCE_DIR; }
inline fs::path project_samples() { return source_dir() / "poly-samples"; }

// The tests' inputs in tests/data (made by scripts/make-samples.py): PSLGs
// with holes, regions, attributes and markers, and .node point sets.
inline fs::path test_data() { return source_dir() / "tests" / "data"; }

}  // namespace gpdr::test
