// The sample inputs in tests/data all read without error, and read back
// identically after a write; between them they use every optional part of
// the .node and .poly formats.

#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include <gpdr/io.hpp>

#include "io/io_test_support.hpp"

using namespace gpdr;

TEST_CASE("every test data sample reads without error", "[io][samples]") {
    const auto samples = test::test_data();
    std::size_t read = 0;
    std::set<std::string> seen;  // the optional parts of the formats met so far
    const auto note = [&](const NodeSet& nodes, int base) {
        if (nodes.attribute_count > 0) seen.insert("vertex attributes");
        seen.insert(nodes.has_markers() ? "vertex markers" : "no vertex markers");
        if (base == 0) seen.insert("numbered from 0");
    };
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
            seen.insert(".node");
            note(r.data, r.base);
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
            seen.insert(".poly");
            note(r.data.nodes, r.base);
            if (r.data.nodes_from_node_file) seen.insert("vertices from the .node");
            seen.insert(r.data.segments.has_markers() ? "segment markers" : "no segment markers");
            if (!r.data.holes.empty()) seen.insert("holes");
            if (!r.data.regions.empty()) seen.insert("regions");
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
    for (const char* part : {".node", ".poly", "vertex attributes", "vertex markers",
                             "no vertex markers", "numbered from 0", "vertices from the .node",
                             "segment markers", "no segment markers", "holes", "regions"}) {
        INFO(part);
        CHECK(seen.count(part) == 1);
    }
}
