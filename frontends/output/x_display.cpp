#include "frontends/output/x_display.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <thread>

#include "optim/errors.h"

// Last: Xlib defines macros (None, Status, Bool) that other headers may use as names.
#include <X11/Xlib.h>

namespace sa {

namespace {

/// The full path of an executable `name` on PATH, or "" when there is none.
std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    const std::string dirs = path ? path : "";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        std::size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
        const std::string candidate = dir + "/" + name;
        struct stat info;
        if (stat(candidate.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
            access(candidate.c_str(), X_OK) == 0) {
            return candidate;
        }
        start = end + 1;
    }
    return "";
}

}  // namespace

/// A private X server: `Xvfb` on a display number it picks, for the lifetime of the object.
class XDisplay::PrivateServer {
  public:
    PrivateServer(int width, int height, const std::string& who) {
        const std::string xvfb = find_on_path("Xvfb");
        if (xvfb.empty()) {
            throw InputError(
                who +
                ": no X display to render on: set DISPLAY, or install xvfb "
                "(scripts/setup.sh installs it) so that a private Xvfb can be started");
        }
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0) {
            throw InputError(who + ": cannot start Xvfb (no pipe)");
        }
        // Everything the child needs is prepared here: between fork and exec only
        // async-signal-safe calls.
        const std::string fd = std::to_string(fds[1]);
        const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
        const char* argv[] = {"Xvfb",         "-displayfd", fd.c_str(), "-screen", "0",
                              screen.c_str(), "-nolisten",  "tcp",      nullptr};
        const int null = open("/dev/null", O_RDWR | O_CLOEXEC);
        const pid_t parent = getpid();
        pid_ = fork();
        if (pid_ == 0) {
            // Die with the calling thread should this process be killed before cleaning up.
            prctl(PR_SET_PDEATHSIG, SIGTERM);
            if (getppid() != parent) _exit(127);
            if (null > 2) {
                dup2(null, 0);
                dup2(null, 1);
                dup2(null, 2);
            }
            fcntl(fds[1], F_SETFD, 0);  // the one descriptor Xvfb inherits
            sigset_t none;
            sigemptyset(&none);
            sigprocmask(SIG_SETMASK, &none, nullptr);
            execv(xvfb.c_str(), const_cast<char* const*>(argv));
            _exit(127);
        }
        if (null >= 0) close(null);
        close(fds[1]);
        if (pid_ < 0) {
            close(fds[0]);
            throw InputError(who + ": cannot start Xvfb (fork failed)");
        }
        // Xvfb writes its display number and a newline once it accepts connections.
        std::string number;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (number.empty() || number.back() != '\n') {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            if (left.count() <= 0) break;
            pollfd p{fds[0], POLLIN, 0};
            const int ready = poll(&p, 1, static_cast<int>(left.count()));
            if (ready < 0 && errno == EINTR) continue;
            if (ready <= 0) break;
            char buffer[32];
            const ssize_t got = read(fds[0], buffer, sizeof buffer);
            if (got < 0 && errno == EINTR) continue;
            if (got <= 0) break;  // Xvfb exited
            number.append(buffer, static_cast<std::size_t>(got));
        }
        close(fds[0]);
        if (number.size() < 2 || number.back() != '\n' ||
            number.find_first_not_of("0123456789\n") != std::string::npos) {
            stop();
            throw InputError(who + ": " + xvfb +
                             " did not start; set DISPLAY to an X server instead");
        }
        number.pop_back();
        display_.push_back(':');  // not ":" + number: GCC 12 warns falsely (-Wrestrict)
        display_.append(number);
    }

    ~PrivateServer() { stop(); }
    PrivateServer(const PrivateServer&) = delete;
    PrivateServer& operator=(const PrivateServer&) = delete;

    const std::string& display() const { return display_; }

  private:
    /// SIGTERM, up to 5 s to exit, then SIGKILL; always reaped.
    void stop() {
        if (pid_ <= 0) return;
        kill(pid_, SIGTERM);
        for (int i = 0; i < 500; ++i) {
            const pid_t done = waitpid(pid_, nullptr, WNOHANG);
            if (done == pid_ || (done < 0 && errno != EINTR)) {
                pid_ = -1;
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        kill(pid_, SIGKILL);
        while (waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
        }
        pid_ = -1;
    }

    pid_t pid_ = -1;
    std::string display_;
};

namespace {

/// A connection to an X server with GLX (`name` null: DISPLAY's), or null.
Display* open_display(const char* name) {
    Display* display = XOpenDisplay(name);
    int opcode = 0, event = 0, error = 0;
    if (display && !XQueryExtension(display, "GLX", &opcode, &event, &error)) {
        XCloseDisplay(display);
        display = nullptr;
    }
    return display;
}

}  // namespace

void XDisplay::Closer::operator()(Display* display) const {
    XCloseDisplay(display);
}

XDisplay::XDisplay(int width, int height, const std::string& who) {
    const char* name = std::getenv("DISPLAY");
    if (name && *name) display_.reset(open_display(nullptr));
    if (!display_) {
        server_ = std::make_unique<PrivateServer>(width, height, who);
        display_.reset(open_display(server_->display().c_str()));
        if (!display_) {
            throw InputError(who + ": cannot connect to the private Xvfb on " + server_->display() +
                             " (or it has no GLX)");
        }
    }
}

XDisplay::~XDisplay() = default;

}  // namespace sa
