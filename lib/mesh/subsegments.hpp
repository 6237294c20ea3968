#pragma once
// The subsegment side table: what a subsegment carries beyond the flag bit in
// its two triangles (boundary marker, index of the input segment it came
// from), keyed by the undirected vertex pair.  Only flags fit in the 32-byte
// triangle record; markers and sources are needed rarely (splitting a
// subsegment, writing files), so they live here.
//
// Not thread-safe for writers: the parallel refiner must give each worker its
// own pending changes or a lock around set()/erase() (decided in parallel/).

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "mesh/ids.hpp"

namespace gpdr::mesh {

struct SubsegmentInfo {
    static constexpr std::uint32_t no_segment = 0xFFFFFFFFu;

    int marker = 0;                        // boundary marker (Triangle's rules, TRIANGLE-COMPAT.md)
    std::uint32_t segment = no_segment;    // index of the input segment it lies on

    friend bool operator==(const SubsegmentInfo&, const SubsegmentInfo&) = default;
};

class SubsegmentTable {
public:
    // Adds or replaces the entry of edge {a, b} (either order).
    void set(VertexId a, VertexId b, SubsegmentInfo info) { map_[key(a, b)] = info; }
    // The entry of edge {a, b}, or nullptr.
    const SubsegmentInfo* find(VertexId a, VertexId b) const {
        auto it = map_.find(key(a, b));
        return it == map_.end() ? nullptr : &it->second;
    }
    // Removes edge {a, b}; false if it was not there.
    bool erase(VertexId a, VertexId b) { return map_.erase(key(a, b)) != 0; }
    std::size_t size() const { return map_.size(); }
    void clear() { map_.clear(); }
    void reserve(std::size_t n) { map_.reserve(n); }

    // f(VertexId low, VertexId high, const SubsegmentInfo&) for every entry,
    // in no particular order.
    template <class F>
    void for_each(F&& f) const {
        for (const auto& [k, info] : map_)
            f(VertexId{static_cast<std::uint32_t>(k >> 32)}, VertexId{static_cast<std::uint32_t>(k)}, info);
    }

private:
    static std::uint64_t key(VertexId a, VertexId b) {
        std::uint64_t lo = index(a), hi = index(b);
        if (lo > hi) std::swap(lo, hi);
        return (lo << 32) | hi;
    }

    std::unordered_map<std::uint64_t, SubsegmentInfo> map_;
};

}  // namespace gpdr::mesh
