#pragma once
// The temporary files of every OutputTransaction in the process, in a form
// a signal handler can read: when gpdr is killed (SIGINT, SIGTERM, SIGHUP)
// the program's handler removes them all with remove_temporary_files()
// before it dies, so that no half-written hidden file is left behind.
//
// The table is a fixed array of slots, each holding one path in place (no
// allocation, no lock): a slot is free, being written, or live, and the
// handler unlinks only live ones.  A process writes a handful of files at
// a time; when every slot is taken, or a path is longer than a slot holds,
// the file is simply not listed (it is still removed by the transaction on
// any error that does not kill the process).

#include <cstddef>

#include <signal.h>

namespace gpdr::io::detail {

class TemporaryFileSlot {
public:
    // Lists `path` (a null-terminated path of `length` characters).
    TemporaryFileSlot(const char* path, std::size_t length) noexcept;
    ~TemporaryFileSlot();  // unlists it (does not remove the file)
    TemporaryFileSlot(const TemporaryFileSlot&) = delete;
    TemporaryFileSlot& operator=(const TemporaryFileSlot&) = delete;

    // Unlists the path now (the file was renamed or removed).
    void release() noexcept;

private:
    int index_ = -1;  // -1: not listed
};

// Holds SIGINT, SIGTERM and SIGHUP back from the calling thread while it
// lives, so that renaming a run's files into place is not cut short
// between two files (a signal that arrives meanwhile is delivered when the
// object is destroyed).  Other threads of the process must not be running
// with those signals unblocked for this to hold; gpdr's own threads have
// all finished by the time its files are renamed.
class SignalsHeld {
public:
    SignalsHeld() noexcept;
    ~SignalsHeld();
    SignalsHeld(const SignalsHeld&) = delete;
    SignalsHeld& operator=(const SignalsHeld&) = delete;

private:
    sigset_t previous_;
};

}  // namespace gpdr::io::detail
