// Point insertion in bands, several at once (see strip_inserter.hpp).

#include "triangulate/strip_inserter.hpp"

#include <algorithm>
#include <limits>

#include "geometry/predicates.hpp"
#include "mesh/locate.hpp"
#include "mesh/slices.hpp"
#include "mesh/sort_by_key.hpp"
#include "triangulate/point_inserter.hpp"

namespace gpdr::triangulate {

using namespace gpdr::mesh;
using geometry::Point;

namespace {

// A walk from `from` (owned by the band of `inserter`) to the triangle that
// holds p, stepping only into owned triangles: each step reads a neighbour
// of an owned triangle, which no other band writes.  no_triangle when the
// way leaves the band, or when p is a corner already (a duplicate: the
// caller's one-thread pass decides which copy stays).  The edge tried first
// turns with every step, so that the walk cannot circle.
TriangleId walk_in_band(const Mesh& mesh, const PointInserter& inserter, TriangleId from,
                        const Point& p) {
    TriangleId t = from;
    for (std::uint32_t step = 0;; ++step) {
        const Triangle& r = mesh.triangle(t);
        // The next triangle is one of these, and the cavity search reads
        // them: at millions of points they are mostly cache misses.
        for (const EdgeRef e : r.n) __builtin_prefetch(&mesh.triangle(e.triangle()));
        const Point* corner[3] = {&mesh.point(r.v[0]), &mesh.point(r.v[1]), &mesh.point(r.v[2])};
        bool moved = false;
        for (int j = 0; j < 3 && !moved; ++j) {
            const int k = static_cast<int>((step + static_cast<std::uint32_t>(j)) % 3);
            if (geometry::orient2d(*corner[next3(k)], *corner[prev3(k)], p) >= 0) continue;
            const TriangleId across = r.n[k].triangle();
            if (!inserter.owns(mesh.triangle(across))) return no_triangle;
            t = across;
            moved = true;
        }
        if (moved) continue;
        for (const Point* c : corner)
            if (*c == p) return no_triangle;
        return t;
    }
}

}  // namespace

struct StripInserter::Band {
    std::span<const std::uint32_t> points;  // this round's, in order
    std::vector<std::uint32_t> deferred;  // in order
    TriangleId start = no_triangle;
    std::uint64_t inserted = 0;
    bool cocircular = false;
};

StripInserter::StripInserter(Mesh& mesh, std::vector<double> cuts, const Box& box,
                             unsigned threads)
    : mesh_(mesh),
      cuts_(std::move(cuts)),
      threads_(std::max(1u, threads)),
      last_(cuts_.size() + 1, no_triangle),
      y_low_(box.y_low),
      y_scale_(box.y_high > box.y_low ? rows / (box.y_high - box.y_low) : 0),
      anchors_((cuts_.size() + 1) * cells, no_triangle) {
    for (std::size_t s = 0; s <= cuts_.size(); ++s) {
        const double low = s == 0 ? box.x_low : cuts_[s - 1];
        const double high = s == cuts_.size() ? box.x_high : cuts_[s];
        column_low_.push_back(low);
        column_scale_.push_back(high > low ? columns / (high - low) : 0);
    }
}

std::uint32_t StripInserter::cell(std::uint32_t band, const Point& p) const {
    const auto clamp = [](double c, std::uint32_t count) {
        return c <= 0 ? 0u : c >= count - 1 ? count - 1 : static_cast<std::uint32_t>(c);
    };
    return clamp((p.y - y_low_) * y_scale_, rows) * columns +
           clamp((p.x - column_low_[band]) * column_scale_[band], columns);
}

StripInserter::~StripInserter() {
    // In band order: each pool hands its spare slots back to the mesh as
    // it goes, and the next pool made takes them in that order.
    for (auto& pool : pools_) pool.reset();
}

std::vector<std::uint32_t> StripInserter::insert_round(std::span<const std::uint32_t> vertices,
                                                       TriangleId hint) {
    const auto bands = static_cast<std::uint32_t>(cuts_.size() + 1);
    set_lanes(bands);
    std::vector<Band> band(bands);
    std::vector<std::uint32_t> sorted;  // the bands' points
    std::vector<std::uint32_t> deferred = sort_into_bands(vertices, sorted, band);
    find_starts(band, hint);
    run_pieces(threads_, bands,
               [&](std::size_t s) { run_band(band[s], static_cast<std::uint32_t>(s)); });
    for (Band& b : band) {
        inserted_ += b.inserted;
        cocircular_ = cocircular_ || b.cocircular;
        deferred.insert(deferred.end(), b.deferred.begin(), b.deferred.end());
    }
    order_for_walks(deferred);
    return deferred;
}

// Every band's pool on its lane of this round's list (made at the first
// round, moved at the others).
void StripInserter::set_lanes(std::uint32_t bands) {
    Lane lane = Lane::first(mesh_, bands);
    for (std::uint32_t s = 0; s < bands; ++s) {
        lane.index = s;
        if (pools_.size() < bands)
            pools_.push_back(std::make_unique<Pool>(mesh_, lane));
        else
            pools_[s]->move_to_lane(lane);
    }
}

// Each point to its band, in order (mesh/sort_by_key.hpp): `sorted` holds
// them band by band, each band's points a span of it.  Returns the points
// on a cut, which belong to none.
std::vector<std::uint32_t> StripInserter::sort_into_bands(std::span<const std::uint32_t> vertices,
                                                          std::vector<std::uint32_t>& sorted,
                                                          std::vector<Band>& band) const {
    const auto bands = static_cast<std::uint32_t>(band.size());
    const std::uint32_t on_cut = bands;  // the "band" of the points on a cut
    sorted.resize(vertices.size());
    const std::vector<std::size_t> start = sort_by_key(
        threads_, vertices.size(), bands + 1,
        [&](std::size_t i) {
            const double x = mesh_.point(VertexId{vertices[i]}).x;
            const auto s = static_cast<std::uint32_t>(
                std::upper_bound(cuts_.begin(), cuts_.end(), x) - cuts_.begin());
            return s > 0 && cuts_[s - 1] == x ? on_cut : s;
        },
        [&](std::size_t i, std::size_t at) { sorted[at] = vertices[i]; });
    const std::span<const std::uint32_t> all(sorted);
    for (std::uint32_t s = 0; s < bands; ++s)
        band[s].points = all.subspan(start[s], start[s + 1] - start[s]);
    return {sorted.begin() + static_cast<std::ptrdiff_t>(start[on_cut]), sorted.end()};
}

void StripInserter::limit_to_band(PointInserter& inserter, std::uint32_t s) const {
    inserter.limit_to(s == 0 ? -std::numeric_limits<double>::infinity() : cuts_[s - 1],
                      s == cuts_.size() ? std::numeric_limits<double>::infinity() : cuts_[s]);
}

// Where each band starts: its last triangle if that is still its own, else
// the triangle that holds one of its first points, found by the ordinary
// walk (one thread, nothing moves yet), if the band owns it.  Anchors the
// band no longer owns (the one-thread pass may have reused their slots
// anywhere) are dropped: during the round a band reads only what it owned
// when the round began, and its own.
void StripInserter::find_starts(std::vector<Band>& band, TriangleId hint) {
    std::uint32_t random_state = 1;
    for (std::uint32_t s = 0; s < band.size(); ++s) {
        if (band[s].points.empty()) continue;
        PointInserter probe(*pools_[s]);
        limit_to_band(probe, s);
        const auto owned = [&](TriangleId t) {
            return t != no_triangle && mesh_.triangle(t).live() && probe.owns(mesh_.triangle(t));
        };
        for (std::uint32_t c = 0; c < cells; ++c) {
            TriangleId& a = anchors_[s * cells + c];
            if (!owned(a)) a = no_triangle;
        }
        if (owned(last_[s])) {
            band[s].start = last_[s];
            continue;
        }
        last_[s] = no_triangle;
        constexpr std::size_t tries = 64;  // its first points may lie near a cut
        for (std::size_t i = 0; i < std::min(tries, band[s].points.size()); ++i) {
            const Point& p = mesh_.point(VertexId{band[s].points[i]});
            const LocateResult where = locate(mesh_, p, hint, random_state);
            if (where.where != Location::on_vertex && owned(where.triangle)) {
                band[s].start = where.triangle;
                break;
            }
        }
    }
}

// Puts the points put off in an order for short walks: they gather along
// the cuts, so cut by cut (the nearest one), up each cut.  Any order makes
// the same triangulation; this one is fixed by the points alone.
void StripInserter::order_for_walks(std::vector<std::uint32_t>& deferred) const {
    const auto nearest_cut = [&](double x) {
        const auto above = std::upper_bound(cuts_.begin(), cuts_.end(), x) - cuts_.begin();
        if (above == 0) return std::ptrdiff_t{0};
        if (above == static_cast<std::ptrdiff_t>(cuts_.size())) return above - 1;
        return x - cuts_[above - 1] < cuts_[above] - x ? above - 1 : above;
    };
    std::vector<std::pair<std::ptrdiff_t, std::uint32_t>> keyed;
    keyed.reserve(deferred.size());
    for (const std::uint32_t v : deferred)
        keyed.push_back({nearest_cut(mesh_.point(VertexId{v}).x), v});
    std::sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
        if (a.first != b.first) return a.first < b.first;
        const double ya = mesh_.point(VertexId{a.second}).y;
        const double yb = mesh_.point(VertexId{b.second}).y;
        return ya < yb || (ya == yb && a.second < b.second);
    });
    for (std::size_t i = 0; i < keyed.size(); ++i) deferred[i] = keyed[i].second;
}

