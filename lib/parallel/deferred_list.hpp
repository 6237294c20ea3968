#pragma once
// A leaf's list of triangles whose counting is put off (Worker::flush_pending
// explains why), kept in blocks of a kilobyte that a worker recycles.
//
// The lists of all leaves together hold about one entry per triangle of the
// mesh, and a split empties a list into its children's or passes it to one
// of them whole (take).  Growing vectors would copy every entry at each
// doubling and hand large buffers back to the system only to fault fresh
// zeroed pages in for the next; fixed blocks taken from, and given back to,
// the worker's own BlockPool are never copied and mostly come back warm.

#include <cstdint>
#include <memory>
#include <vector>

#include "mesh/ids.hpp"

namespace gpdr::parallel {

// A triangle whose counting is put off: stale once the slot's generation
// has moved on.
struct DeferredTriangle {
    mesh::TriangleId t;
    std::uint32_t generation;
};

struct DeferredBlock {
    // (A block is 1 KiB.  Every leaf has five lists, its own and one per
    // future child, each with a partly filled block: with 4 KiB blocks the
    // graded pipe's peak was 1116 MiB at -g3 (23,000 leaves) against 934.)
    static constexpr std::uint32_t capacity = 126;
    // (No initialisers: a slab's blocks are left untouched until handed
    // out; BlockPool::take sets these.)
    DeferredBlock* next;
    std::uint32_t size;
    DeferredTriangle items[capacity];
};

// The spare blocks of one worker.  Blocks move between lists and pools of
// different workers (a leaf is refined by whichever worker gets it); each
// stays owned by the pool that made it, and all pools are destroyed
// together after refinement, when no list is read any more.
//
// Blocks are made 64 at a time (64 KiB), and a block is first written when
// it is handed out.  Each of the 64 lanes has a slab it has not used up:
// slabs of 1 MiB whose blocks were all initialised when made held 36 MiB
// of the graded pipe's -j2 peak that no list ever used.
class BlockPool {
public:
    DeferredBlock* take() {
        DeferredBlock* b = free_;
        if (b != nullptr) {
            free_ = b->next;
        } else {
            if (unused_ == 0) {
                made_.push_back(std::make_unique_for_overwrite<DeferredBlock[]>(slab_blocks));
                unused_ = slab_blocks;
            }
            b = &made_.back()[slab_blocks - unused_--];
        }
        b->next = nullptr;
        b->size = 0;
        return b;
    }
    void give(DeferredBlock* b) {
        b->next = free_;
        free_ = b;
    }

private:
    static constexpr std::size_t slab_blocks = 64;
    std::vector<std::unique_ptr<DeferredBlock[]>> made_;
    std::size_t unused_ = 0;  // blocks of the last slab never handed out
    DeferredBlock* free_ = nullptr;
};

// How far ahead of the entry being read drain() shows entries to its `ahead`
// callback (and to its `near` callback, half as far): the triangles a list
// names lie anywhere in a mesh of hundreds of megabytes, so each read misses
// the caches; asking for the memory of an entry this many steps early lets
// those misses overlap instead of following one another.  Two distances
// serve a reader that needs memory found through the entry's (the
// triangle's corners): by the time an entry is near, its triangle has
// mostly arrived.
inline constexpr std::uint32_t look_ahead = 8;
inline constexpr std::uint32_t look_near = look_ahead / 2;

class DeferredList {
public:
    std::size_t size() const { return size_; }

    void push(DeferredTriangle e, BlockPool& pool) {
        if (head_ == nullptr || head_->size == DeferredBlock::capacity) [[unlikely]]
            add_block(pool);
        head_->items[head_->size++] = e;
        ++size_;
    }

