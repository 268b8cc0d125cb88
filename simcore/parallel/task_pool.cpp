#include "simcore/parallel/task_pool.h"

#include <chrono>
#include <utility>

#if defined(__linux__)
#include <sched.h>
#endif

#if defined(__x86_64__) || defined(_M_X64) || defined(__i386__)
#include <immintrin.h>
#endif

namespace simcore {

namespace {

// How long an idle worker keeps looking for the next job before it sleeps. Within a step, jobs
// follow each other within microseconds (a colour of the solver is one): a worker woken through
// the condition variable for each took longer to start than the job took (pyramid10: 2 threads
// 1.3x slower than 1 on an idle machine). Spinning on the core for longer (50 us) burnt the time
// slices a loaded machine gives the process (pyramid10 at load 16: 2 threads 12 ms a step against
// 4 ms with 10 us), so after kSpinTime a worker keeps looking between yields, which hand the core
// to any other thread that wants it, and sleeps only after kYieldTime. The serial stages between
// a step's parallel ones (pairs, islands, integration kept inline) outlast 10 us: a worker that
// slept through them woke too late for the next stage's first jobs (2026-12-04, 2-core EPYC, 2
// threads against 1: pyramid10 1.43x -> 1.48x, mixed1k 1.14x -> 1.39x, pile1k 1.29x -> 1.36x;
// under 8 and 16 busy processes no slower than sleeping after 10 us).
constexpr auto kSpinTime = std::chrono::microseconds(10);
constexpr auto kYieldTime = std::chrono::microseconds(200);
// A thread waiting for the workers of its job yields after this many pauses: a worker that was
// descheduled in the middle of a chunk then gets the core back sooner on a busy machine.
constexpr int kPausesBeforeYield = 64;

void pause(int spins) {
    if (spins >= kPausesBeforeYield) {
        std::this_thread::yield();
        return;
    }
#if defined(__x86_64__) || defined(_M_X64) || defined(__i386__)
    _mm_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
}

// The CPU the calling thread runs on now; -1 where the platform does not say.
int currentCpu() {
#if defined(__linux__)
    return sched_getcpu();
#else
    return -1;
#endif
}

std::vector<int> cpusAllowed() {
    std::vector<int> cpus;
#if defined(__linux__)
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0)
        for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
            if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
#endif
    return cpus;
}

}  // namespace

TaskPool::TaskPool(int threads) : cpusAllowed_(cpusAllowed()) {
    const int total = threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    progress_ = std::vector<Progress>(static_cast<std::size_t>(total));
    growPhases(1);
    workers_.reserve(static_cast<std::size_t>(total - 1));
    for (int i = 1; i < total; ++i) workers_.emplace_back([this, i] { workerLoop(i); });
}

void TaskPool::growPhases(std::size_t phases) {
    phaseSize_.resize(phases);
    phaseFirstChunk_.resize(phases + 1, 0);
    shares_ = std::vector<Share>(phases * progress_.size());
}

