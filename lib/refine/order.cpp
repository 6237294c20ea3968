// The rules of refinement order decided once per run (see order.hpp).

#include "refine/order.hpp"

namespace gpdr::refine {

OrderRules order_rules(const QualityTest& quality) {
    OrderRules rules;
    if (quality.has_angle_test()) {
        // ρ̄ = 1 / (2 sin θ) is 1 at 30 degrees: compared with a margin for
        // the rounding of the sine, so that -q30 stacks.
        constexpr double size_stack_rho_bar = 0.999;
        rules.stack_size_only = quality.rho_bar() >= size_stack_rho_bar;
        rules.sort_size_only = quality.criteria().min_angle_degrees <= size_sort_max_angle;
    }
    return rules;
}

bool quadtree_keeps_order(double min_angle_degrees) {
    return min_angle_degrees <= max_quadtree_angle;
}

}  // namespace gpdr::refine
