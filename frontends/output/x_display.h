#pragma once
// An X display to render on with OpenGL, for the lifetime of the object. VTK on Debian renders
// through X11 (GLX) even off screen, so even a picture that never appears needs an X server.
//
// When DISPLAY names an X server that can be opened and has GLX, that server is used (render off
// screen there: no window appears). Otherwise (DISPLAY unset, empty or unusable) a private `Xvfb`
// found on PATH is started (`Xvfb -displayfd <fd> -screen 0 WxHx24 -nolisten tcp`, its output
// discarded) and used. The destructor closes the connection, then terminates the Xvfb (SIGTERM,
// SIGKILL after 5 s) and reaps it; so does the constructor when it throws. The Xvfb also gets
// SIGTERM should the thread that started it die first. DISPLAY itself is never changed.
//
//   XDisplay display(width, height, "write_checkerboard_png");
//   render_window->SetDisplayId(display.get());
//   ...
//   render_window->Finalize();  // before `display` is destroyed

#include <memory>
#include <string>

// Xlib's display type, declared as <X11/Xlib.h> declares it, so that this header does not bring
// in Xlib's macros (None, Status, Bool).
struct _XDisplay;
typedef struct _XDisplay Display;

namespace sa {

class XDisplay {
  public:
    /// Opens DISPLAY, or starts a private Xvfb with a `width` x `height` x 24 screen (the size
    /// of the pictures to render) and connects to it. Exception texts start with `who` + ": ".
    /// Throws InputError when DISPLAY is unusable and there is no Xvfb on PATH ("<who>: no X
    /// display to render on: set DISPLAY, or install xvfb (scripts/setup.sh installs it) so that
    /// a private Xvfb can be started"), when Xvfb does not start within 20 s, or when its display
    /// cannot be opened or has no GLX.
    XDisplay(int width, int height, const std::string& who);
    ~XDisplay();
    XDisplay(const XDisplay&) = delete;
    XDisplay& operator=(const XDisplay&) = delete;

    /// The open connection, with GLX; valid until the object is destroyed.
    Display* get() const { return display_.get(); }

  private:
    class PrivateServer;
    struct Closer {
        void operator()(Display* display) const;
    };

    // In this order, so that the connection closes before the server stops.
    std::unique_ptr<PrivateServer> server_;
    std::unique_ptr<Display, Closer> display_;
};

}  // namespace sa
