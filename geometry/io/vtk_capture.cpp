#include "geometry/io/vtk_capture.h"

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <mutex>
#include <sstream>

namespace sa {
namespace {

// An output window that keeps the first error and the first message instead of printing them.
class CapturingOutputWindow : public vtkOutputWindow {
  public:
    static CapturingOutputWindow* New();
    // No vtkTypeMacro: it ends with its own ';', which clang-format and -Wpedantic disagree on,
    // and nothing here needs the class's VTK type name.
    void DisplayText(const char* text) override {
        if (GetCurrentMessageType() == MESSAGE_TYPE_ERROR && error.empty())
            error = clean(text != nullptr ? text : "");
        if (text != nullptr && !have_message) {
            have_message = true;
            first_message = one_line(text);
        }
    }

    std::string error;
    std::string first_message;
    bool have_message = false;

  private:
    // VTK's text is "ERROR: In FILE, line N\nvtkClass (0x...): message\n\n": keep the message.
    static std::string clean(const std::string& text) {
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) {
            if (line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
                line.rfind("Generic Warning: In ", 0) == 0)
                continue;
            while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
            if (line.empty()) continue;
            const std::size_t prefix = line.find("): ");
            if (line.rfind("vtk", 0) == 0 && prefix != std::string::npos)
                line = line.substr(prefix + 3);
            return printable(line);
        }
        return "unknown VTK error";
    }

    // The whole text with newlines as spaces, trailing spaces dropped.
    static std::string one_line(std::string text) {
        std::replace(text.begin(), text.end(), '\n', ' ');
        while (!text.empty() && text.back() == ' ') text.pop_back();
        return printable(text);
    }

    // VTK quotes what it read, raw bytes of a binary file included: those become '?', and the
    // text is cut at 160 characters.
    static std::string printable(std::string text) {
        for (char& c : text) {
            const auto u = static_cast<unsigned char>(c);
            if (u < 0x20 || u >= 0x7f) c = '?';
        }
        if (text.size() > 160) text = text.substr(0, 157) + "...";
        return text;
    }
};
vtkStandardNewMacro(CapturingOutputWindow);

// VTK's output window and vtkLogger's stderr verbosity are global: one thread's captures at a time.
std::recursive_mutex& capture_mutex() {
    static std::recursive_mutex mutex;
    return mutex;
}

}  // namespace

struct VtkCapture::State {
    // First, so that it is taken before anything is swapped and released after all is restored.
    std::lock_guard<std::recursive_mutex> lock{capture_mutex()};
    vtkSmartPointer<vtkOutputWindow> previous;
    vtkSmartPointer<CapturingOutputWindow> window;
    vtkLogger::Verbosity verbosity = vtkLogger::VERBOSITY_WARNING;
};

VtkCapture::VtkCapture() : state_(std::make_unique<State>()) {
    state_->previous = vtkOutputWindow::GetInstance();
    state_->window = vtkSmartPointer<CapturingOutputWindow>::New();
    vtkOutputWindow::SetInstance(state_->window);
    // vtkLogger has no getter for its stderr verbosity; without other log sinks, the cutoff is
    // that verbosity.
    state_->verbosity = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkCapture::~VtkCapture() {
    vtkOutputWindow::SetInstance(state_->previous);
    vtkLogger::SetStderrVerbosity(state_->verbosity);
}

const std::string& VtkCapture::error() const {
    return state_->window->error;
}

const std::string& VtkCapture::first_message() const {
    return state_->window->first_message;
}

}  // namespace sa
