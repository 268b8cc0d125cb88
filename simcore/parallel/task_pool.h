#pragma once
// A small pool of worker threads for the step's data-parallel stages: parallelFor splits an index
// range into fixed chunks and runs them on the workers and the calling thread. Which thread runs
// a chunk varies from call to call, the chunks do not, so a stage whose chunks write disjoint data
// and whose reductions are combined in chunk order gives the same bits for any thread count.
//
// parallelSumInPhases runs several such ranges one after another as a single job, for passes whose
// pieces depend on the piece before (the solver's colours).
//
// Idle workers spin briefly (the jobs of a step come microseconds apart), then look between
// yields for a while, then sleep on a condition variable until the next job. One pool runs one
// job at a time and a call returns only when every chunk has run. It allocates when created (and
// parallelSum when a job has more chunks or phases than ever before), never otherwise, so a step
// in steady state allocates nothing.

#include <algorithm>
#include <atomic>
#include <cassert>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace simcore {

class TaskPool {
public:
    // threads: how many threads run a parallelFor, the caller's included; 0 means one per core
    // (std::thread::hardware_concurrency), 1 runs everything on the calling thread.
    explicit TaskPool(int threads = 1);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    int threadCount() const { return static_cast<int>(workers_.size()) + 1; }
    // The threads a parallelFor runs on now: 1 while the workers are off.
    int activeThreadCount() const { return workersEnabled_ ? threadCount() : 1; }

    // Jobs offered to the workers so far: each a hand-over, of a few hundred nanoseconds between
    // cores that share a cache, and tens of microseconds where it wakes a worker that went to sleep.
    std::uint64_t jobsOffered() const { return jobsOffered_; }
    // Jobs so far that the workers would have been offered, whether they were on or off: where a
    // stretch of work has none, it runs the same with the workers off as on.
    std::uint64_t sharableJobs() const { return sharableJobs_; }

    // The CPU participant p (0: the caller, i: worker i) was last seen on, -1 if not yet or where
    // the platform does not say.
    int lastCpu(int participant) const {
        return progress_[static_cast<std::size_t>(participant)].cpu.load(std::memory_order_relaxed);
    }

    // Off: parallelFor runs every chunk on the calling thread, in chunk order, as with one thread
    // (the same chunks, so the same results). For work the workers would only slow down.
    void setWorkersEnabled(bool enabled) { workersEnabled_ = enabled; }

    // Chunks of `grain` indices (the last may be shorter): the unit of work.
    static std::size_t chunkCount(std::size_t count, std::size_t grain) { return (count + grain - 1) / grain; }

    // Calls body(chunk, begin, end) for every chunk of [0, count); chunk k is [k grain, (k + 1) grain)
    // clipped to count. With one thread or one chunk it runs inline, in chunk order.
    template <class Body>
    void parallelFor(std::size_t count, std::size_t grain, Body&& body) {
        const std::size_t chunks = chunkCount(count, grain);
        if (!sharable(chunks > 1) || !workersEnabled_) {
            for (std::size_t k = 0; k < chunks; ++k) body(k, k * grain, std::min(count, (k + 1) * grain));
            return;
        }
        auto call = [](void* context, std::size_t, std::size_t chunk, std::size_t begin, std::size_t end) {
            (*static_cast<Body*>(context))(chunk, begin, end);
            return std::uint64_t{0};
        };
        phaseSize_[0] = count;
        phaseFirstChunk_[1] = chunks;
        run({call, &body, grain, 1});
    }

    // Whether phases run one after another, the widest of widestChunks chunks, give `threads`
    // threads work to share. Phases of at most one chunk per thread leave no thread anything to
    // take over from a slower one, only a wait at the end of every phase, and each chunk there is
    // a few hundred nanoseconds of work, about what that wait costs (tower20 solves two colours of
    // ten manifolds, one chunk each; a tower of 40 two of twenty, two chunks each: with workers
    // its steps took 2-5 us longer, and learning and probing them cost 1 % of its run).
    static bool phasesShareable(std::size_t phases, std::size_t widestChunks, std::size_t threads) {
        return widestChunks > 1 && (phases <= 1 || widestChunks > threads);
    }