    // Whether sweep() would be worth its reads: the list has doubled since
    // it was last swept (or made), and holds more than a few blocks.  So a
    // list is read at most about twice per entry it was given.
    bool worth_sweeping() const {
        return size_ >= 2 * swept_size_ && size_ >= 8 * DeferredBlock::capacity;
    }
    // Drops the entries that alive(e) calls dead and packs the others, in
    // their order, into as few blocks as they fill; gives the emptied
    // blocks back.  (Entries pushed later may then be read before them
    // rather than after: nothing that reads a list depends on its order,
    // for counts add up the same in any order.)  alive.ahead(e) is called
    // look_ahead entries before alive(e), for prefetching.
    template <class Alive>
    void sweep(Alive&& alive, BlockPool& pool) {
        DeferredBlock* w = head_;
        std::uint32_t wi = 0;
        std::size_t kept = 0;
        // The write position never passes the read position: a block is
        // written past its first entries only once it has been read.
        for (DeferredBlock* r = head_; r != nullptr; r = r->next) {
            for (std::uint32_t i = 0; i < look_ahead && i < r->size; ++i) alive.ahead(r->items[i]);
            for (std::uint32_t i = 0; i < r->size; ++i) {
                if (i + look_ahead < r->size) alive.ahead(r->items[i + look_ahead]);
                if (!alive(r->items[i])) continue;
                if (wi == DeferredBlock::capacity) {
                    w->size = wi;
                    w = w->next;
                    wi = 0;
                }
                w->items[wi++] = r->items[i];
                ++kept;
            }
        }
        DeferredBlock* spare = nullptr;
        if (kept == 0) {
            spare = head_;
            head_ = nullptr;
        } else {
            w->size = wi;
            spare = w->next;
            w->next = nullptr;
        }
        while (spare != nullptr) {
            DeferredBlock* next = spare->next;
            pool.give(spare);
            spare = next;
        }
        size_ = kept;
        swept_size_ = kept;
    }

    // Takes over the entries of `from` (left empty) without reading them:
    // its blocks are linked in as they are (in constant time when this list
    // is empty, as a new leaf's is).
    void take(DeferredList& from) {
        if (from.head_ == nullptr) return;
        if (head_ != nullptr) {
            DeferredBlock* last = from.head_;
            while (last->next != nullptr) last = last->next;
            last->next = head_;
        }
        head_ = from.head_;
        size_ += from.size_;
        swept_size_ += from.swept_size_;
        from.head_ = nullptr;
        from.size_ = 0;
        from.swept_size_ = 0;
    }

    template <class F>
    void for_each(F&& f) const {
        for (const DeferredBlock* b = head_; b != nullptr; b = b->next)
            for (std::uint32_t i = 0; i < b->size; ++i) f(b->items[i]);
    }

    // Calls f on every entry and empties the list, giving each block back
    // as soon as it is read (f may push onto other lists from the same
    // pool).  For prefetching, within a block, ahead(e) is called on each
    // entry look_ahead entries before f(e), and near(e) look_near entries
    // before (not for a block's first look_near entries).
    template <class F, class Ahead, class Near>
    void drain(F&& f, Ahead&& ahead, Near&& near, BlockPool& pool) {
        DeferredBlock* b = head_;
        head_ = nullptr;
        size_ = 0;
        swept_size_ = 0;
        while (b != nullptr) {
            show_ahead(*b, ahead);
            for (std::uint32_t i = 0; i < b->size; ++i) {
                if (i + look_ahead < b->size) ahead(b->items[i + look_ahead]);
                if (i + look_near < b->size) near(b->items[i + look_near]);
                f(b->items[i]);
            }
            DeferredBlock* next = b->next;
            pool.give(b);
            b = next;
        }
    }

private:
    // (Out of line: push is made for every triangle a worker creates, and
    // its inlined fast path stays small.)
    [[gnu::noinline]] void add_block(BlockPool& pool) {
        DeferredBlock* b = pool.take();
        b->next = head_;
        head_ = b;
    }
    // The first entries of a block, before its first is read.
    template <class Ahead>
    static void show_ahead(const DeferredBlock& b, Ahead& ahead) {
        for (std::uint32_t i = 0; i < look_ahead && i < b.size; ++i) ahead(b.items[i]);
    }

    DeferredBlock* head_ = nullptr;
    std::size_t size_ = 0;
    std::size_t swept_size_ = 0;  // size_ after the last sweep
};

}  // namespace gpdr::parallel
