// Triangle's classic sample inputs (../shared/samples) all read without
// error, and read back identically after a write.  Skipped, with a warning,
// where that folder is absent.

#include <catch2/catch.hpp>

#include <filesystem>

#include <gpdr/io.hpp>

#include "io/io_test_support.hpp"

using namespace gpdr;

TEST_CASE("every classic sample reads without error", "[io][samples]") {
    const auto samples = test::shared_samples();
    if (samples.empty()) {
        WARN("SKIPPED: ../shared/samples is absent");
        return;
    }
    std::size_t read = 0;
    for (const auto& entry : std::filesystem::directory_iterator(samples)) {
        const auto path = entry.path();
        const auto ext = path.extension().string();
        if (ext != ".node" && ext != ".poly") continue;
        INFO(path.string());
        test::WarningLog log;
        test::TempDir dir;
        const auto out = (dir / ("copy" + ext)).string();
        if (ext == ".node") {
            const auto r = io::read_node(path.string(), log.sink());
            CHECK(r.data.size() > 0);
            io::OutputTransaction tx;
            io::write_node(tx, out, r.data, {r.base, true, "gpdr test"});
            tx.commit();
            const auto back = io::read_node(out, ignore_warning);
            CHECK(back.base == r.base);
            CHECK(test::same_bits(back.data.xy, r.data.xy));
            CHECK(test::same_bits(back.data.attributes, r.data.attributes));
            CHECK(back.data.markers == r.data.markers);
        } else {
            const auto r = io::read_poly(path.string(), log.sink());
            CHECK(r.data.nodes.size() > 0);
            io::OutputTransaction tx;
            io::write_poly(tx, out, r.data, {r.base, true, "gpdr test"});
            if (r.data.nodes_from_node_file)
                io::write_node(tx, (dir / "copy.node").string(), r.data.nodes,
                               {r.base, true, "gpdr test"});
            tx.commit();
            const auto back = io::read_poly(out, ignore_warning);
            CHECK(back.base == r.base);
            CHECK(test::same_bits(back.data.nodes.xy, r.data.nodes.xy));
            CHECK(back.data.segments.endpoints == r.data.segments.endpoints);
            CHECK(back.data.segments.markers == r.data.segments.markers);
            CHECK(test::same_bits(back.data.holes, r.data.holes));
            CHECK(back.data.regions.size() == r.data.regions.size());
        }
        for (const auto& w : log.warnings) WARN(w.file << ":" << w.line << ": " << w.message);
        ++read;
    }
    CHECK(read >= 1);
}
