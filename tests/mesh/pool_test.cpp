// Pool and store: slots are reused through the free list with a new
// generation, pools claim distinct chunks, spare slots survive a pool.

#include <catch2/catch.hpp>

#include <memory>
#include <set>
#include <thread>
#include <vector>

#include <gpdr/errors.hpp>

#include "mesh/mesh.hpp"
#include "mesh/pool.hpp"
#include "mesh/traverse.hpp"

using namespace gpdr::mesh;

TEST_CASE("EdgeRef packs a triangle id and an edge index", "[mesh][ids]") {
    const EdgeRef e(TriangleId{123456}, 2);
    CHECK(e.triangle() == TriangleId{123456});
    CHECK(e.edge() == 2);
    CHECK(e.next() == EdgeRef(TriangleId{123456}, 0));
    CHECK(e.prev() == EdgeRef(TriangleId{123456}, 1));
    CHECK(EdgeRef::none().is_none());
    CHECK_FALSE(EdgeRef(TriangleId{max_triangles - 1}, 2).is_none());
    CHECK(EdgeRef::from_bits(e.bits()) == e);
}

TEST_CASE("a destroyed slot is reused with a new generation", "[mesh][pool]") {
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    Pool pool(mesh);
    const TriangleId a = pool.create(VertexId{0}, VertexId{1}, VertexId{2});
    const TriangleId b = pool.create(VertexId{0}, VertexId{1}, VertexId{2});
    CHECK(a != b);
    CHECK(mesh.count_triangles() == 2);
    const std::uint32_t generation = mesh.triangle(a).generation;
    pool.destroy(a);
    CHECK_FALSE(mesh.triangle(a).live());
    CHECK(mesh.triangle(a).generation == generation + 1);
    CHECK(mesh.count_triangles() == 1);
    const TriangleId c = pool.create(VertexId{2}, VertexId{0}, VertexId{1});
    CHECK(c == a);
    CHECK(mesh.triangle(c).live());
    CHECK(mesh.triangle(c).generation == generation + 1);
    CHECK(mesh.triangle(c).v[0] == VertexId{2});
}

TEST_CASE("pools claim distinct chunks and hand spare slots on", "[mesh][pool]") {
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    std::set<std::uint32_t> ids;
    TriangleId freed = no_triangle;
    {
        Pool p1(mesh);
        Pool p2(mesh);
        for (int i = 0; i < 100; ++i) {
            CHECK(ids.insert(index(p1.create(VertexId{0}, VertexId{1}, VertexId{2}))).second);
            CHECK(ids.insert(index(p2.create(VertexId{0}, VertexId{1}, VertexId{2}))).second);
        }
        CHECK(mesh.triangle_end() == 2 * Mesh::TriangleTable::chunk_size);
        freed = TriangleId{*ids.begin()};
        p1.destroy(freed);
    }
    CHECK(mesh.count_triangles() == 199);
    // A new pool starts from what the finished ones gave back: no new chunk.
    Pool p3(mesh);
    std::set<std::uint32_t> again;
    for (int i = 0; i < 1000; ++i)
        again.insert(index(p3.create(VertexId{0}, VertexId{1}, VertexId{2})));
    CHECK(mesh.triangle_end() == 2 * Mesh::TriangleTable::chunk_size);
    CHECK(mesh.count_triangles() == 1199);
    CHECK(again.size() == 1000);
}

TEST_CASE("a pool fills more than one chunk", "[mesh][pool]") {
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    Pool pool(mesh);
    const std::uint32_t n = Mesh::TriangleTable::chunk_size + 10;
    for (std::uint32_t i = 0; i < n; ++i) pool.create(VertexId{0}, VertexId{1}, VertexId{2});
    CHECK(mesh.count_triangles() == n);
    CHECK(mesh.triangle_end() == 2 * Mesh::TriangleTable::chunk_size);
    const TriangleId last{n - 1};
    CHECK(mesh.triangle(last).live());
}