TriangleId StripInserter::live_triangle(TriangleId hint) const {
    if (mesh_.triangle(hint).live()) return hint;
    for (const TriangleId t : last_)
        if (t != no_triangle && mesh_.triangle(t).live()) return t;
    for (std::uint32_t i = 0;; ++i)
        if (mesh_.triangle(TriangleId{i}).live()) return TriangleId{i};
}

void StripInserter::run_band(Band& band, std::uint32_t s) {
    PointInserter inserter(*pools_[s]);
    limit_to_band(inserter, s);
    inserter.watch_cocircular();
    TriangleId at = band.start;
    TriangleId* anchors = &anchors_[s * cells];
    for (const std::uint32_t v : band.points) {
        const VertexId id{v};
        const Point& p = mesh_.point(id);
        TriangleId& anchor = anchors[cell(s, p)];
        // The anchor's slot is this band's (made by it this round, or owned
        // when the round began): if it died, only this band reused it.
        TriangleId from = at;
        if (anchor != no_triangle && mesh_.triangle(anchor).live() &&
            inserter.owns(mesh_.triangle(anchor)))
            from = anchor;
        TriangleId made = no_triangle;
        if (from != no_triangle) {
            const TriangleId seed = walk_in_band(mesh_, inserter, from, p);
            if (seed != no_triangle) made = inserter.try_insert(id, seed);
        }
        if (made == no_triangle) {
            band.deferred.push_back(v);
            continue;
        }
        at = made;
        anchor = made;
        ++band.inserted;
    }
    last_[s] = at;
    band.cocircular = inserter.cocircular_seen();
}

}  // namespace gpdr::triangulate
