// PolyFile -> Pslg (see pslg.hpp).

#include "triangulate/pslg.hpp"

namespace gpdr::triangulate {

Pslg pslg_from(const PolyFile& poly) {
    Pslg p;
    p.points.reserve(poly.nodes.size());
    for (std::size_t i = 0; i < poly.nodes.size(); ++i)
        p.points.push_back({poly.nodes.xy[2 * i], poly.nodes.xy[2 * i + 1]});
    p.segments = poly.segments.endpoints;
    p.segment_markers = poly.segments.markers;
    for (std::size_t i = 0; i + 1 < poly.holes.size(); i += 2)
        p.holes.push_back({poly.holes[i], poly.holes[i + 1]});
    p.regions = poly.regions;
    return p;
}

}  // namespace gpdr::triangulate