TEST_CASE("pool vertices get consecutive ids and the unused block is returned", "[mesh][pool]") {
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    {
        Pool pool(mesh, 64);
        const VertexId v = pool.new_vertex({0.25, 0.25}, VertexKind::free);
        const VertexId w = pool.new_vertex({0.5, 0.25}, VertexKind::segment);
        CHECK(index(v) == 3);
        CHECK(index(w) == 4);
        CHECK(mesh.point(w) == Point{0.5, 0.25});
        CHECK(mesh.kind(w) == VertexKind::segment);
        CHECK(mesh.vertex_end() == 3 + 64);
    }
    CHECK(mesh.vertex_end() == 5);
    CHECK(mesh.add_vertex({9, 9}, VertexKind::input) == VertexId{5});
}

TEST_CASE("a moved mesh keeps its triangles and vertices", "[mesh][pool]") {
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    {
        Pool pool(mesh);
        pool.create(VertexId{0}, VertexId{1}, VertexId{2});
    }
    Mesh moved(std::move(mesh));
    CHECK(moved.count_triangles() == 1);
    CHECK(moved.point(VertexId{1}) == Point{1, 0});
    Mesh assigned;
    assigned = std::move(moved);
    CHECK(assigned.count_triangles() == 1);
    Pool pool(assigned);
    pool.create(VertexId{0}, VertexId{1}, VertexId{2});
    CHECK(assigned.count_triangles() == 2);
}

TEST_CASE("pools on several threads allocate in one mesh at once", "[mesh][pool][threads]") {
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    constexpr int threads = 4;
    constexpr std::uint32_t per_thread = 150000;  // more than two chunks each
    std::vector<std::vector<TriangleId>> made(threads);
    std::vector<std::vector<VertexId>> vertices(threads);
    {
        std::vector<std::thread> workers;
        for (int w = 0; w < threads; ++w)
            workers.emplace_back([&, w] {
                Pool pool(mesh, 100);
                for (std::uint32_t i = 0; i < per_thread; ++i) {
                    const TriangleId t = pool.create(VertexId{0}, VertexId{1}, VertexId{2});
                    mesh.triangle(t).region = static_cast<std::uint16_t>(w);
                    made[static_cast<std::size_t>(w)].push_back(t);
                    if (i % 3 == 0) {
                        pool.destroy(t);
                        made[static_cast<std::size_t>(w)].pop_back();
                    }
                    if (i % 1000 == 0)
                        vertices[static_cast<std::size_t>(w)].push_back(
                            pool.new_vertex({double(w), double(i)}, VertexKind::free));
                }
            });
        for (auto& t : workers) t.join();
    }
    std::set<std::uint32_t> ids;
    for (int w = 0; w < threads; ++w)
        for (TriangleId t : made[static_cast<std::size_t>(w)]) {
            CHECK(ids.insert(index(t)).second);
            CHECK(mesh.triangle(t).region == w);
        }
    CHECK(mesh.count_triangles() == ids.size());
    for (int w = 0; w < threads; ++w)
        for (VertexId v : vertices[static_cast<std::size_t>(w)])
            CHECK(mesh.point(v).x == double(w));
}

TEST_CASE("destroying a dead triangle is refused", "[mesh][pool]") {
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    Pool pool(mesh);
    const TriangleId t = pool.create(VertexId{0}, VertexId{1}, VertexId{2});
    pool.destroy(t);
    // A bug in gpdr, not the input's fault: its own error type.
    CHECK_THROWS_AS(pool.destroy(t), gpdr::InternalError);
    // The free list is intact: the slot comes back once.
    CHECK(pool.create(VertexId{0}, VertexId{1}, VertexId{2}) == t);
    CHECK(pool.create(VertexId{0}, VertexId{1}, VertexId{2}) != t);
}

