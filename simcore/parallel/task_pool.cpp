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

void TaskPool::run(const Job& job) {
    {
        std::lock_guard lock(mutex_);
        job_ = job;
        nextChunk_.store(0, std::memory_order_relaxed);
        busyWorkers_ = static_cast<int>(workers_.size());
        ++generation_;
    }
    wake_.notify_all();
    runChunks();
    // Every worker must have left the job before it goes out of scope (it lives on the caller's
    // stack), not only every chunk be done.
    std::unique_lock lock(mutex_);
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
        }
        runChunks();
        std::lock_guard lock(mutex_);
        if (--busyWorkers_ == 0) finished_.notify_one();
    }
}

}  // namespace simcore