    // Sums count(begin, end) over the chunks of [0, count), as parallelFor runs them. Each thread
    // adds up the counts of the chunks it ran and the caller adds the threads' sums: integers, so
    // the total is the same for any thread count, and no count is a variable threads share.
    template <class Count>
    std::uint64_t parallelSum(std::size_t count, std::size_t grain, Count&& countChunk) {
        return parallelSumInPhases(1, grain, [count](std::size_t) { return count; },
                                   [&](std::size_t, std::size_t begin, std::size_t end) { return countChunk(begin, end); });
    }

    // parallelSum over [0, phaseSize(q)) with countChunk(q, begin, end) for the phases q = 0, 1, ...
    // in turn, as one job: no chunk of a phase starts before every chunk of the phase before has
    // finished, so a phase may read what the one before wrote. Between phases a participant only
    // waits for the others' chunks, where a parallelFor per phase hands a new job to the workers and
    // waits for them to leave the last: a solver colour takes a few microseconds, and that
    // hand-over was a fifth of it.
    template <class Size, class Count>
    std::uint64_t parallelSumInPhases(std::size_t phases, std::size_t grain, Size&& phaseSize, Count&& countChunk) {
        if (phaseSize_.size() < phases) growPhases(phases);  // only when the work grew
        std::size_t chunks = 0, widestPhase = 0;
        for (std::size_t q = 0; q < phases; ++q) {
            phaseSize_[q] = phaseSize(q);
            phaseFirstChunk_[q] = chunks;
            const std::size_t phaseChunks = chunkCount(phaseSize_[q], grain);
            widestPhase = std::max(widestPhase, phaseChunks);
            chunks += phaseChunks;
        }
        phaseFirstChunk_[phases] = chunks;
        std::uint64_t sum = 0;
        if (!sharable(phasesShareable(phases, widestPhase, progress_.size())) || !workersEnabled_) {
            for (std::size_t q = 0; q < phases; ++q)
                for (std::size_t k = 0, n = phaseFirstChunk_[q + 1] - phaseFirstChunk_[q]; k < n; ++k)
                    sum += countChunk(q, k * grain, std::min(phaseSize_[q], (k + 1) * grain));
            return sum;
        }
        auto call = [](void* context, std::size_t phase, std::size_t, std::size_t begin, std::size_t end) {
            return std::uint64_t{(*static_cast<std::remove_reference_t<Count>*>(context))(phase, begin, end)};
        };
        run({call, &countChunk, grain, phases});
        for (const Progress& progress : progress_) sum += progress.sum;
        return sum;
    }

    // Sequences of steps that wait for one another's steps, one sequence per thread: calls
    // sequence(s) for s = 0 .. threadCount() - 1 at once, each on a thread of its own, and returns
    // the sum of what they return. Within sequence s, publishSteps(s, n) says it has done n steps
    // and awaitSteps(t, n) waits until sequence t has said at least n, after which s may read what
    // those steps wrote. One thread could not run them in turn (a sequence may wait for a later
    // one), so only while activeThreadCount() > 1. (A thread that finishes its own sequence may
    // then run one that no thread has started: every sequence it could wait for has started.)
    template <class Sequence>
    std::uint64_t runSequences(Sequence&& sequence) {
        assert(activeThreadCount() > 1);
        for (Progress& progress : progress_) progress.stepsDone.store(0, std::memory_order_relaxed);
        return parallelSum(progress_.size(), 1, [&](std::size_t begin, std::size_t end) {
            std::uint64_t sum = 0;
            for (std::size_t s = begin; s < end; ++s) sum += sequence(s);
            return sum;
        });
    }
    void publishSteps(std::size_t sequence, std::uint32_t steps) {
        progress_[sequence].stepsDone.store(steps, std::memory_order_release);
    }
    // Returns the steps sequence t had done when it returned: at least `steps`.
    std::uint32_t awaitSteps(std::size_t sequence, std::uint32_t steps);

private:
    // A job without its type, so workers need no std::function (which may allocate): call(context,
    // phase, chunk, begin, end) for the chunks of each phase, the phases' sizes in phaseSize_; it
    // returns the chunk's count, summed per participant.
    struct Job {
        std::uint64_t (*call)(void*, std::size_t, std::size_t, std::size_t, std::size_t) = nullptr;
        void* context = nullptr;
        std::size_t grain = 0, phases = 0;
    };
    // Whether a job that `wide` says has work for more than one thread can be shared here, counted.
    bool sharable(bool wide) {
        if (workers_.empty() || !wide) return false;
        ++sharableJobs_;
        return true;
    }
    void growPhases(std::size_t phases);
    void run(const Job& job);
    void wakeSleepingWorkers();
    void workerLoop(int participant);
    // Takes chunks of the current job until none is left: first from the participant's own share,
    // then from the others'.
    void runChunks(int participant);
    // Waits until generation_ differs from `seen` (or the pool stops): spinning and yielding first,
    // since a step's jobs follow each other within microseconds, then asleep. Returns the generation.
    std::uint64_t awaitGeneration(std::uint64_t seen, int participant);
    // Moves a waiting worker off a CPU that another participant was last seen on (see the .cpp).
    void leaveSharedCpu(int participant);

