#pragma once
// Runs a program (the suites' interplay-run) to completion and hands back its exit code, stdout,
// stderr, wall time and peak memory. posix_spawn rather than QProcess: Qt 6.4 starts a child with
// clone(CLONE_VM | CLONE_VFORK), which clang 14's ThreadSanitizer runtime (Debian 12's) takes for
// a fork and then fails its own check in the parent (tsan_rtl.cpp:234, "!thr->slot") on every
// start, so no suite that ran the runner could run under TSan. glibc's posix_spawn makes the same
// vfork-like clone internally, where the runtime does not intercept it.

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <spawn.h>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <vector>

extern char** environ;

namespace test_support {

struct ProgramRun {
    bool finished = false;  // started, and exited by itself within the time allowed
    int exitCode = -1;      // -1 unless it exited normally
    QByteArray out, err;
    double seconds = 0.0;  // wall time from start to exit
    double peakMiB = 0.0;  // the child's peak resident memory (ru_maxrss)
};

inline ProgramRun runProgram(const QString& program, const QStringList& arguments, int timeoutMs = 60'000,
                             const QString& workingDirectory = {}) {
    ProgramRun run;
    QTemporaryDir dir;  // the child's stdout and stderr: files, so neither can fill a pipe and block it
    if (!dir.isValid()) return run;
    const std::string outPath = dir.filePath("stdout").toStdString();
    const std::string errPath = dir.filePath("stderr").toStdString();
    std::vector<std::string> args{program.toStdString()};
    for (const QString& a : arguments) args.push_back(a.toStdString());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const std::string cwd = workingDirectory.toStdString();
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return run;

    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    rusage usage{};
    for (;;) {
        const pid_t waited = wait4(pid, &status, WNOHANG, &usage);
        if (waited == pid) break;
        if (waited < 0) return run;
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return run;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.peakMiB = double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
    run.finished = WIFEXITED(status);
    run.exitCode = run.finished ? WEXITSTATUS(status) : -1;
    QFile out(QString::fromStdString(outPath)), err(QString::fromStdString(errPath));
    if (out.open(QIODevice::ReadOnly)) run.out = out.readAll();
    if (err.open(QIODevice::ReadOnly)) run.err = err.readAll();
    return run;
}

}  // namespace test_support
