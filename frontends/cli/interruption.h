#pragma once
// What the `sa` command does when it is interrupted (SIGINT, SIGTERM, SIGHUP) or its output
// pipe closes (SIGPIPE): the outputs of the run are removed, then the process ends as killed by
// that signal (a shell reports 128 + the signal's number: 130 for Ctrl-C).
//
// The handler itself only writes the signal's number to a pipe (all a handler may safely do); a
// thread started by install_interruption_handling() reads it, takes the output lock (waiting for
// a write in progress to finish, so that no half-written file is left and none is renamed into
// place afterwards), runs the cleanup the running command registered (OutputPlan), and re-raises
// the signal with its default action. The output lock is never released then: no write starts
// after the cleanup.

#include <functional>
#include <mutex>

namespace sa::cli {

/// Installs the handlers and starts the thread; once per process, before any output is written.
void install_interruption_handling();

/// Held by whoever writes an output (a file, a frame of --record, the renames at the end). Once an
/// interruption has been seen, it never returns: the process ends while waiting.
std::unique_lock<std::mutex> output_lock();

/// The cleanup an interruption runs (under the output lock); an empty function clears it. Takes
/// the output lock itself: not to be called while holding it.
void set_interruption_cleanup(std::function<void()> cleanup);

/// To be called when a write to standard output failed with EPIPE (its reader has gone). When
/// SIGPIPE is handled here, that write raised it and the cleanup thread ends the process after
/// the cleanup: this waits for it and never returns. When the parent ignores SIGPIPE, it returns
/// at once and the caller reports the write error. Not to be called holding the output lock.
void await_broken_pipe_cleanup();

}  // namespace sa::cli