    // What the threads write while a job runs (the generation, the count of busy workers, each
    // participant's progress) has cache lines of its own, apart from the job they read, wherever
    // the heap puts the pool.
    std::vector<std::thread> workers_;
    std::vector<int> cpusAllowed_;  // the CPUs the creating thread could run on
    bool workersEnabled_ = true;
    std::uint64_t jobsOffered_ = 0;  // the caller's own counts
    std::uint64_t sharableJobs_ = 0;
    alignas(64) Job job_;  // written by run() only while no worker is in a job
    // Odd while a job is open to workers. A worker joins by counting itself in busyWorkers_ and
    // then finding the generation unchanged; run() closes the job and then waits for busyWorkers_
    // to reach zero, so it never misses a worker that joined (both sides are sequentially consistent).
    alignas(64) std::atomic<std::uint64_t> generation_{0};
    // Each phase's chunks are dealt out in one contiguous share per participant (the caller is 0,
    // worker i is i), and each takes its own share first: a colour's batches of the solver then go
    // to the same core pass after pass, with their data in its cache. Taken freely, chunks moved
    // between cores every pass (2-core machine, 2026-12-04: pyramid10 at 2 threads 0.53 of 1
    // thread's speed, 0.64 with shares). A participant that finds its share done takes what is
    // left of the others'.
    struct alignas(64) Share {
        std::atomic<std::size_t> next{0};  // the next chunk of the share nobody has taken yet
        std::size_t end = 0;
    };
    std::vector<Share> shares_;  // by phase, then participant
    // Each participant's part of the current job: the chunks it has run, as it last published
    // (release) on finishing its part of a phase (phase q is done when they add up to
    // phaseFirstChunk_[q + 1]), and the sum of its chunks' counts (integers: the total is the same
    // whichever thread ran which chunk), written as it leaves the job.
    // And the CPU the participant was last seen on (-1: not yet, or the platform does not say):
    // the caller's as it offers a job, a worker's as it waits for one.
    struct alignas(64) Progress {
        std::atomic<std::size_t> chunksRun{0};
        std::atomic<std::uint32_t> stepsDone{0};  // of sequence p, in runSequences
        std::uint64_t sum = 0;
        std::atomic<int> cpu{-1};
    };
    std::vector<Progress> progress_;         // by participant
    std::vector<std::size_t> phaseSize_;     // the current job's, by phase
    std::vector<std::size_t> phaseFirstChunk_;  // by phase, and one past the last: chunks before it
    alignas(64) std::atomic<int> busyWorkers_{0};  // workers in the current job
    std::atomic<int> sleepingWorkers_{0};    // workers blocked on wake_ (changed under mutex_)
    bool wakeCalled_ = false;                // notified since a worker last went to sleep (under mutex_)
    std::atomic<bool> stopping_{false};
    std::mutex mutex_;  // only for sleeping and waking
    std::condition_variable wake_;
};

}  // namespace simcore
