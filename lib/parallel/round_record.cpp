// The rounds' record and the simulation of ranks that reads it (see
// round_record.hpp).

#include "parallel/round_record.hpp"

#include <algorithm>
#include <numeric>

#include "mesh/traverse.hpp"
#include "parallel/morton.hpp"

namespace gpdr::parallel {

namespace {

constexpr std::uint32_t none = 0xFFFFFFFFu;

}  // namespace

std::uint64_t Cell::morton() const {
    const int shift = max_level - level;
    return parallel::morton(ix << shift, iy << shift);
}

namespace {

// Every leaf of the tree in Morton order, each with its triangles, and each
// node's index among them (none for internal and shadow nodes).
RecordedRound record_leaves(const mesh::Mesh& mesh, const Quadtree& tree,
                            std::vector<std::uint32_t>& index_of) {
    std::vector<NodeId> leaves;
    tree.leaves(leaves);
    std::vector<std::pair<std::uint64_t, NodeId>> order;
    order.reserve(leaves.size());
    for (const NodeId l : leaves) {
        const Node& n = tree.node(l);
        order.emplace_back(Cell{n.level, n.ix, n.iy}.morton(), l);
    }
    std::sort(order.begin(), order.end());
    RecordedRound r;
    r.leaves.resize(order.size());
    index_of.assign(tree.node_end(), none);
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Node& n = tree.node(order[i].second);
        r.leaves[i].cell = Cell{n.level, n.ix, n.iy};
        index_of[order[i].second] = static_cast<std::uint32_t>(i);
    }
    // Each triangle's leaf by its centroid.  Consecutive ids are mostly
    // neighbours (a lane's pool hands out slots in order), so the leaf of the
    // last one is tried first.
    NodeId last = no_node;
    Square square{0, 0, 0};
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId, const mesh::Triangle& t) {
        const Point& a = mesh.point(t.v[0]);
        const Point& b = mesh.point(t.v[1]);
        const Point& c = mesh.point(t.v[2]);
        const Point centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
        if (last == no_node || !square.contains(centroid)) {
            last = tree.leaf_at(centroid);
            square = tree.square(last);
        }
        ++r.leaves[index_of[last]].triangles;
    });
    return r;
}

}  // namespace

RecordedRound record_round(const mesh::Mesh& mesh, const Quadtree& tree,
                           const std::vector<NodeId>& round,
                           const std::function<const std::vector<NodeId>&(std::size_t)>& zone) {
    std::vector<std::uint32_t> index_of;
    RecordedRound r = record_leaves(mesh, tree, index_of);
    r.triangle_end = mesh.triangle_end();
    r.vertex_end = mesh.vertex_end();
    r.runs.resize(round.size());
    for (std::size_t i = 0; i < round.size(); ++i) {
        RecordedRun& run = r.runs[i];
        run.leaf = index_of[round[i]];
        for (const NodeId z : zone(i)) run.zone.push_back(index_of[z]);
        std::sort(run.zone.begin(), run.zone.end());
    }
    return r;
}

std::vector<std::uint32_t> morton_owners(const RecordedRound& round, unsigned ranks) {
    std::uint64_t total = 0;
    for (const RecordedLeaf& l : round.leaves) total += l.triangles;
    std::vector<std::uint32_t> owner(round.leaves.size(), 0);
    if (ranks <= 1 || total == 0) return owner;
    // The leaf's middle triangle, 2 * (before + triangles / 2), against the
    // ranks' equal shares of 2 * total: integers, so the same on any machine.
    std::uint64_t before = 0;
    for (std::size_t i = 0; i < round.leaves.size(); ++i) {
        const std::uint64_t middle = 2 * before + round.leaves[i].triangles;
        owner[i] = static_cast<std::uint32_t>(
            std::min<std::uint64_t>(ranks - 1, middle * ranks / (2 * total)));
        before += round.leaves[i].triangles;
    }
    return owner;
}

std::vector<RankRound> simulate_ranks(const ScheduleRecord& record, unsigned ranks) {
    ranks = std::max(1u, ranks);
    std::vector<RankRound> out;
    out.reserve(record.size());
    std::vector<std::uint64_t> rank_work(ranks);
    // Where each rank's range began the round before (Morton codes; none
    // before the first round).  Leaves only split, so each leaf lies in one
    // leaf of the round before, and so in one range.
    std::vector<std::uint64_t> starts;
    for (const RecordedRound& round : record) {
        const std::vector<std::uint32_t> owner = morton_owners(round, ranks);
        RankRound r;
        for (std::size_t i = 0; i < round.leaves.size() && !starts.empty(); ++i) {
            const std::uint64_t key = round.leaves[i].cell.morton();
            const auto before = static_cast<std::uint32_t>(
                std::upper_bound(starts.begin(), starts.end(), key) - starts.begin());
            if (before != owner[i]) r.moved_triangles += round.leaves[i].triangles;
        }
        starts.assign(ranks, ~std::uint64_t{0});
        starts[0] = 0;
        for (std::size_t i = round.leaves.size(); i-- > 0;)
            starts[owner[i]] = std::min(starts[owner[i]], round.leaves[i].cell.morton());
        for (std::size_t k = ranks - 1; k-- > 0;) starts[k] = std::min(starts[k], starts[k + 1]);
        // starts[k] is where rank k's range begins; the rank of a key is the
        // number of ranges beginning at or before it, less one.
        starts.erase(starts.begin());
        std::fill(rank_work.begin(), rank_work.end(), 0);
        for (const RecordedRun& run : round.runs) {
            const std::uint32_t mine = owner[run.leaf];
            r.work += run.work;
            rank_work[mine] += run.work;
            for (const std::uint32_t z : run.zone) {
                if (z == run.leaf) continue;
                const std::uint64_t t = round.leaves[z].triangles;
                r.zone_triangles += t;
                if (owner[z] != mine) r.remote_triangles += t;
            }
        }
        r.largest = *std::max_element(rank_work.begin(), rank_work.end());
        r.balance = r.work == 0 ? 1.0 : double(r.largest) * ranks / double(r.work);
        r.share =
            r.zone_triangles == 0 ? 0.0 : double(r.remote_triangles) / double(r.zone_triangles);
        out.push_back(r);
    }
    return out;
}

namespace {

// The median, the work-weighted mean and the largest of value(round).
template <class Value>
RoundStatistic statistic(const std::vector<RankRound>& rounds, const Value& value) {
    RoundStatistic s;
    if (rounds.empty()) return s;
    std::vector<double> v;
    double sum = 0, weights = 0;
    for (const RankRound& r : rounds) {
        v.push_back(value(r));
        sum += value(r) * double(r.work);
        weights += double(r.work);
    }
    std::sort(v.begin(), v.end());
    s.median = v.size() % 2 == 1 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    s.weighted = weights == 0 ? s.median : sum / weights;
    s.worst = v.back();
    return s;
}

}  // namespace

RankSummary summarise(const std::vector<RankRound>& rounds) {
    RankSummary s;
    s.share = statistic(rounds, [](const RankRound& r) { return r.share; });
    s.balance = statistic(rounds, [](const RankRound& r) { return r.balance; });
    std::uint64_t span = 0;
    for (const RankRound& r : rounds) {
        s.work += r.work;
        s.remote += r.remote_triangles;
        s.moved += r.moved_triangles;
        span += r.largest;
    }
    s.speedup = span == 0 ? 1.0 : double(s.work) / double(span);
    return s;
}

}  // namespace gpdr::parallel
