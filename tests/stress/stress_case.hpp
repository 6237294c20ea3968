#pragma once
// One stress case: write a PSLG, mesh it with gpdr or Triangle under a time
// limit, read back what was written and check it with check_mesh.

#include <string>
#include <vector>

#include <gpdr/files.hpp>

namespace gpdr::stress {

enum class Verdict {
    right,
    wrong,   // exited 0, but the mesh fails the independent check
    failed,  // a non-zero exit status (a clean error counts: the inputs are valid), a crash
    hung,    // still running at the time limit, and killed
};

const char* verdict_name(Verdict verdict);

struct Mesher {
    std::string path;
    bool gpdr = true;  // gpdr takes -jN and reports triangles left by precision; Triangle does not
};

struct RunSpec {
    std::string switches;  // one word, such as "-pq20"; C (and A with regions) are added
    int threads = 0;       // gpdr's -jN; 0: not given
    double time_limit = 10;
    bool strict_angles = false;  // no excuse for angles opposite edges spanning input angles
};

struct Outcome {
    Verdict verdict = Verdict::right;
    std::string detail;  // why, when not right
    double seconds = 0;
};

// The command line run_case uses, without the program and the input name.
std::vector<std::string> mesher_switches(const Mesher& mesher, const RunSpec& spec,
                                         const PolyFile& input);

// Writes `input` to folder/in.poly (headed by `comment`), runs the mesher
// there and checks its in.1.* files.
Outcome run_case(const Mesher& mesher, const RunSpec& spec, const PolyFile& input,
                 const std::string& comment, const std::string& folder);

}  // namespace gpdr::stress
