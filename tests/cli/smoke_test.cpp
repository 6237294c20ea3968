// The built gpdr starts, and -h answers with exit status 0.
#include <catch2/catch.hpp>

#include "cli/cli_support.hpp"

using namespace gpdr::test;

TEST_CASE("gpdr -h prints help and exits 0", "[cli]") {
    TempDir dir;
    const auto r = run_gpdr(dir, "-h");
    CHECK(r.status == 0);
    CHECK(r.out.find("-p") != std::string::npos);
}
