#include "simcore/parallel/task_pool.h"

namespace simcore {

TaskPool::TaskPool(int threads) {
    const int total = threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    workers_.reserve(static_cast<std::size_t>(total - 1));
    for (int i = 1; i < total; ++i) workers_.emplace_back([this] { workerLoop(); });
}

TaskPool::~TaskPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

// The caller never waits for a worker to wake: on a busy machine a descheduled worker took
// milliseconds to, ten times what pyramid10's step took. Workers join the job while it is open (odd
// generation), the caller runs whatever chunks are left, closes it, and waits only for the workers
// that joined and may still be running a chunk of it (its body lives on the caller's stack).
void TaskPool::run(const Job& job) {
    {
        std::lock_guard lock(mutex_);
        job_ = job;
        nextChunk_.store(0, std::memory_order_relaxed);
        ++generation_;  // odd: open
    }
    wake_.notify_all();
    runChunks();
    std::unique_lock lock(mutex_);
    ++generation_;  // even: closed to latecomers
    finished_.wait(lock, [this] { return busyWorkers_ == 0; });
}

void TaskPool::runChunks() {
    const Job& job = job_;
    for (std::size_t k = nextChunk_.fetch_add(1, std::memory_order_relaxed); k < job.chunks;
         k = nextChunk_.fetch_add(1, std::memory_order_relaxed)) {
        job.call(job.context, k, k * job.grain, std::min(job.count, (k + 1) * job.grain));
    }
}

void TaskPool::workerLoop() {
    std::uint64_t seen = 0;
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
            if (stopping_) return;
            seen = generation_;
            if (seen % 2 == 0) continue;  // closed before this worker woke
            ++busyWorkers_;               // job_ stays as it is until this worker leaves
        }
        runChunks();
        std::lock_guard lock(mutex_);
        if (--busyWorkers_ == 0) finished_.notify_one();
    }
}

}  // namespace simcore
