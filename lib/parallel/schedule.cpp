// The choice of refinement schedule (see schedule.hpp).

#include "parallel/schedule.hpp"

#include <fmt/format.h>

namespace gpdr::parallel {

Schedule choose_schedule(const Options& o) {
    const unsigned g = o.granularity != 0 ? o.granularity : refine::default_granularity;
    if (o.threads == 1) return Schedule::sequential(Schedule::Why::one_thread, g);
    if (o.steiner_limit) return Schedule::sequential(Schedule::Why::steiner_limit, g);
    if (o.quality && !refine::quadtree_keeps_order(o.min_angle))
        return Schedule::sequential(Schedule::Why::high_angle, g);
    return Schedule::rounds(thread_count(o.threads), g);
}

std::string Schedule::describe() const {
    constexpr const char* one_thread = "Refinement on one thread, in Triangle's order";
    switch (why) {
        case Why::rounds:
            return fmt::format(
                "Refinement in rounds over the quadtree on {} thread{}, granularity {}", threads,
                threads == 1 ? "" : "s", granularity);
        case Why::one_thread:
            return fmt::format("{}: -j1", one_thread);
        case Why::steiner_limit:
            return fmt::format("{}: -S, whose limit is exact only there", one_thread);
        case Why::high_angle:
            // Up to 34 degrees the leaves' order makes meshes larger or
            // endless; above, where -P1 tries placements in turn, a try that
            // will not end is caught only late in rounds (refine/order.hpp).
            return fmt::format(
                "{}: the angle bound is above {} degrees, where the quadtree's leaves change "
                "whether refinement ends",
                one_thread, refine::max_quadtree_angle);
    }
    return one_thread;
}

}  // namespace gpdr::parallel