TEST_CASE("the unused ends of lanes' chunks are known and passed over", "[mesh][pool]") {
    constexpr std::uint32_t chunk = Mesh::TriangleTable::chunk_size;
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    const Lane base = Lane::first(mesh, 2);
    std::vector<TriangleId> made;
    VertexId added = no_vertex;
    {
        Lane second = base;
        second.index = 1;
        Pool a(mesh, base), b(mesh, second);
        for (int i = 0; i < 30; ++i)
            made.push_back(a.create(VertexId{0}, VertexId{1}, VertexId{2}));
        for (int i = 0; i < 5; ++i) made.push_back(b.create(VertexId{0}, VertexId{1}, VertexId{2}));
        a.new_vertex({0.25, 0.25}, VertexKind::free);
        added = b.new_vertex({0.5, 0.25}, VertexKind::free);
        // While the pools hold their chunks' ends, the whole chunks count.
        CHECK(mesh.triangle_chunk_used(0) == chunk);
        CHECK(mesh.triangle_chunk_used(1) == chunk);
    }
    // Lane 0 took triangle chunk 0 and vertex chunk 1 (chunk 0 holds the
    // input); lane 1 chunks 1 and 2.
    CHECK(mesh.triangle_chunk_used(0) == 30);
    CHECK(mesh.triangle_chunk_used(1) == 5);
    CHECK(mesh.triangle_chunk_used(2) == chunk);  // never claimed: unknown
    CHECK(index(added) == 2 * chunk);
    CHECK(mesh.vertex_chunk_used(1) == 1);
    // Lane 1's vertex chunk is the last: its end goes back to the mesh.
    CHECK(mesh.vertex_end() == index(added) + 1);
    CHECK(mesh.count_triangles() == 35);
    std::vector<TriangleId> seen;
    for_each_triangle(mesh, [&](TriangleId t, const Triangle&) { seen.push_back(t); });
    CHECK(seen == made);

    // A pool that takes a given-back end uses it again: it counts again.
    Pool again(mesh);
    const TriangleId t = again.create(VertexId{0}, VertexId{1}, VertexId{2});
    CHECK(mesh.triangle_chunk_used(index(t) >> Mesh::triangle_chunk_bits) == chunk);
}

TEST_CASE("the next round's lanes claim the chunks the last one left unclaimed", "[mesh][pool]") {
    constexpr std::uint32_t chunk = Mesh::TriangleTable::chunk_size;
    Mesh mesh;
    mesh.add_vertices(std::vector<Point>{{0, 0}, {1, 0}, {0, 1}}, VertexKind::input);
    const auto make = [](Pool& pool, std::uint32_t n) {
        for (std::uint32_t i = 0; i < n; ++i) pool.create(VertexId{0}, VertexId{1}, VertexId{2});
    };
    // Round 1, four lanes: lane 0 fills three chunks (places 0, 4, 8), the
    // others one each (places 1, 2, 3): chunks 5, 6, 7 stay holes.
    std::vector<std::unique_ptr<Pool>> lanes;
    const Lane first = Lane::first(mesh, 4);
    CHECK(first.triangle_holes.empty());
    for (std::uint32_t k = 0; k < 4; ++k) {
        Lane lane = first;
        lane.index = k;
        lanes.push_back(std::make_unique<Pool>(mesh, lane));
    }
    make(*lanes[0], 3 * chunk);
    for (std::uint32_t k = 1; k < 4; ++k) make(*lanes[k], chunk);
    CHECK(mesh.triangle_end() == 9 * chunk);
    // Round 2, three lanes: the holes first, then chunks 9, 10, ...
    const Lane second = Lane::first(mesh, 3);
    CHECK(std::vector<std::uint32_t>(second.triangle_holes.begin(), second.triangle_holes.end()) ==
          std::vector<std::uint32_t>{5, 6, 7});
    for (std::uint32_t k = 0; k < 3; ++k) {
        Lane lane = second;
        lane.index = k;
        lanes[k]->move_to_lane(lane);
    }
    TriangleId at_hole = lanes[1]->create(VertexId{0}, VertexId{1}, VertexId{2});
    CHECK(index(at_hole) == 6 * chunk);  // lane 1's first place: the second hole
    make(*lanes[1], chunk);              // its next place, 4, is chunk 9 + (4 - 3)
    CHECK(mesh.has_triangle_chunk(10));
    CHECK_FALSE(mesh.has_triangle_chunk(9));
    // Round 3: the holes left are chunks 5, 7 and 9.
    const Lane third = Lane::first(mesh, 1);
    CHECK(std::vector<std::uint32_t>(third.triangle_holes.begin(), third.triangle_holes.end()) ==
          std::vector<std::uint32_t>{5, 7, 9});
}
