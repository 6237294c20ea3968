// The rounds (see rounds.hpp): the calling thread's loop, the threads that
// run the lanes, and the shape of the recorded rounds.

#include "parallel/rounds.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "mesh/pool.hpp"
#include "parallel/freed_memory.hpp"
#include "parallel/scheduler.hpp"
#include "parallel/stopwatch.hpp"
#include "parallel/worker.hpp"

namespace gpdr::parallel {

namespace {

// What one leaf's run leaves for the master.
struct RunResult {
    const std::vector<NodeId>* zone = nullptr;  // Scheduler::zone, for the run
    std::vector<NodeId> balance;  // Scheduler::take_balance_candidates, for the run
    bool split = false;
    std::vector<NodeId> balanced;
    std::vector<Routed> outbox;
    std::uint64_t work = 0;
};

// One round's leaves and their results, shared by the threads: lane l runs
// leaves l, l + lanes, ... in that order.
struct Round {
    std::vector<NodeId> leaves;
    std::vector<RunResult> results;
    unsigned lanes_used = 0;
    std::atomic<unsigned> next_lane{0};
};

// Runs lane `l`'s leaves of the round.  An exception stops the lane (its
// remaining leaves are not refined; the master completes them unchanged).
void run_lane(Worker& lane, unsigned l, unsigned lanes, Round& round, std::mutex& mutex,
              std::exception_ptr& failure) {
    for (std::size_t i = l; i < round.leaves.size(); i += lanes) {
        if (lane.stopped) return;
        RunResult& result = round.results[i];
        const std::uint64_t before = lane.report.triangles_created;
        try {
            result.split =
                lane.run(round.leaves[i], static_cast<std::int32_t>(i + 1), *result.zone,
                         result.balance);
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!failure) failure = std::current_exception();
            lane.stopped = true;
        }
        result.work = lane.report.triangles_created - before;
        result.balanced = std::move(lane.balanced);
        result.outbox = std::move(lane.outbox);
        lane.balanced.clear();
        lane.outbox.clear();
    }
}

// The threads besides the master's: each round, they take lanes until none
// is left; the master takes lanes too, then waits for them.
class LaneThreads {
public:
    LaneThreads(std::vector<std::unique_ptr<Worker>>& lanes, unsigned helpers,
                std::exception_ptr& failure, std::vector<ThreadTimes>& times)
        : lanes_(lanes), failure_(failure), times_(times) {
        times_.assign(helpers + 1, ThreadTimes{});
        for (unsigned t = 0; t < helpers; ++t) threads_.emplace_back([this, t] { loop(t + 1); });
    }
    ~LaneThreads() {
        {
            std::lock_guard lock(mutex_);
            quit_ = true;
        }
        start_.notify_all();
        for (auto& t : threads_) t.join();
    }
    LaneThreads(const LaneThreads&) = delete;
    LaneThreads& operator=(const LaneThreads&) = delete;

    // Runs the round's lanes on every thread; returns when all are done.
    // With `return_memory`, the calling thread first gives the free memory
    // back (return_freed_memory) while the others start.
    void run(Round& round, bool return_memory) {
        round.next_lane.store(0, std::memory_order_relaxed);
        const auto helpers = static_cast<unsigned>(threads_.size());
        // Only as many helpers as there are lanes beyond the master's.
        const unsigned wanted = std::min(helpers, round.lanes_used - 1);
        if (wanted > 0) {
            std::lock_guard lock(mutex_);
            round_ = &round;
            ++generation_;
            wanted_ = wanted;
            joined_ = 0;
            finished_ = 0;
        }
        // Every helper is woken, and the first `wanted` to see the new
        // round join it.  (Waking `wanted` of them one by one could wake a
        // helper that had already joined, run and gone back to wait, which
        // then finds the round full and sleeps again: the others would never
        // hear of the round.)
        if (wanted > 0) start_.notify_all();
        if (return_memory) return_freed_memory();
        take_lanes(round, 0);
        if (wanted > 0) {
            const Stopwatch clock;
            std::unique_lock lock(mutex_);
            done_.wait(lock, [&] { return finished_ == wanted_; });
            times_[0].waiting += clock.elapsed();
        }
    }

private:
    void take_lanes(Round& round, unsigned thread) {
        const Stopwatch clock;
        const auto lanes = static_cast<unsigned>(lanes_.size());
        for (;;) {
            const unsigned l = round.next_lane.fetch_add(1, std::memory_order_relaxed);
            if (l >= round.lanes_used) break;
            run_lane(*lanes_[l], l, lanes, round, mutex_, failure_);
        }
        times_[thread].refining += clock.elapsed();
    }
    void loop(unsigned thread) {
        std::uint64_t seen = 0;
        for (;;) {
            Round* round = nullptr;
            {
                const Stopwatch clock;
                std::unique_lock lock(mutex_);
                // A helper takes part in a round only while fewer than
                // `wanted_` have joined it.
                start_.wait(lock,
                            [&] { return quit_ || (generation_ != seen && joined_ < wanted_); });
                times_[thread].waiting += clock.elapsed();
                if (quit_) return;
                ++joined_;
                seen = generation_;
                round = round_;
            }
            take_lanes(*round, thread);
            bool last;
            {
                std::lock_guard lock(mutex_);
                last = ++finished_ == wanted_;
            }
            if (last) done_.notify_one();
        }
    }

