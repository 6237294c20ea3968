#pragma once
// The subsegment side table: what a subsegment carries beyond the flag bit in
// its two triangles (boundary marker, index of the input segment it came
// from), keyed by the undirected vertex pair.  Only flags fit in the 32-byte
// triangle record; markers and sources are needed rarely (splitting a
// subsegment, writing files), so they live here.
//
// Thread safety: the table is split into shards by vertex pair, each with
// its own lock, so parallel refinement workers (parallel/) may call find(),
// set() and erase() at once without a global lock.  A pointer find() returns
// stays valid while other threads add or remove OTHER entries (the shards
// are node-based maps); the parallel layer guarantees that an entry is only
// changed by the worker whose buffer zone holds the subsegment.  size(),
// clear(), reserve() and for_each() are for single-threaded use.

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>

#include "mesh/ids.hpp"

namespace gpdr::mesh {

struct SubsegmentInfo {
    static constexpr std::uint32_t no_segment = 0xFFFFFFFFu;

    int marker = 0;                      // boundary marker (Triangle's rules, docs/file-formats.md)
    std::uint32_t segment = no_segment;  // index of the input segment it lies on

    friend bool operator==(const SubsegmentInfo&, const SubsegmentInfo&) = default;
};

class SubsegmentTable {
public:
    SubsegmentTable() : shards_(std::make_unique<Shard[]>(shard_count)) {}

    // Adds or replaces the entry of edge {a, b} (either order).
    void set(VertexId a, VertexId b, SubsegmentInfo info) {
        if (!shards_) shards_ = std::make_unique<Shard[]>(shard_count);  // a moved-from table
        const std::uint64_t k = key(a, b);
        Shard& s = shard(k);
        std::lock_guard lock(s.mutex);
        s.map[k] = info;
    }
    // The entry of edge {a, b}, or nullptr.
    const SubsegmentInfo* find(VertexId a, VertexId b) const {
        if (!shards_) return nullptr;
        const std::uint64_t k = key(a, b);
        Shard& s = shard(k);
        std::lock_guard lock(s.mutex);
        auto it = s.map.find(k);
        return it == s.map.end() ? nullptr : &it->second;
    }
    // Removes edge {a, b}; false if it was not there.
    bool erase(VertexId a, VertexId b) {
        if (!shards_) return false;
        const std::uint64_t k = key(a, b);
        Shard& s = shard(k);
        std::lock_guard lock(s.mutex);
        return s.map.erase(k) != 0;
    }
    std::size_t size() const {
        std::size_t n = 0;
        if (!shards_) return 0;
        for (std::size_t i = 0; i < shard_count; ++i) n += shards_[i].map.size();
        return n;
    }
    void clear() {
        if (!shards_) return;
        for (std::size_t i = 0; i < shard_count; ++i) shards_[i].map.clear();
    }
    void reserve(std::size_t n) {
        if (!shards_) shards_ = std::make_unique<Shard[]>(shard_count);
        for (std::size_t i = 0; i < shard_count; ++i) shards_[i].map.reserve(n / shard_count + 1);
    }

    // f(VertexId low, VertexId high, const SubsegmentInfo&) for every entry,
    // in no particular order.
    template <class F>
    void for_each(F&& f) const {
        if (!shards_) return;
        for (std::size_t i = 0; i < shard_count; ++i)
            for (const auto& [k, info] : shards_[i].map)
                f(VertexId{static_cast<std::uint32_t>(k >> 32)},
                  VertexId{static_cast<std::uint32_t>(k)}, info);
    }

private:
    static constexpr std::size_t shard_count = 64;
    struct Shard {
        mutable std::mutex mutex;
        std::unordered_map<std::uint64_t, SubsegmentInfo> map;
    };

    static std::uint64_t key(VertexId a, VertexId b) {
        std::uint64_t lo = index(a), hi = index(b);
        if (lo > hi) std::swap(lo, hi);
        return (lo << 32) | hi;
    }
    Shard& shard(std::uint64_t k) const {
        // Mix both ids so neighbouring pairs spread over the shards.
        return shards_[((k * 0x9E3779B97F4A7C15ull) >> 58) & (shard_count - 1)];
    }

    std::unique_ptr<Shard[]> shards_;
};

}  // namespace gpdr::mesh
