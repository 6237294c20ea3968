#pragma once
// ReservedTable: the mesh's element stores, in one address range reserved up
// front (docs/architecture.md, "Storage that never moves").
//
// Element i lives at base + i: one load per access, where a table of chunk
// pointers costs a second, dependent one (ChunkTable, store.hpp; that load
// was about a sixth of refinement's instructions).  The range is reserved
// read-only, which costs neither memory nor commit charge, and is made
// writable as ids are claimed, so an id handed out once stays valid and an
// element never moves while other threads add more.
//
// Ids are claimed in chunks of 2^ChunkBits (mesh.hpp), small, so that the
// parallel refiner's lanes, which each claim chunks of their own every
// round, leave few ids unused.  Memory is made writable in granules of
// 2 MiB, each holding whole chunks, so claiming a chunk costs a system
// call only once per granule.
//
// Pages nobody wrote read as zeros, claimed or not: ids may have holes of
// whole chunks (the lanes claim chunks by a fixed rule, mesh.hpp), and a
// pass over all ids reads empty elements there.  An all-zero element must
// therefore be a valid "empty" element of T.  Writing into a granule never
// made writable faults, as a bug should.
//
// The owner reserves the range when it first needs it, and chooses its size
// (Mesh reserves all MaxChunks unless the address space is limited:
// mesh.cpp); a chunk beyond the reservation is refused as memory that ran
// out.
//
// Thread safety: ensure() may be called by several threads at once; making
// a granule writable twice is harmless, and the flags that has_chunk()
// reads are published after it.  Element access needs no synchronisation
// of its own: a thread reads only elements whose ids reached it through
// some synchronisation, which also orders the chunk's making.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>

#include <sys/mman.h>

namespace gpdr::mesh {

template <class T, unsigned ChunkBits, std::uint32_t MaxChunks>
class ReservedTable {
public:
    static constexpr std::uint32_t chunk_size = 1u << ChunkBits;
    static constexpr std::uint32_t chunk_mask = chunk_size - 1;
    static constexpr std::uint32_t max_chunks = MaxChunks;
    static constexpr std::size_t chunk_bytes = std::size_t{chunk_size} * sizeof(T);
    // Chunks per granule: 2 MiB of elements (one chunk if that is more, the
    // whole table if it is less).
    static constexpr std::uint32_t granule_chunks =
        chunk_bytes >= (std::size_t{1} << 21) ? 1
        : (std::size_t{1} << 21) / chunk_bytes >= std::size_t{MaxChunks}
            ? MaxChunks
            : static_cast<std::uint32_t>((std::size_t{1} << 21) / chunk_bytes);
    static_assert((granule_chunks & (granule_chunks - 1)) == 0, "granules hold 2^k chunks");
    static_assert(MaxChunks % granule_chunks == 0, "the table ends at a granule's end");

    // An empty table reserves nothing: reserve() gives it its range.
    ReservedTable() = default;
    ~ReservedTable() { release(); }
    ReservedTable(ReservedTable&& other) noexcept { take(other); }
    ReservedTable& operator=(ReservedTable&& other) noexcept {
        if (this != &other) {
            release();
            take(other);
        }
        return *this;
    }
    ReservedTable(const ReservedTable&) = delete;
    ReservedTable& operator=(const ReservedTable&) = delete;

    T& operator[](std::uint32_t i) const { return base_[i]; }

    // Whether chunk c was claimed (ensure()d).
    bool has_chunk(std::uint32_t c) const {
        return c < reserved_chunks_ && flag(c).load(std::memory_order_acquire) != 0;
    }

