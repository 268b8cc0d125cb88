#include "app/simulation/worker_thread.h"

#include <utility>

namespace interplay {

WorkerThread::WorkerThread() : m_thread([this] { run(); }) {}

WorkerThread::~WorkerThread() {
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return !m_job; });
        m_quit = true;
    }
    m_changed.notify_all();
    m_thread.join();
}

void WorkerThread::start(std::function<void()> job, std::function<void()> done) {
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return !m_job; });
        m_job = std::move(job);
        m_done = std::move(done);
    }
    m_changed.notify_all();
}

void WorkerThread::wait() {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return !m_job; });
}

void WorkerThread::run() {
    std::unique_lock lock(m_mutex);
    for (;;) {
        m_changed.wait(lock, [this] { return m_quit || m_job; });
        if (!m_job) return;  // quit, with nothing left to run
        const std::function<void()> job = m_job, done = std::exchange(m_done, {});
        lock.unlock();
        job();
        // Before the job counts as done: once wait() returns the owner may be destroyed, and
        // `done` must not post to it then.
        if (done) done();
        lock.lock();
        m_job = nullptr;
        m_changed.notify_all();
    }
}

}  // namespace interplay
