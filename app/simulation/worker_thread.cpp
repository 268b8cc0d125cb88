#include "app/simulation/worker_thread.h"

#include <utility>

namespace interplay {

WorkerThread::WorkerThread() : m_thread([this] { run(); }) {}

WorkerThread::~WorkerThread() {
    {
        std::unique_lock lock(m_mutex);
        m_stop = true;
        m_changed.notify_all();
        m_changed.wait(lock, [this] { return !m_job; });
        m_quit = true;
    }
    m_changed.notify_all();
    m_thread.join();
}

void WorkerThread::start(std::function<void()> job) {
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return !m_job; });
        m_job = std::move(job);
        m_stop = false;
    }
    m_changed.notify_all();
}

void WorkerThread::wait() {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return !m_job; });
}

void WorkerThread::stop() {
    std::unique_lock lock(m_mutex);
    m_stop = true;
    m_changed.notify_all();  // a job in sleepFor wakes
    m_changed.wait(lock, [this] { return !m_job; });
}

bool WorkerThread::stopRequested() {
    std::lock_guard lock(m_mutex);
    return m_stop;
}

bool WorkerThread::sleepFor(std::chrono::nanoseconds duration) {
    std::unique_lock lock(m_mutex);
    return !m_changed.wait_for(lock, duration, [this] { return m_stop; });
}

void WorkerThread::run() {
    std::unique_lock lock(m_mutex);
    for (;;) {
        m_changed.wait(lock, [this] { return m_quit || m_job; });
        if (!m_job) return;  // quit, with nothing left to run
        const std::function<void()> job = m_job;
        lock.unlock();
        job();
        lock.lock();
        m_job = nullptr;
        m_changed.notify_all();
    }
}

}  // namespace interplay
