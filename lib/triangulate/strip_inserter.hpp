#pragma once
// Point insertion on several threads at once, for delaunay.cpp's -jN path.
//
// The plane is cut into vertical bands (strips) at fixed x values; a band
// OWNS a triangle whose three corners lie strictly inside it.  In a round,
// each band inserts its own points, in their order, into its own
// triangles, and any point whose walk, cavity or cavity border would touch
// a triangle the band does not own is put off (deferred) with nothing
// changed.  The bands then never get in each other's way:
//
//   - a band writes only triangles it owns (the cavity, and the neighbours
//     across the cavity's border, whose links change), and the triangles
//     it creates are its own (their corners are the new point and corners
//     of the cavity);
//   - it reads only its own triangles and their neighbours, and a
//     neighbour of a triangle of band s shares two corners with it, inside
//     band s, so no other band can own it: nobody writes it this round.
//
// So each band's work depends on its own points and the triangles it
// owns, never on the other bands' timing, and each band claims its slots
// from its own lane pool (mesh/pool.hpp: ids by a fixed rule): the mesh
// after a round is the same for any number of threads and any schedule.
// The caller inserts the points put off: delaunay.cpp gives them to a
// second set of bands, cut half way between these cuts, then inserts what
// that puts off one at a time.
//
// Bowyer-Watson insertion of a point makes the Delaunay triangulation of
// the points inserted so far whatever their order, so the parallel rounds
// make the one sequential insertion makes wherever that triangulation is
// unique.  Every insertion watches for edges whose two triangles share a
// circle (PointInserter::watch_cocircular); where one was made, delaunay.cpp
// starts again on one thread.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/pool.hpp"

namespace gpdr::triangulate {

class PointInserter;

class StripInserter {
public:
    // The points' bounding box.
    struct Box {
        double x_low, x_high, y_low, y_high;
    };
    // `cuts`: the x values between the bands, ascending (bands - 1 of them).
    StripInserter(mesh::Mesh& mesh, std::vector<double> cuts, const Box& box, unsigned threads);
    ~StripInserter();
    StripInserter(const StripInserter&) = delete;
    StripInserter& operator=(const StripInserter&) = delete;

    // Inserts `vertices`, each band's in their order and on one thread;
    // returns the ones put off, cut by cut and up each cut (short walks for
    // whoever inserts them next).  `hint` is a live triangle.
    std::vector<std::uint32_t> insert_round(std::span<const std::uint32_t> vertices,
                                            mesh::TriangleId hint);

    // The first band's pool, for the deferred points between rounds.  Its
    // lane claims chunks from the list of the last round's Lane::first:
    // use it only while no other lane pool's round came after that.
    mesh::Pool& pool() { return *pools_.front(); }

    // `hint` if it is alive, else a live triangle (a band's last one).
    mesh::TriangleId live_triangle(mesh::TriangleId hint) const;

    std::uint64_t inserted() const { return inserted_; }
    // Whether an insertion of a round made an edge with cocircular triangles.
    bool cocircular_seen() const { return cocircular_; }

private:
    struct Band;
    void set_lanes(std::uint32_t bands);
    std::vector<std::uint32_t> sort_into_bands(std::span<const std::uint32_t> vertices,
                                               std::vector<std::uint32_t>& sorted,
                                               std::vector<Band>& band) const;
    void limit_to_band(PointInserter& inserter, std::uint32_t s) const;
    void find_starts(std::vector<Band>& band, mesh::TriangleId hint);
    void order_for_walks(std::vector<std::uint32_t>& deferred) const;
    void run_band(Band& band, std::uint32_t s);

    mesh::Mesh& mesh_;
    std::vector<double> cuts_;
    unsigned threads_;
    std::vector<std::unique_ptr<mesh::Pool>> pools_;
    std::vector<mesh::TriangleId> last_;  // each band's last triangle made
    // Where a band's walks start: per band, the triangle it made last in each
    // cell of a grid of `rows` x `columns` over the band.  A band's points
    // come in curve order, which leaves a cell and enters it again
    // elsewhere, where a walk from the last point made would be long (or
    // run out of the band).
    static constexpr std::uint32_t rows = 128, columns = 16;
    static constexpr std::uint32_t cells = rows * columns;
    double y_low_, y_scale_;
    std::vector<double> column_low_, column_scale_;  // per band
    std::vector<mesh::TriangleId> anchors_;
    std::uint32_t cell(std::uint32_t band, const geometry::Point& p) const;
    std::uint64_t inserted_ = 0;
    bool cocircular_ = false;
};

}  // namespace gpdr::triangulate
