#pragma once
// Fifos for the tests of input that is not a regular file: a fifo made in a
// scratch folder and a background writer that copies a file (or a device
// such as /dev/zero) into it.  The writer runs under `timeout`, its open of
// the fifo included, so a test whose reader never opens the fifo, or stops
// reading early, leaves no process behind and cannot hang: a writer whose
// reader closed the fifo dies of SIGPIPE at its next write.

#include <sys/stat.h>
#include <sys/types.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace gpdr::test {

// Makes the fifo `fifo` and starts a writer that copies `source` into it,
// giving up after `seconds`.  Returns false if either step failed.
inline bool feed_fifo(const std::filesystem::path& fifo, const std::filesystem::path& source,
                      int seconds = 30) {
    if (::mkfifo(fifo.c_str(), 0600) != 0) return false;
    const std::string command = "(timeout " + std::to_string(seconds) + " sh -c 'exec cat \"" +
                                source.string() + "\" > \"" + fifo.string() +
                                "\"' >/dev/null 2>&1 &)";
    return std::system(command.c_str()) == 0;
}

}  // namespace gpdr::test
