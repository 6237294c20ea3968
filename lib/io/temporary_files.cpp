// The process's table of temporary output files (see temporary_files.hpp).
//
// A slot's state goes free -> claimed (by the thread listing a path, which
// then copies the path in) -> live -> free.  The signal handler unlinks the
// path of every live slot: only atomic loads and unlink(), both
// async-signal-safe.  A path is written only while its slot is claimed, so
// the handler never reads one being written (unless the slot is freed and
// claimed again while the handler runs, when the worst it can remove is
// another of the process's own temporaries).

#include "io/temporary_files.hpp"

#include <array>
#include <atomic>
#include <cstring>

#include <pthread.h>
#include <unistd.h>

#include <gpdr/io.hpp>

namespace gpdr::io {

namespace {

constexpr int slot_count = 64;
constexpr std::size_t path_capacity = 4096;  // PATH_MAX on Linux, with its null

enum State : int { free_slot = 0, claimed = 1, live = 2 };

struct Slot {
    std::atomic<int> state{free_slot};
    char path[path_capacity];
};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the states");

std::array<Slot, slot_count> slots;

}  // namespace

void remove_temporary_files() noexcept {
    for (Slot& s : slots)
        if (s.state.load(std::memory_order_acquire) == live) ::unlink(s.path);
}

namespace detail {

TemporaryFileSlot::TemporaryFileSlot(const char* path, std::size_t length) noexcept {
    if (length >= path_capacity) return;
    for (int i = 0; i < slot_count; ++i) {
        int expected = free_slot;
        if (slots[static_cast<std::size_t>(i)].state.compare_exchange_strong(
                expected, claimed, std::memory_order_acquire)) {
            Slot& s = slots[static_cast<std::size_t>(i)];
            std::memcpy(s.path, path, length + 1);
            s.state.store(live, std::memory_order_release);
            index_ = i;
            return;
        }
    }
}

TemporaryFileSlot::~TemporaryFileSlot() { release(); }

void TemporaryFileSlot::release() noexcept {
    if (index_ < 0) return;
    slots[static_cast<std::size_t>(index_)].state.store(free_slot, std::memory_order_release);
    index_ = -1;
}

SignalsHeld::SignalsHeld() noexcept {
    sigset_t held;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    sigaddset(&held, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &held, &previous_);
}

SignalsHeld::~SignalsHeld() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }

}  // namespace detail

}  // namespace gpdr::io