    // Reserves room for `chunks` chunks (at most MaxChunks, rounded up to
    // whole granules), once; nothing when the table has its range already.
    // Throws std::bad_alloc when the system refuses the range.
    void reserve(std::uint32_t chunks) {
        if (base_ != nullptr) return;
        chunks = chunks < MaxChunks ? chunks : MaxChunks;
        chunks = (chunks + granule_chunks - 1) / granule_chunks * granule_chunks;
        if (chunks == 0) chunks = granule_chunks;
        const std::size_t length = std::size_t{chunks} * chunk_bytes;
        // The flags, one byte per chunk and one per granule, in pages that
        // read as zeros until written (a mesh of a few triangles touches one).
        const std::size_t flag_bytes = std::size_t{chunks} + chunks / granule_chunks;
        void* flags = mmap(nullptr, flag_bytes, PROT_READ | PROT_WRITE,
                           MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (flags == MAP_FAILED) throw std::bad_alloc();
        void* p =
            mmap(nullptr, length, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (p == MAP_FAILED) {
            munmap(flags, flag_bytes);
            throw std::bad_alloc();
        }
        // Transparent huge pages are left out: measured on the triangle
        // chunks they doubled the system time (docs/performance.md).
        madvise(p, length, MADV_NOHUGEPAGE);
        flags_ = static_cast<std::uint8_t*>(flags);
        base_ = static_cast<T*>(p);
        reserved_chunks_ = chunks;
    }

    // Makes sure chunk c is writable.  Returns false when c is past
    // MaxChunks.  Throws std::bad_alloc when the chunk lies beyond the
    // reservation or the system refuses the memory.
    bool ensure(std::uint32_t c) {
        if (c >= MaxChunks) return false;
        if (c >= reserved_chunks_) throw std::bad_alloc();
        if (flag(c).load(std::memory_order_acquire) != 0) return true;
        const std::uint32_t g = c / granule_chunks;
        std::atomic_ref<std::uint8_t> granule(flags_[reserved_chunks_ + g]);
        if (granule.load(std::memory_order_acquire) == 0) {
            T* first = base_ + std::size_t{g} * granule_chunks * chunk_size;
            if (mprotect(first, granule_chunks * chunk_bytes, PROT_READ | PROT_WRITE) != 0)
                throw std::bad_alloc();
            if (granule.exchange(1, std::memory_order_acq_rel) == 0)
                granules_.fetch_add(1, std::memory_order_relaxed);
        }
        flag(c).store(1, std::memory_order_release);
        return true;
    }

    // Gives the memory of every whole granule below chunk `chunk` back to
    // the system, for good: its elements may no longer be read or written
    // (they fault, as a bug should).  For a table whose elements have been
    // copied elsewhere and are never read again; calls must not overlap.
    void discard_below(std::uint32_t chunk) {
        const std::uint32_t end =
            (chunk < reserved_chunks_ ? chunk : reserved_chunks_) / granule_chunks;
        if (end <= discarded_granules_) return;
        T* first = base_ + std::size_t{discarded_granules_} * granule_chunks * chunk_size;
        const std::size_t length =
            std::size_t{end - discarded_granules_} * granule_chunks * chunk_bytes;
        madvise(first, length, MADV_DONTNEED);
        mprotect(first, length, PROT_NONE);
        for (std::uint32_t g = discarded_granules_; g < end; ++g)
            if (flags_[reserved_chunks_ + g] != 0)
                granules_.fetch_sub(1, std::memory_order_relaxed);
        discarded_granules_ = end;
    }

    // Bytes made writable (whole granules; untouched pages of them cost
    // nothing) and the flags.
    std::size_t bytes() const {
        return granules_.load(std::memory_order_relaxed) * granule_chunks * chunk_bytes +
               reserved_chunks_ + reserved_chunks_ / granule_chunks;
    }

private:
    std::atomic_ref<std::uint8_t> flag(std::uint32_t c) const {
        return std::atomic_ref<std::uint8_t>(flags_[c]);
    }

    void release() {
        if (base_ != nullptr) {
            munmap(base_, std::size_t{reserved_chunks_} * chunk_bytes);
            munmap(flags_, std::size_t{reserved_chunks_} + reserved_chunks_ / granule_chunks);
        }
        base_ = nullptr;
        flags_ = nullptr;
        reserved_chunks_ = 0;
        granules_ = 0;
        discarded_granules_ = 0;
    }

    void take(ReservedTable& other) {
        base_ = std::exchange(other.base_, nullptr);
        flags_ = std::exchange(other.flags_, nullptr);
        reserved_chunks_ = std::exchange(other.reserved_chunks_, 0);
        granules_ = other.granules_.exchange(0);
        discarded_granules_ = std::exchange(other.discarded_granules_, 0);
    }

    T* base_ = nullptr;
    std::uint8_t* flags_ = nullptr;  // per chunk, then per granule
    std::uint32_t reserved_chunks_ = 0;
    std::atomic<std::size_t> granules_{0};
    std::uint32_t discarded_granules_ = 0;  // granules below it were discarded
};

}  // namespace gpdr::mesh
