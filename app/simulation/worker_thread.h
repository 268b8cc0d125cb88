#pragma once
// One thread that runs the jobs it is given, one at a time, away from the GUI thread: the
// simulation controller steps its world here. Plain C++: a job says it is done by calling what the
// owner passed with it (on this thread, so it only posts to the owner's thread), then wait()
// returns. Nothing is shared with the owner but the job; the owner keeps off whatever the job
// touches until wait() has returned.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace interplay {

class WorkerThread {
public:
    WorkerThread();
    ~WorkerThread();  // waits for the job in flight, then ends the thread
    WorkerThread(const WorkerThread&) = delete;
    WorkerThread& operator=(const WorkerThread&) = delete;

    // Runs `job` on the thread, then `done` (also on the thread), unless it is empty. The job in
    // flight, if any, is waited for first.
    void start(std::function<void()> job, std::function<void()> done = {});
    // Returns once no job is in flight: the job and its `done` have returned.
    void wait();

private:
    void run();

    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::function<void()> m_job;  // the job in flight, empty when idle
    std::function<void()> m_done;
    bool m_quit = false;
    std::thread m_thread;  // last: it starts once the members it uses exist
};

}  // namespace interplay