TaskPool::~TaskPool() {
    stopping_.store(true);
    { std::lock_guard lock(mutex_); }  // a worker between its check and its wait holds the mutex
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

// The caller never waits for a worker to wake: on a busy machine a descheduled worker took
// milliseconds to, ten times what pyramid10's step took. Workers join the job while it is open (odd
// generation), the caller runs whatever chunks are left, closes it, and waits only for the workers
// that joined and may still be running a chunk of it (its body lives on the caller's stack).
void TaskPool::run(const Job& job) {
    ++jobsOffered_;
    job_ = job;
    const std::size_t participants = progress_.size();
    for (std::size_t q = 0; q < job.phases; ++q) {
        const std::size_t first = phaseFirstChunk_[q], chunks = phaseFirstChunk_[q + 1] - first;
        for (std::size_t p = 0; p < participants; ++p) {
            Share& share = shares_[q * participants + p];
            share.next.store(first + chunks * p / participants, std::memory_order_relaxed);
            share.end = first + chunks * (p + 1) / participants;
        }
    }
    for (Progress& progress : progress_) {
        progress.chunksRun.store(0, std::memory_order_relaxed);
        progress.sum = 0;
    }
    progress_[0].cpu.store(currentCpu(), std::memory_order_relaxed);
    generation_.fetch_add(1);  // odd: open; publishes job_ to the workers that see it
    wakeSleepingWorkers();
    runChunks(0);
    generation_.fetch_add(1);  // even: closed to latecomers
    for (int spins = 0; busyWorkers_.load() > 0; ++spins) pause(spins);
}

// One wake-up call until a worker goes to sleep again: a job every few microseconds would otherwise
// make a system call each while the workers take tens of microseconds to wake (a stage the tuner
// probes with workers after a spell without them). The flag is cleared by a worker as it goes to
// sleep, under the mutex, not as it wakes: cleared on waking, it could be set again by a call that
// found the worker already awake, and then no call reached it when it next slept: a worker asleep
// through every later job, whose chunks the caller then ran alone.
void TaskPool::wakeSleepingWorkers() {
    if (sleepingWorkers_.load() == 0) return;
    bool call = false;
    {
        std::lock_guard lock(mutex_);
        call = !std::exchange(wakeCalled_, true);
    }
    if (call) wake_.notify_all();
}

std::uint32_t TaskPool::awaitSteps(std::size_t sequence, std::uint32_t steps) {
    for (int spins = 0;; ++spins) {
        const std::uint32_t done = progress_[sequence].stepsDone.load(std::memory_order_acquire);
        if (done >= steps) return done;
        pause(spins);
    }
}

// A worker that joins late goes through the phases already done, finding no chunk left in them.
void TaskPool::runChunks(int participant) {
    const Job& job = job_;
    const std::size_t participants = progress_.size();
    Progress& mine = progress_[static_cast<std::size_t>(participant)];
    std::size_t ran = 0;
    std::uint64_t sum = 0;
    for (std::size_t q = 0; q < job.phases; ++q) {
        const std::size_t first = phaseFirstChunk_[q];
        for (std::size_t i = 0; i < participants; ++i) {
            Share& share = shares_[q * participants + (static_cast<std::size_t>(participant) + i) % participants];
            for (std::size_t k = share.next.fetch_add(1, std::memory_order_relaxed); k < share.end;
                 k = share.next.fetch_add(1, std::memory_order_relaxed), ++ran) {
                const std::size_t chunk = k - first;
                sum += job.call(job.context, q, chunk, chunk * job.grain, std::min(phaseSize_[q], (chunk + 1) * job.grain));
            }
        }
        // The next phase may read what this one wrote: wait for the others' chunks of it.
        mine.chunksRun.store(ran, std::memory_order_release);
        const std::size_t phaseEnd = phaseFirstChunk_[q + 1];
        for (int spins = 0;; ++spins) {
            std::size_t done = 0;
            for (const Progress& progress : progress_) done += progress.chunksRun.load(std::memory_order_acquire);
            if (done >= phaseEnd) break;
            pause(spins);
        }
    }
    mine.sum = sum;  // read by run()'s caller once every worker has left the job
}

std::uint64_t TaskPool::awaitGeneration(std::uint64_t seen, int participant) {
    const auto start = std::chrono::steady_clock::now();
    const auto spinUntil = start + kSpinTime, yieldUntil = start + kYieldTime;
    bool yielding = false;
    for (int spins = 0;; ++spins) {
        const std::uint64_t generation = generation_.load();
        if (generation != seen || stopping_.load()) return generation;
        if (spins % 16 == 15) {
            leaveSharedCpu(participant);
            const auto now = std::chrono::steady_clock::now();
            if (now > yieldUntil) break;
            yielding = now > spinUntil;
        }
        if (yielding)
            std::this_thread::yield();
        else
            pause(0);
    }
    std::unique_lock lock(mutex_);
    sleepingWorkers_.fetch_add(1);  // before the check: run() either sees it or is seen by it
    wakeCalled_ = false;            // this sleep needs a call of its own
    wake_.wait(lock, [&] { return stopping_.load() || generation_.load() != seen; });
    sleepingWorkers_.fetch_sub(1);
    return generation_.load();
}

void TaskPool::workerLoop(int participant) {
    std::uint64_t seen = 0;
    for (;;) {
        seen = awaitGeneration(seen, participant);
        if (stopping_.load()) return;
        if (seen % 2 == 0) continue;  // closed before this worker came
        busyWorkers_.fetch_add(1);
        // Still the job it saw: run() cannot close and reuse job_ without seeing this worker.
        if (generation_.load() == seen) runChunks(participant);
        busyWorkers_.fetch_sub(1);
    }
}

// Two participants on one CPU only take turns on it, and the scheduler can leave them so: a worker
// that waits by spinning and yielding is always runnable and its cache always warm, so the kernel
// did not move it to the idle CPU. mixed1k at 2 threads found its worker on the caller's CPU in
// about half the runs, for tens of steps. Its first 100 steps, medians of 20 alternating runs on
// a 2-core EPYC with the cores near (2026-12-07): 1 thread 66.3 ms; 2 threads 54.7 ms before,
// 49.3 with the worker moving off (pile1k 43.4 -> 38.9, 1 thread 56.6; pyramid10's first 300
// steps 217 -> 205, 1 thread 320).
// The worker moves to the allowed CPUs on which no other participant was last seen, and stays
// free to run on any of them; where there is none (more threads than CPUs) it stays.
void TaskPool::leaveSharedCpu(int participant) {
#if defined(__linux__)
    const int cpu = currentCpu();
    progress_[static_cast<std::size_t>(participant)].cpu.store(cpu, std::memory_order_relaxed);
    cpu_set_t others;
    CPU_ZERO(&others);
    for (std::size_t p = 0; p < progress_.size(); ++p) {
        const int theirs = progress_[p].cpu.load(std::memory_order_relaxed);
        if (p != static_cast<std::size_t>(participant) && theirs >= 0 && theirs < CPU_SETSIZE) CPU_SET(theirs, &others);
    }
    if (cpu < 0 || cpu >= CPU_SETSIZE || !CPU_ISSET(cpu, &others)) return;
    cpu_set_t elsewhere;
    CPU_ZERO(&elsewhere);
    for (const int allowed : cpusAllowed_)
        if (!CPU_ISSET(allowed, &others)) CPU_SET(allowed, &elsewhere);
    if (CPU_COUNT(&elsewhere) > 0) sched_setaffinity(0, sizeof elsewhere, &elsewhere);
#else
    (void)participant;
#endif
}

}  // namespace simcore
