#pragma once
// Runs a list of independent tasks on a few threads: each thread (this one
// among them) takes the next task nobody has taken, so a long task and many
// short ones share the threads evenly.  For the parallel reader, whose
// tasks are known up front and few (tens), not for fine-grained work.

#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace gpdr::io::detail {

// Calls task(i) once for every i in [0, count), on `threads` threads in all;
// returns when all are done, rethrowing the first exception one threw (the
// others still run: a task cannot be half-done for its caller).
template <class Task>
void run_tasks(unsigned threads, std::size_t count, const Task& task) {
    std::atomic<std::size_t> next{0};
    std::mutex failure_mutex;
    std::exception_ptr failure;
    const auto work = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            try {
                task(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    const std::size_t helpers = std::min<std::size_t>(threads, count) - (count > 0 ? 1 : 0);
    std::vector<std::thread> pool;
    pool.reserve(helpers);
    for (std::size_t t = 0; t < helpers; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace gpdr::io::detail
