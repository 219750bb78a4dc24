#include "frontends/cli/interruption.h"

#include <fcntl.h>
#include <unistd.h>

#include <pthread.h>
#include <atomic>
#include <cerrno>
#include <csignal>

namespace sa::cli {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};

int wake_pipe[2] = {-1, -1};
std::atomic<bool> interrupted{false};  // set before the cleanup waits for the output lock
std::atomic<bool> handles_sigpipe{false};

std::mutex& output_mutex() {
    static std::mutex mutex;
    return mutex;
}

// Guarded by output_mutex().
std::function<void()>& cleanup() {
    static std::function<void()> function;
    return function;
}

extern "C" void on_signal(int signal) {
    const int saved = errno;
    const unsigned char byte = static_cast<unsigned char>(signal);
    // A full pipe means a signal is pending already: dropping this one is fine.
    [[maybe_unused]] const ssize_t written = write(wake_pipe[1], &byte, 1);
    errno = saved;
}

[[noreturn]] void clean_up_and_die(int signal) {
    output_mutex().lock();  // never unlocked: the process ends below
    if (cleanup()) {
        try {
            cleanup()();
        } catch (...) {
            // Removing what can be removed is all that is left to do.
        }
    }
    std::signal(signal, SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, signal);
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    raise(signal);
    _exit(128 + signal);  // only if the default action did not end the process
}

void* wait_for_signal(void*) {
    for (;;) {
        unsigned char byte = 0;
        const ssize_t n = read(wake_pipe[0], &byte, 1);
        if (n == 1) {
            interrupted.store(true);
            clean_up_and_die(byte);
        }
        if (n < 0 && errno == EINTR) continue;
        return nullptr;  // the pipe is gone: nothing to wait for
    }
}

}  // namespace

void install_interruption_handling() {
    if (wake_pipe[0] >= 0) return;
    if (pipe2(wake_pipe, O_CLOEXEC) != 0) return;  // no cleanup on interruption, as before
    fcntl(wake_pipe[1], F_SETFL, O_NONBLOCK);
    // A small stack: under a tight `ulimit -v` the default 8 MB could not be mapped, and the
    // thread only removes files.
    pthread_attr_t attributes;
    pthread_attr_init(&attributes);
    pthread_attr_setstacksize(&attributes, std::size_t(256) << 10);
    pthread_attr_setdetachstate(&attributes, PTHREAD_CREATE_DETACHED);
    pthread_t thread;
    const int started = pthread_create(&thread, &attributes, wait_for_signal, nullptr);
    pthread_attr_destroy(&attributes);
    if (started != 0) {  // interruptions end the process without cleanup, as before
        close(wake_pipe[0]);
        close(wake_pipe[1]);
        wake_pipe[0] = wake_pipe[1] = -1;
        return;
    }
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigset_t blocked;
    sigemptyset(&blocked);
    pthread_sigmask(SIG_BLOCK, nullptr, &blocked);
    for (const int signal : kSignals) {
        struct sigaction previous {};
        sigaction(signal, nullptr, &previous);
        // A signal the parent ignores (nohup, a shell's background job) stays ignored.
        if (previous.sa_handler == SIG_IGN) continue;
        // A blocked SIGPIPE is never delivered: a failed write to stdout is then an error.
        if (sigaction(signal, &action, nullptr) == 0 && signal == SIGPIPE &&
            sigismember(&blocked, SIGPIPE) != 1)
            handles_sigpipe.store(true);
    }
}

std::unique_lock<std::mutex> output_lock() {
    std::unique_lock<std::mutex> lock(output_mutex());
    if (interrupted.load()) {
        // No output starts once an interruption is seen: the cleanup, waiting for this lock,
        // removes what was written and ends the process.
        lock.unlock();
        for (;;) pause();
    }
    return lock;
}

void set_interruption_cleanup(std::function<void()> function) {
    const std::lock_guard<std::mutex> lock(output_mutex());
    cleanup() = std::move(function);
}

void await_broken_pipe_cleanup() {
    if (!handles_sigpipe.load()) return;
    // The failed write raised SIGPIPE in this thread before returning; the handler has woken the
    // cleanup thread, which takes the output lock, removes the outputs and ends the process.
    for (;;) pause();
}

}  // namespace sa::cli
