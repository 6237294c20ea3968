// All-or-nothing output: commit() renames every file into place; a
// transaction abandoned by an exception leaves the earlier files untouched
// and no temporaries; unwritable targets give OutputError naming the file.

#include <catch2/catch.hpp>

#include <csignal>
#include <stdexcept>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gpdr/errors.hpp>
#include <gpdr/io.hpp>

#include "io/io_test_support.hpp"

using namespace gpdr;
using gpdr::test::TempDir;

namespace {

NodeSet tiny_nodes() {
    NodeSet n;
    n.xy = {0, 0, 1, 0, 0, 1};
    return n;
}

EleSet tiny_ele() {
    EleSet e;
    e.corners = {0, 1, 2};
    return e;
}

}  // namespace

TEST_CASE("commit renames all files into place and leaves no temporaries", "[io][atomic]") {
    TempDir dir;
    dir.write("m.node", "old");
    io::OutputTransaction tx;
    io::write_node(tx, (dir / "m.node").string(), tiny_nodes(), {1, true, "gpdr m"});
    io::write_ele(tx, (dir / "m.ele").string(), tiny_ele(), {1, true, "gpdr m"});
    // Before commit: the old file is intact, the new one not yet visible.
    CHECK(dir.read("m.node") == "old");
    CHECK_FALSE(dir.exists("m.ele"));
    tx.commit();
    CHECK(dir.files() == std::vector<std::string>{"m.ele", "m.node"});
    CHECK(dir.read("m.node").rfind("3  2  0  0\n", 0) == 0);
    CHECK(tx.files() ==
          std::vector<std::string>{(dir / "m.node").string(), (dir / "m.ele").string()});
}

TEST_CASE("a failed transaction keeps earlier files and removes its temporaries", "[io][atomic]") {
    TempDir dir;
    dir.write("m.node", "earlier result");
    try {
        io::OutputTransaction tx;
        io::write_node(tx, (dir / "m.node").string(), tiny_nodes(), {1, true, "gpdr m"});
        io::write_ele(tx, (dir / "m.ele").string(), tiny_ele(), {1, true, "gpdr m"});
        throw std::runtime_error("the mesher failed");
    } catch (const std::runtime_error&) {}
    CHECK(dir.files() == std::vector<std::string>{"m.node"});
    CHECK(dir.read("m.node") == "earlier result");
}

TEST_CASE("inconsistent data fails before anything is renamed", "[io][atomic]") {
    TempDir dir;
    EleSet bad = tiny_ele();
    bad.attribute_count = 1;  // but no attribute values
    try {
        io::OutputTransaction tx;
        io::write_node(tx, (dir / "m.node").string(), tiny_nodes(), {1, true, "gpdr m"});
        io::write_ele(tx, (dir / "m.ele").string(), bad, {1, true, "gpdr m"});
        tx.commit();
        FAIL("no error");
    } catch (const OutputError& e) {
        CHECK_THAT(e.what(), Catch::Contains("m.ele"));
    }
    CHECK(dir.files().empty());
}

TEST_CASE("an unwritable target gives OutputError naming the file", "[io][atomic]") {
    TempDir dir;
    const auto target = (dir / "no-such-folder" / "m.node").string();
    io::OutputTransaction tx;
    try {
        io::write_node(tx, target, tiny_nodes(), {1, true, "gpdr m"});
        FAIL("no error");
    } catch (const OutputError& e) {
        CHECK_THAT(e.what(), Catch::Contains(target));
    }
    CHECK(dir.files().empty());
}

TEST_CASE("a write error (file too large) gives OutputError naming the file", "[io][atomic]") {
    // A file-size limit makes write() fail with EFBIG like a full disk fails
    // with ENOSPC.  Run in a child process so the limit stays there.
    TempDir dir;
    const auto target = (dir / "big.node").string();
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        struct rlimit limit {
            4096, 4096
        };
        ::setrlimit(RLIMIT_FSIZE, &limit);
        NodeSet many;
        many.xy.assign(20000, 0.5);
        int code = 1;
        try {
            io::OutputTransaction tx;
            io::write_node(tx, target, many, {1, true, "gpdr big"});
            tx.commit();
        } catch (const OutputError& e) {
            code = std::string(e.what()).find(target) != std::string::npos ? 0 : 2;
        } catch (...) {
            code = 3;
        }
        ::_exit(code);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    CHECK(dir.files().empty());
}
