#pragma once
// One thread that runs the jobs it is given, one at a time, away from the GUI thread: the
// simulation controller steps its world here. Plain C++. A long job polls stopRequested() (or
// sleeps in sleepFor, which wakes early) so that its owner can end it; the owner keeps off whatever
// the job touches until wait() has returned, and the job tells the owner's thread what it needs to
// by posting, never by calling into it.

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace interplay {

class WorkerThread {
public:
    WorkerThread();
    ~WorkerThread();  // ends the job in flight (as stop() does), then the thread
    WorkerThread(const WorkerThread&) = delete;
    WorkerThread& operator=(const WorkerThread&) = delete;

    // Runs `job` on the thread; the job in flight, if any, is waited for first.
    void start(std::function<void()> job);
    // Returns once no job is in flight.
    void wait();
    // Asks the job in flight to return, and waits for it.
    void stop();

    // For the job: whether its owner asked it to return.
    bool stopRequested();
    // For the job: sleeps for `duration`, or less if asked to return; false if it was.
    bool sleepFor(std::chrono::nanoseconds duration);

private:
    void run();

    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::function<void()> m_job;  // the job in flight, empty when idle
    bool m_stop = false;          // the job in flight is asked to return
    bool m_quit = false;
    std::thread m_thread;  // last: it starts once the members it uses exist
};

}  // namespace interplay
