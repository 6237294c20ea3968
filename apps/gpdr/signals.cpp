// Signal handling (see signals.hpp).  The handler does only
// async-signal-safe work: unlink() through io::remove_temporary_files and
// raise().  SA_RESETHAND restores the default action on entry, and the
// signal stays blocked while the handler runs, so the raise() takes effect,
// with the default action (termination), as soon as the handler returns.

#include "signals.hpp"

#include <csignal>

#include <gpdr/io.hpp>

namespace gpdr::app {

namespace {

extern "C" void remove_temporaries_and_die(int signal) {
    gpdr::io::remove_temporary_files();
    std::raise(signal);
}

}  // namespace

void remove_temporaries_on_signals() {
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_die;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
        // A signal the caller chose to ignore (nohup's SIGHUP) stays ignored.
        struct sigaction old {};
        if (sigaction(signal, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        sigaction(signal, &action, nullptr);
    }
}

}  // namespace gpdr::app
