#pragma once
// Bad inputs and the error each must give: gpdr::InputError with this file,
// line and a reason containing the given text.  Shared by the reader tests
// (tests/io) and the CLI tests, which write `files` into a scratch folder and
// run `gpdr <input>` there (the input's extension picks the readers: .node,
// .poly, .ele = .node + .ele, .area = .node + .ele + .area).

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace gpdr::test {

struct BadInputCase {
    std::string name;
    std::vector<std::pair<std::string, std::string>> files;  // (file name, contents) to create
    std::string input;   // the file gpdr is given
    std::string file;    // where the error is expected
    std::size_t line;    // 0: the file as a whole
    std::string reason_contains;
};

inline const std::string good_node = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n";

inline const std::vector<BadInputCase>& bad_input_cases() {
    static const std::vector<BadInputCase> cases = {
        // ---- any file
        {"missing file", {}, "missing.node", "missing.node", 0, "cannot read"},
        {"empty file", {{"bad.node", ""}}, "bad.node", "bad.node", 1, "no data"},
        {"only comments", {{"bad.node", "# nothing here\n\n   # still nothing\n"}}, "bad.node",
         "bad.node", 4, "no data"},
        // ---- .node header
        {"negative vertex count", {{"bad.node", "-3 2 0 0\n1 0 0\n"}}, "bad.node", "bad.node", 1,
         "negative"},
        {"absurd vertex count", {{"bad.node", "# big\n1000000000 2 0 0\n1 0 0\n2 1 0\n"}},
         "bad.node", "bad.node", 2, "impossible"},
        {"non-numeric vertex count", {{"bad.node", "four 2 0 0\n"}}, "bad.node", "bad.node", 1,
         "not an integer"},
        {"dimension 3", {{"bad.node", "3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"}}, "bad.node",
         "bad.node", 1, "dimension 3"},
        {"marker count 2", {{"bad.node", "3 2 0 2\n1 0 0\n2 1 0\n3 0 1\n"}}, "bad.node",
         "bad.node", 1, "must be 0 or 1"},
        {"negative attribute count", {{"bad.node", "3 2 -1 0\n1 0 0\n2 1 0\n3 0 1\n"}}, "bad.node",
         "bad.node", 1, "negative"},
        {"absurd attribute count", {{"bad.node", "3 2 100000000 0\n1 0 0\n2 1 0\n3 0 1\n"}},
         "bad.node", "bad.node", 1, "impossible"},
        {"fractional count", {{"bad.node", "3.5 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"}}, "bad.node",
         "bad.node", 1, "not an integer"},
        // ---- .node vertices
        {"truncated vertex list", {{"bad.node", "4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"}}, "bad.node",
         "bad.node", 5, "expected 4 vertices, found 3"},
        {"truncated vertex list, no final newline", {{"bad.node", "4 2 0 0\n1 0 0\n2 1 0\n3 0 1"}},
         "bad.node", "bad.node", 5, "expected 4 vertices, found 3"},
        {"non-numeric coordinate", {{"bad.node", "3 2 0 0\n1 0 0\n2 abc 0\n3 0 1\n"}}, "bad.node",
         "bad.node", 3, "not a number"},
        {"number with trailing text", {{"bad.node", "3 2 0 0\n1 0 0\n2 1.5abc 0\n3 0 1\n"}},
         "bad.node", "bad.node", 3, "not a number"},
        {"NaN coordinate", {{"bad.node", "3 2 0 0\n1 0 0\n2 1 nan\n3 0 1\n"}}, "bad.node",
         "bad.node", 3, "not finite"},
        {"infinite coordinate", {{"bad.node", "3 2 0 0\n1 0 0\n2 -inf 0\n3 0 1\n"}}, "bad.node",
         "bad.node", 3, "not finite"},
        {"overflowing coordinate", {{"bad.node", "3 2 0 0\n1 0 0\n2 1e999 0\n3 0 1\n"}},
         "bad.node", "bad.node", 3, "not finite"},
        {"missing y coordinate", {{"bad.node", "3 2 0 0\n1 0 0\n2 1\n3 0 1\n"}}, "bad.node",
         "bad.node", 3, "y coordinate is missing"},
        {"non-numeric attribute", {{"bad.node", "3 2 1 0\n1 0 0 5\n2 1 0 x\n3 0 1 5\n"}},
         "bad.node", "bad.node", 3, "not a number"},
        {"fractional vertex number", {{"bad.node", "3 2 0 0\n1 0 0\n2.5 1 0\n3 0 1\n"}},
         "bad.node", "bad.node", 3, "not an integer"},
        {"fractional marker", {{"bad.node", "3 2 0 1\n1 0 0 1\n2 1 0 0.5\n3 0 1 1\n"}},
         "bad.node", "bad.node", 3, "not an integer"},
        // ---- .poly
        {"segment endpoint out of range",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 9\n3 3 1\n0\n"}}, "bad.poly",
         "bad.poly", 7, "out of range"},
        {"segment endpoint off the base",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 0\n0\n"}},
         "bad.poly", "bad.poly", 8, "out of range"},
        {"segment endpoint past the end, 0-based",
         {{"bad.poly", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 3\n0\n"}}, "bad.poly", "bad.poly",
         6, "numbered 0 to 2"},
        {"segment without second endpoint",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n2 2\n0\n"}}, "bad.poly",
         "bad.poly", 7, "segment endpoint is missing"},
        {"segment marker count 3",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 3\n1 1 2\n0\n"}}, "bad.poly", "bad.poly",
         5, "must be 0 or 1"},
        {"missing segment header", {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"}}, "bad.poly",
         "bad.poly", 5, "segment header"},
        {"truncated segment list",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n"}}, "bad.poly",
         "bad.poly", 8, "expected 3 segments, found 2"},
        {"missing hole count",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2\n"}}, "bad.poly", "bad.poly", 7,
         "number of holes"},
        {"hole without y",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n1\n1 0.5\n"}}, "bad.poly", "bad.poly",
         7, "hole y coordinate is missing"},
        {"truncated hole list",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n2\n1 0.2 0.2\n"}}, "bad.poly",
         "bad.poly", 8, "expected 2 holes, found 1"},
        {"region without attribute",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1\n1 0.2 0.2\n"}}, "bad.poly",
         "bad.poly", 8, "region attribute is missing"},
        {"region without y",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1\n1 0.2\n"}}, "bad.poly",
         "bad.poly", 8, "region y coordinate is missing"},
        {"negative region count",
         {{"bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n-2\n"}}, "bad.poly", "bad.poly", 7,
         "negative"},
        {"poly needing a missing node file", {{"bad.poly", "0 2 0 0\n0 0\n0\n"}}, "bad.poly",
         "bad.node", 0, "vertex count 0"},
        {"poly taking a bad node file",
         {{"bad.poly", "0 2 0 0\n1 0\n1 1 2\n0\n"}, {"bad.node", "3 2 0 0\n1 0 0\n2 zero 0\n3 0 1\n"}},
         "bad.poly", "bad.node", 3, "not a number"},
        {"poly segment past the node file",
         {{"bad.poly", "0 2 0 0\n1 0\n1 1 5\n0\n"}, {"bad.node", good_node}}, "bad.poly",
         "bad.poly", 3, "numbered 1 to 4"},
        // ---- .ele (gpdr -r)
        {"ele with 4 nodes per triangle", {{"bad.node", good_node}, {"bad.ele", "1 4 0\n1 1 2 3 4\n"}},
         "bad.ele", "bad.ele", 1, "must be 3 or 6"},
        {"ele corner out of range",
         {{"bad.node", good_node}, {"bad.ele", "2 3 0\n1 1 2 3\n2 1 3 7\n"}}, "bad.ele", "bad.ele",
         3, "out of range"},
        {"ele corner 0 in a 1-based run",
         {{"bad.node", good_node}, {"bad.ele", "2 3 0\n1 1 2 3\n2 0 1 3\n"}}, "bad.ele", "bad.ele",
         3, "numbered 1 to 4"},
        {"ele fractional corner", {{"bad.node", good_node}, {"bad.ele", "1 3 0\n1 1 2.5 3\n"}},
         "bad.ele", "bad.ele", 2, "not an integer"},
        {"ele missing corner", {{"bad.node", good_node}, {"bad.ele", "1 3 0\n1 1 2\n"}}, "bad.ele",
         "bad.ele", 2, "triangle vertex is missing"},
        {"ele truncated", {{"bad.node", good_node}, {"bad.ele", "3 3 0\n1 1 2 3\n2 1 3 4\n"}},
         "bad.ele", "bad.ele", 4, "expected 3 triangles, found 2"},
        {"ele absurd count", {{"bad.node", good_node}, {"bad.ele", "99999999999 3 0\n1 1 2 3\n"}},
         "bad.ele", "bad.ele", 1, "impossible"},
        {"ele with a bad node file", {{"bad.node", "4 2 0 0\n1 0 0\n"}, {"bad.ele", "1 3 0\n1 1 2 3\n"}},
         "bad.ele", "bad.node", 3, "expected 4 vertices, found 1"},
        // ---- .area (gpdr -ra)
        {"area count disagrees with ele",
         {{"bad.node", good_node}, {"bad.ele", "2 3 0\n1 1 2 3\n2 1 3 4\n"}, {"bad.area", "3\n1 0.1\n2 0.1\n3 0.1\n"}},
         "bad.area", "bad.area", 1, "the .ele file has 2"},
        {"area not a number",
         {{"bad.node", good_node}, {"bad.ele", "2 3 0\n1 1 2 3\n2 1 3 4\n"}, {"bad.area", "2\n1 0.1\n2 tiny\n"}},
         "bad.area", "bad.area", 3, "not a number"},
        {"area truncated",
         {{"bad.node", good_node}, {"bad.ele", "2 3 0\n1 1 2 3\n2 1 3 4\n"}, {"bad.area", "2\n1 0.1\n"}},
         "bad.area", "bad.area", 3, "expected 2 area bounds, found 1"},
    };
    return cases;
}

}  // namespace gpdr::test
