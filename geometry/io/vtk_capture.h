#pragma once
// Captures VTK's messages instead of letting VTK print them. VTK reports errors, warnings and
// debug text through one process-wide output window (vtkOutputWindow, which prints to the
// terminal) and, since 9.0, logs errors and warnings through vtkLogger to stderr as well. While a
// VtkCapture is alive, the output window is one that keeps the messages in the capture and
// vtkLogger's stderr output is off, so nothing is printed; the destructor puts back the previous
// output window and stderr verbosity.
//
//   std::string error;
//   {
//       VtkCapture capture;
//       reader->Update();
//       error = capture.error();   // "" when VTK reported no error
//   }
//
// Both are global to the process, so captures are serialized by a process-wide lock: a capture
// on another thread waits for this one to end. Captures may nest on one thread (the lock is
// recursive): the inner one gets the messages during its lifetime, then the outer one again.

#include <memory>
#include <string>

namespace sa {

class VtkCapture {
  public:
    VtkCapture();
    ~VtkCapture();
    VtkCapture(const VtkCapture&) = delete;
    VtkCapture& operator=(const VtkCapture&) = delete;

    /// The first error message so far, on one line: VTK's "ERROR: In FILE, line N" header and
    /// the "vtkClass (0x...): " prefix are dropped ("unknown VTK error" when nothing is left).
    /// "" when VTK has reported no error.
    const std::string& error() const;

    /// The first message of any type (error, warning, text, debug) so far, whole on one line:
    /// newlines become spaces, trailing spaces are dropped. "" when there was none.
    const std::string& first_message() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace sa