    std::vector<std::unique_ptr<Worker>>& lanes_;
    std::exception_ptr& failure_;
    std::vector<ThreadTimes>& times_;
    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable start_, done_;
    Round* round_ = nullptr;
    std::uint64_t generation_ = 0;
    unsigned wanted_ = 0, joined_ = 0, finished_ = 0;
    bool quit_ = false;
};

// Between rounds: once the lanes have given back return_threshold bytes of
// queue storage since the last time, the free memory goes back to the
// system (freed_memory.hpp), by the calling thread once the next round's
// other threads are on their lanes: a trim takes 10-20 ms per run, which
// they would otherwise wait for.  Whether and when that happens changes
// nothing but the resident size.
constexpr std::uint64_t return_threshold = std::uint64_t{32} << 20;

bool memory_to_return(std::vector<std::unique_ptr<Worker>>& lanes) {
    std::uint64_t released = 0;
    for (const auto& lane : lanes) released += lane->released_bytes;
    if (released < return_threshold) return false;
    for (const auto& lane : lanes) lane->released_bytes = 0;
    return true;
}

}  // namespace

void run_rounds(std::vector<std::unique_ptr<Worker>>& lanes, Scheduler& scheduler, unsigned threads,
                bool checked, ParallelReport& report, std::exception_ptr& failure,
                const std::function<void()>& check,
                const std::function<void(const std::vector<NodeId>&)>& record) {
    const auto lane_total = static_cast<unsigned>(lanes.size());
    LaneThreads pool(lanes, std::min(threads, lane_total) - 1, failure, report.workers);
    Round round;
    Stopwatch clock;
    bool trim = false;
    std::uint64_t last_work = 0;  // the round before's, every run's
    for (;;) {
        clock.lap();
        scheduler.plan_round(round.leaves);
        if (round.leaves.empty()) break;
        const std::size_t n = round.leaves.size();
        round.results.assign(n, RunResult{});
        for (std::size_t i = 0; i < n; ++i) {
            round.results[i].zone = &scheduler.zone(static_cast<int>(i));
            round.results[i].balance = scheduler.take_balance_candidates(static_cast<int>(i));
        }
        round.lanes_used = static_cast<unsigned>(std::min<std::size_t>(n, lane_total));
        // The round's lanes claim ids above every id claimed so far, lane l
        // every lanes_used-th chunk from the l-th: a round of one leaf claims
        // chunks one after another.  (With the 64 lanes set once, a run that
        // made most of the mesh on one lane left 63 chunks unused for each
        // one it filled: ids 64 times its triangles, which met the limit of
        // 2^30 ids at about 16 million triangles.)
        const mesh::Lane base = mesh::Lane::first(lanes[0]->pool().mesh(), round.lanes_used);
        for (unsigned l = 0; l < round.lanes_used; ++l) {
            mesh::Lane lane = base;
            lane.index = l;
            lanes[l]->pool().move_to_lane(lane);
            lanes[l]->set_split_budget(round_split_budget(last_work));
        }
        report.master.managing += clock.lap();
        if (record) record(round.leaves);  // (no one's time: the lap below drops it)

        pool.run(round, trim);

        clock.lap();
        std::vector<std::uint64_t>& work = report.rounds.emplace_back(n);
        bool stopped = false;
        for (std::size_t i = 0; i < n; ++i) {
            RunResult& r = round.results[i];
            const Worker& lane = *lanes[i % lane_total];
            scheduler.complete(static_cast<int>(i), r.split, r.balanced, r.outbox,
                               lane.outgrew_root);
            work[i] = r.work;
        }
        last_work = 0;
        for (const std::uint64_t w : work) last_work += w;
        for (const auto& lane : lanes) stopped = stopped || lane->stopped;
        if (checked) check();
        trim = memory_to_return(lanes);
        report.master.managing += clock.lap();
        if (stopped || failure) break;
    }
}

ScheduleShape schedule_shape(const std::vector<std::vector<std::uint64_t>>& rounds) {
    ScheduleShape s;
    s.rounds = rounds.size();
    if (rounds.empty()) return s;
    std::vector<std::uint64_t> sizes;
    for (const auto& r : rounds) {
        sizes.push_back(r.size());
        s.runs += r.size();
        std::uint64_t largest = 0;
        for (const std::uint64_t w : r) {
            s.work += w;
            largest = std::max(largest, w);
        }
        s.span += largest;
    }
    std::sort(sizes.begin(), sizes.end());
    s.fewest = sizes.front();
    s.most = sizes.back();
    s.median = sizes[sizes.size() / 2];
    return s;
}

double predicted_speedup(const std::vector<std::vector<std::uint64_t>>& rounds, unsigned workers) {
    double work = 0, time = 0;
    for (const auto& r : rounds) {
        double sum = 0, largest = 0;
        for (const std::uint64_t w : r) {
            sum += double(w);
            largest = std::max(largest, double(w));
        }
        work += sum;
        time += std::max(largest, sum / workers);
    }
    return time == 0 ? 1.0 : work / time;
}

}  // namespace gpdr::parallel
