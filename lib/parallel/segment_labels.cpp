// Temporary segment labels (see segment_labels.hpp).

#include "parallel/segment_labels.hpp"

#include <algorithm>
#include <array>
#include <tuple>
#include <unordered_set>
#include <utility>
#include <vector>

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
    const auto key = [](mesh::VertexId a, mesh::VertexId b) {
        return std::min(mesh::index(a), mesh::index(b)) |
               std::uint64_t{std::max(mesh::index(a), mesh::index(b))} << 32;
    };
    // Subsegments already labelled (each is seen from both sides, and every
    // piece of a chain is labelled by the one walk that meets it first).
    std::unordered_set<std::uint64_t> labelled;
    std::vector<std::array<mesh::VertexId, 2>> pieces;
    mesh::for_each_triangle(mesh, [&](mesh::TriangleId t, const mesh::Triangle& r) {
        for (int k = 0; k < 3; ++k) {
            if (!r.is_subsegment(k)) continue;
            const mesh::VertexId a = r.v[mesh::next3(k)], b = r.v[mesh::prev3(k)];
            if (usable(mesh.subsegments().find(a, b)) || labelled.count(key(a, b)) != 0) continue;
            std::array<mesh::VertexId, 2> ends{mesh::no_vertex, mesh::no_vertex};
            pieces.clear();
            if (!refine::walk_segment_chain(mesh, mesh::EdgeRef(t, k), ends, pieces))
                ends = {mesh::no_vertex, mesh::no_vertex};
            // One label per original index met on the chain (almost always
            // just one), so that restore() can give each piece its own back.
            std::vector<std::pair<std::uint32_t, std::uint32_t>> label_of;  // original -> label
            for (const auto& [u, w] : pieces) {
                const mesh::SubsegmentInfo* info = mesh.subsegments().find(u, w);
                if (usable(info) || !labelled.insert(key(u, w)).second) continue;
                mesh::SubsegmentInfo relabelled = info != nullptr ? *info : mesh::SubsegmentInfo{};
                auto found = std::find_if(label_of.begin(), label_of.end(), [&](const auto& p) {
                    return p.first == relabelled.segment;
                });
                if (found == label_of.end()) {
                    label_of.emplace_back(relabelled.segment,
                                          static_cast<std::uint32_t>(ends_.size() / 2));
                    found = label_of.end() - 1;
                    original_.push_back(relabelled.segment);
                    ends_.push_back(ends[0]);
                    ends_.push_back(ends[1]);
                }
                relabelled.segment = found->second;
                mesh.subsegments().set(u, w, relabelled);
            }
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
