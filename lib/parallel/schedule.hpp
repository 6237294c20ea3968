#pragma once
// How refinement runs: the one decision, made from the options, and the
// value the refinement stage hands to the parallel layer.
//
// There are two schedules:
//   sequential  one flat leaf on the calling thread, in Triangle's order
//               (refine::refine_mesh; refine/order.hpp, rule 1).  For -j1;
//               for -S, whose limit is exact only when one thread counts
//               the Steiner points; and for an angle bound above
//               refine::max_quadtree_angle, where the quadtree's leaves
//               cannot keep the order refinement needs to end (rule 5).
//   rounds      the quadtree's leaves refined in rounds (rounds.hpp): the
//               calling thread forms each round from the mesh alone, and
//               the threads refine its leaves side by side.  The mesh, its
//               numbering and the files are the same for every thread
//               count, and so the same on every machine: -j0 on a machine
//               with one hardware thread runs the same rounds on it.
//
// The granularity g (-g) has one default, refine::default_granularity,
// resolved here.

#include <algorithm>
#include <cstdint>
#include <string>
#include <thread>

#include <gpdr/options.hpp>

#include "refine/order.hpp"

namespace gpdr::parallel {

// The threads a -jN asks for: N, or for 0 one per hardware thread (at
// least one).  Refinement and the output stage both use it.
inline unsigned thread_count(unsigned requested) {
    return requested != 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

struct Schedule {
    enum class Kind : std::uint8_t { sequential, rounds };
    // Why a schedule is sequential.
    enum class Why : std::uint8_t { rounds, one_thread, steiner_limit, high_angle };

    Kind kind = Kind::rounds;
    unsigned threads = 1;  // the threads that refine (sequential: 1)
    unsigned granularity = refine::default_granularity;
    Why why = Why::rounds;
    // Checked mode (tests): verify the quadtree (relation (9) for every
    // leaf, exact counters, leaves tiling the root) after every round, and
    // the buffer zones' exclusivity whenever a leaf is handed out.
    // Failures go to ParallelReport::problems.  Slow.
    bool checked = false;
    // Recording (tests): each round's leaves, buffer zones and triangles go
    // to ParallelReport::record (round_record.hpp), for the simulation of
    // refinement across machines.  One pass over the mesh per round.
    bool record = false;

    static Schedule sequential(Why why, unsigned granularity = refine::default_granularity) {
        return {Kind::sequential, 1, granularity, why, false};
    }
    static Schedule rounds(unsigned threads, unsigned granularity = refine::default_granularity) {
        return {Kind::rounds, std::max(1u, threads), granularity, Why::rounds, false};
    }

    // What -V says of it, and why.
    std::string describe() const;
};

// The schedule for these options (-j, -g, -S, -q and its angle).
Schedule choose_schedule(const Options& options);

}  // namespace gpdr::parallel
