#!/usr/bin/env python3
"""Runs a command with a pseudo-terminal as its standard input, output and
error, as if typed at a terminal, and exits with the command's status.  What
the terminal shows is discarded (or copied to standard output with --show).

    scripts/on-terminal.py [--show] [--stderr FILE] [--time] COMMAND [ARG ...]

--stderr FILE sends the command's standard error to FILE instead, so that two
runs differ only there; --time prints the seconds from the start to the exit
on standard error.  For the benchmarks (the progress line's cost) and the
ThreadSanitizer run of gpdr with its progress thread: the tests use their
own forkpty() helper (tests/cli/progress_cli_test.cpp).
"""
import os
import pty
import sys
import time


def main(argv):
    show = stderr = timed = None
    while argv and argv[0].startswith("--"):
        option = argv.pop(0)
        if option == "--show":
            show = True
        elif option == "--time":
            timed = True
        elif option == "--stderr" and argv:
            stderr = argv.pop(0)
        else:
            sys.exit(__doc__)
    if not argv:
        sys.exit(__doc__)
    start = time.monotonic()
    pid, fd = pty.fork()
    if pid == 0:
        if stderr is not None:
            err = os.open(stderr, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
            os.dup2(err, 2)
        try:
            os.execvp(argv[0], argv)
        finally:
            os._exit(127)
    while True:
        try:
            data = os.read(fd, 65536)
        except OSError:  # EIO: the command closed its side
            break
        if not data:
            break
        if show:
            sys.stdout.buffer.write(data)
    _, status = os.waitpid(pid, 0)
    if timed:
        print(f"{time.monotonic() - start:.3f}", file=sys.stderr)
    return os.waitstatus_to_exitcode(status)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
