#pragma once
// ChunkTable: storage whose elements never move (docs/architecture.md, "The mesh"),
// for the quadtree's nodes.  (The mesh's own tables are ReservedTables,
// reserved_table.hpp: one load per access instead of two.)
//
// Element i lives in chunk i >> ChunkBits at offset i & mask.  The table of
// chunk pointers is reserved up front, so an id handed out once stays valid
// and a reference to an element stays stable while other threads add chunks.
// Chunks come from calloc: pages nobody touches cost nothing, and an all-zero
// element must therefore be a valid "empty" element of T.
//
// A chunk never made reads as zeros (one read-only mapping shared by every
// missing chunk of the table's type), so a pass over all ids reads empty
// elements there instead of following a null pointer.  Writing into a
// missing chunk faults.
//
// Thread safety: ensure() may be called by several threads at once (the first
// to publish a chunk wins, lock-free).  Element access needs no lock: a thread
// only reads elements whose ids reached it through some synchronisation (the
// scheduler's queue), which also orders the chunk pointer's publication.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>

#include <sys/mman.h>

namespace gpdr::mesh {

template <class T, unsigned ChunkBits, std::uint32_t MaxChunks>
class ChunkTable {
public:
    static constexpr std::uint32_t chunk_size = 1u << ChunkBits;
    static constexpr std::uint32_t chunk_mask = chunk_size - 1;
    static constexpr std::uint32_t max_chunks = MaxChunks;

    ChunkTable() : chunks_(new std::atomic<T*>[MaxChunks]) {
        T* const zero = zero_chunk();
        for (std::uint32_t c = 0; c < MaxChunks; ++c)
            chunks_[c].store(zero, std::memory_order_relaxed);
    }
    ~ChunkTable() { release(); }
    ChunkTable(ChunkTable&& other) noexcept
        : chunks_(std::move(other.chunks_)), allocated_(other.allocated_.load()) {
        other.allocated_ = 0;
    }
    ChunkTable& operator=(ChunkTable&& other) noexcept {
        if (this != &other) {
            release();
            chunks_ = std::move(other.chunks_);
            allocated_ = other.allocated_.load();
            other.allocated_ = 0;
        }
        return *this;
    }
    ChunkTable(const ChunkTable&) = delete;
    ChunkTable& operator=(const ChunkTable&) = delete;

    // A relaxed load: the synchronisation that brought id i to this thread
    // orders the chunk's publication (see above).  (An acquire load, which
    // the compiler may not merge with the loads around it, cost 2.8% of
    // -j1's instructions on the graded pipe.)
    T& operator[](std::uint32_t i) const {
        return chunks_[i >> ChunkBits].load(std::memory_order_relaxed)[i & chunk_mask];
    }

    bool has_chunk(std::uint32_t c) const {
        return c < MaxChunks && chunks_[c].load(std::memory_order_acquire) != zero_chunk();
    }

    // Makes sure chunk c exists (zero-filled).  Returns false when c is past
    // the reserved table.  Throws std::bad_alloc when memory runs out.
    //
    // `write_now`: write the zeros at once.  For a table that is read
    // before it is written (a slot's old record), a calloc page first read
    // maps the shared zero page, and the first write then copies it and
    // flushes the TLB of every core running the process: one interrupt per
    // page on each of them while threads work.  Writing the chunk when it
    // is made faults each page in once, privately.
    bool ensure(std::uint32_t c, bool write_now = false) {
        if (c >= MaxChunks) return false;
        T* const zero = zero_chunk();
        if (chunks_[c].load(std::memory_order_acquire) != zero) return true;
        T* fresh = static_cast<T*>(std::calloc(chunk_size, sizeof(T)));
        if (fresh == nullptr) throw std::bad_alloc();
        if (write_now) {
            // One volatile store per page: the compiler may not drop it (it
            // drops a memset of calloc'd memory, and turns malloc + memset
            // into calloc).
            volatile char* bytes = reinterpret_cast<volatile char*>(fresh);
            for (std::size_t at = 0; at < std::size_t{chunk_size} * sizeof(T); at += 4096)
                bytes[at] = 0;
        }
        T* expected = zero;
        if (chunks_[c].compare_exchange_strong(expected, fresh, std::memory_order_acq_rel))
            allocated_.fetch_add(1, std::memory_order_relaxed);
        else
            std::free(fresh);
        return true;
    }

    std::size_t allocated_chunks() const { return allocated_.load(std::memory_order_relaxed); }
    // Bytes held: the chunks and the pointer table.
    std::size_t bytes() const {
        return allocated_chunks() * std::size_t{chunk_size} * sizeof(T) +
               std::size_t{MaxChunks} * sizeof(std::atomic<T*>);
    }

private:
    // The zeros every missing chunk reads: read-only anonymous pages (the
    // kernel's zero page; no memory is used for them), mapped once for the
    // process and never unmapped.
    static T* zero_chunk() {
        static T* const zero = [] {
            void* p = mmap(nullptr, std::size_t{chunk_size} * sizeof(T), PROT_READ,
                           MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (p == MAP_FAILED) throw std::bad_alloc();
            return static_cast<T*>(p);
        }();
        return zero;
    }

    // Stops once every allocated chunk is freed: a small mesh holds a few
    // chunks of a table reserved for millions, and a sanitizer's free()
    // costs a stack trace even for a null pointer.
    void release() {
        if (!chunks_) return;
        std::size_t left = allocated_.load(std::memory_order_relaxed);
        T* const zero = zero_chunk();
        for (std::uint32_t c = 0; c < MaxChunks && left > 0; ++c)
            if (T* chunk = chunks_[c].exchange(zero); chunk != zero) {
                std::free(chunk);
                --left;
            }
        allocated_ = 0;
    }

    std::unique_ptr<std::atomic<T*>[]> chunks_;
    std::atomic<std::size_t> allocated_{0};
};

}  // namespace gpdr::mesh
