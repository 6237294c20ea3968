// Temporary segment labels (see segment_labels.hpp).

#include "parallel/segment_labels.hpp"

#include <algorithm>
#include <array>
#include <tuple>
#include <unordered_set>

#include "mesh/traverse.hpp"
#include "refine/segments.hpp"

namespace gpdr::parallel {

SegmentLabels::SegmentLabels(mesh::Mesh& mesh, std::span<const mesh::VertexId> given_ends)
    : mesh_(mesh),
      first_label_(static_cast<std::uint32_t>(given_ends.size() / 2)),
      ends_(given_ends.begin(), given_ends.begin() + 2 * std::ptrdiff_t{first_label_}) {
    auto usable = [&](const mesh::SubsegmentInfo* info) {
        return info != nullptr && info->segment < first_label_;
    };
    std::unordered_set<std::uint64_t> labelled;  // (each subsegment is seen from both sides)
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId t, const mesh::Triangle& r) {
        for (int k = 0; k < 3; ++k) {
            if (!r.is_subsegment(k)) continue;
            const mesh::VertexId a = r.v[mesh::next3(k)], b = r.v[mesh::prev3(k)];
            const mesh::SubsegmentInfo* info = mesh.subsegments().find(a, b);
            if (usable(info)) continue;
            const std::uint64_t key = std::min(mesh::index(a), mesh::index(b)) |
                                      std::uint64_t{std::max(mesh::index(a), mesh::index(b))} << 32;
            if (!labelled.insert(key).second) continue;
            std::array<mesh::VertexId, 2> ends{mesh::no_vertex, mesh::no_vertex};
            if (!refine::walk_segment_ends(mesh, mesh::EdgeRef(t, k), ends))
                ends = {mesh::no_vertex, mesh::no_vertex};
            mesh::SubsegmentInfo labelled = info != nullptr ? *info : mesh::SubsegmentInfo{};
            original_.push_back(labelled.segment);
            labelled.segment = static_cast<std::uint32_t>(ends_.size() / 2);
            ends_.push_back(ends[0]);
            ends_.push_back(ends[1]);
            mesh.subsegments().set(a, b, labelled);
        }
    });
}

void SegmentLabels::restore() {
    if (original_.empty()) return;
    std::vector<std::tuple<mesh::VertexId, mesh::VertexId, mesh::SubsegmentInfo>> changed;
    mesh_.subsegments().for_each(
        [&](mesh::VertexId a, mesh::VertexId b, const mesh::SubsegmentInfo& info) {
            if (info.segment == mesh::SubsegmentInfo::no_segment || info.segment < first_label_)
                return;
            mesh::SubsegmentInfo back = info;
            back.segment = original_[info.segment - first_label_];
            changed.emplace_back(a, b, back);
        });
    for (const auto& [a, b, info] : changed) mesh_.subsegments().set(a, b, info);
}

}  // namespace gpdr::parallel
