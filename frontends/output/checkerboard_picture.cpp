#include "frontends/output/checkerboard_picture.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>
#include <vector>

#include "geometry/io/atomic_file.h"
#include "optim/errors.h"

// Last: Xlib defines macros (None, Status, Bool) that other headers may use as names.
#include <X11/Xlib.h>

namespace sa {

namespace {

const char* const kNoDisplay =
    "write_checkerboard_png: no X display to render on: set DISPLAY, or install xvfb "
    "(scripts/setup.sh installs it) so that a private Xvfb can be started";

// ---- Checking the input ----------------------------------------------------------------------

void check_colour(const char* field, const std::array<double, 3>& c) {
    for (double x : c) {
        if (!(x >= 0.0 && x <= 1.0)) {
            throw InvalidArgumentError("write_checkerboard_png: picture." + std::string(field) +
                                       " has a component " + std::to_string(x) + " outside [0, 1]");
        }
    }
}

void check_input(const Eigen::MatrixXd& positions, const Eigen::MatrixXi& faces,
                 const Eigen::MatrixXd& uv, const CheckerboardPicture& picture) {
    const std::string where = "write_checkerboard_png: ";
    if (positions.cols() != 3 && positions.cols() != 2) {
        throw InvalidArgumentError(where + "positions must be #V x 3, got " +
                                   std::to_string(positions.rows()) + " x " +
                                   std::to_string(positions.cols()));
    }
    if (uv.rows() != positions.rows() || uv.cols() != 2) {
        throw InvalidArgumentError(
            where + "uv must be #V x 2 = " + std::to_string(positions.rows()) + " x 2, got " +
            std::to_string(uv.rows()) + " x " + std::to_string(uv.cols()));
    }
    if (faces.cols() != 3 || faces.rows() == 0) {
        throw InvalidArgumentError(where + "faces must be #F x 3 with #F > 0, got " +
                                   std::to_string(faces.rows()) + " x " +
                                   std::to_string(faces.cols()));
    }
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        for (int k = 0; k < 3; ++k) {
            if (faces(f, k) < 0 || faces(f, k) >= positions.rows()) {
                throw InvalidArgumentError(where + "face " + std::to_string(f) +
                                           " has vertex index " + std::to_string(faces(f, k)) +
                                           ", outside [0, " + std::to_string(positions.rows()) +
                                           ")");
            }
        }
    }
    for (Eigen::Index v = 0; v < positions.rows(); ++v) {
        if (!positions.row(v).allFinite()) {
            throw InvalidArgumentError(where + "vertex " + std::to_string(v) +
                                       " has a non-finite position");
        }
        if (!uv.row(v).allFinite()) {
            throw InvalidArgumentError(where + "vertex " + std::to_string(v) +
                                       " has non-finite uv");
        }
    }
    auto check_size = [&](const char* field, int value) {
        if (value < 16 || value > 8192) {
            throw InvalidArgumentError(where + "picture." + field + " = " + std::to_string(value) +
                                       ", outside [16, 8192]");
        }
    };
    check_size("width", picture.width);
    check_size("height", picture.height);
    if (!std::isfinite(picture.azimuth) || !std::isfinite(picture.elevation)) {
        throw InvalidArgumentError(where + "picture.azimuth and picture.elevation must be finite");
    }
    check_colour("light_colour", picture.light_colour);
    check_colour("dark_colour", picture.dark_colour);
    check_colour("background", picture.background);
}

// ---- The scene ---------------------------------------------------------------------------------

/// Per-vertex normals, area-weighted over the faces around all vertices at the same position,
/// so that the copies of a seam vertex get one normal.
Eigen::MatrixXd welded_normals(const Eigen::MatrixXd& points, const Eigen::MatrixXi& faces) {
    const Eigen::Index n = points.rows();
    std::vector<Eigen::Index> order(n);
    std::iota(order.begin(), order.end(), Eigen::Index(0));
    auto less = [&](Eigen::Index a, Eigen::Index b) {
        for (int c = 0; c < 3; ++c) {
            if (points(a, c) != points(b, c)) return points(a, c) < points(b, c);
        }
        return false;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<Eigen::Index> group(n);
    Eigen::Index groups = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (i > 0 && less(order[i - 1], order[i])) ++groups;
        group[order[i]] = groups;
    }
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(groups + 1, 3);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const Eigen::Vector3d a = points.row(faces(f, 0)), b = points.row(faces(f, 1)),
                              c = points.row(faces(f, 2));
        const Eigen::RowVector3d area_normal = (b - a).cross(c - a).transpose();
        for (int k = 0; k < 3; ++k) sums.row(group[faces(f, k)]) += area_normal;
    }
    Eigen::MatrixXd normals(n, 3);
    for (Eigen::Index v = 0; v < n; ++v) {
        const Eigen::RowVector3d s = sums.row(group[v]);
        const double length = s.norm();
        normals.row(v) =
            length > 0.0 ? Eigen::RowVector3d(s / length) : Eigen::RowVector3d(0, 0, 1);
    }
    return normals;
}

vtkSmartPointer<vtkPolyData> make_surface(const Eigen::MatrixXd& points,
                                          const Eigen::MatrixXi& faces, const Eigen::MatrixXd& uv) {
    vtkNew<vtkPoints> vtk_points;
    vtk_points->SetDataTypeToDouble();
    vtk_points->SetNumberOfPoints(points.rows());
    for (Eigen::Index v = 0; v < points.rows(); ++v) {
        vtk_points->SetPoint(v, points(v, 0), points(v, 1), points(v, 2));
    }
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(faces.rows(), 3 * faces.rows());
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        const vtkIdType ids[3] = {faces(f, 0), faces(f, 1), faces(f, 2)};
        triangles->InsertNextCell(3, ids);
    }
    // The texture holds 2 x 2 squares, so texture coordinates are uv / 2. They are shifted by
    // an even number of squares first, keeping the pattern, so that large uv keep their
    // precision in single precision on the GPU.
    const Eigen::RowVector2d shift = 2.0 * (uv.colwise().minCoeff() / 2.0).array().floor();
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("uv");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(uv.rows());
    for (Eigen::Index v = 0; v < uv.rows(); ++v) {
        tcoords->SetTypedComponent(v, 0, static_cast<float>((uv(v, 0) - shift[0]) / 2.0));
        tcoords->SetTypedComponent(v, 1, static_cast<float>((uv(v, 1) - shift[1]) / 2.0));
    }
    const Eigen::MatrixXd normals = welded_normals(points, faces);
    vtkNew<vtkFloatArray> vtk_normals;
    vtk_normals->SetName("normals");
    vtk_normals->SetNumberOfComponents(3);
    vtk_normals->SetNumberOfTuples(normals.rows());
    for (Eigen::Index v = 0; v < normals.rows(); ++v) {
        for (int c = 0; c < 3; ++c) {
            vtk_normals->SetTypedComponent(v, c, static_cast<float>(normals(v, c)));
        }
    }
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->SetPoints(vtk_points);
    surface->SetPolys(triangles);
    surface->GetPointData()->SetTCoords(tcoords);
    surface->GetPointData()->SetNormals(vtk_normals);
    return surface;
}

/// One period of the checkerboard: 2 x 2 squares of kSquare pixels, light at the lower left.
vtkSmartPointer<vtkImageData> make_checkerboard(const CheckerboardPicture& picture) {
    constexpr int kSquare = 128, kHalfLine = 2;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(2 * kSquare, 2 * kSquare, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto byte = [](double x) { return static_cast<unsigned char>(std::lround(255.0 * x)); };
    for (int j = 0; j < 2 * kSquare; ++j) {
        for (int i = 0; i < 2 * kSquare; ++i) {
            const bool dark = (i / kSquare + j / kSquare) % 2 == 1;
            std::array<double, 3> c = dark ? picture.dark_colour : picture.light_colour;
            auto on_line = [](int x) {
                const int r = x % kSquare;
                return r < kHalfLine || r >= kSquare - kHalfLine;
            };
            if (picture.lines && (on_line(i) || on_line(j))) {
                for (int k = 0; k < 3; ++k) c[k] = 0.45 * picture.dark_colour[k];
            }
            auto* pixel = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
            for (int k = 0; k < 3; ++k) pixel[k] = byte(c[k]);
        }
    }
    return image;
}

/// Turns and zooms the camera so that the projected vertices fill the box [-1 + margin,
/// 1 - margin] x [-1 + margin, top] in normalized device coordinates, centred. A few rounds,
/// since panning a perspective view moves near and far points differently.
void fit_camera(vtkRenderer* renderer, const Eigen::MatrixXd& points, double aspect, double top) {
    constexpr double kMargin = 0.06;
    vtkCamera* camera = renderer->GetActiveCamera();
    const double bottom = -1.0 + kMargin, half_width = 1.0 - kMargin;
    const double half_height = 0.5 * (top - bottom), centre_y = 0.5 * (top + bottom);
    for (int round = 0; round < 4; ++round) {
        renderer->ResetCameraClippingRange();
        vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
        Eigen::Array2d lo(1e300, 1e300), hi(-1e300, -1e300);
        for (Eigen::Index v = 0; v < points.rows(); ++v) {
            const double p[4] = {points(v, 0), points(v, 1), points(v, 2), 1.0};
            double q[4];
            m->MultiplyPoint(p, q);
            if (q[3] <= 0.0) continue;  // behind the camera: cannot happen after ResetCamera
            const Eigen::Array2d ndc(q[0] / q[3], q[1] / q[3]);
            lo = lo.min(ndc);
            hi = hi.max(ndc);
        }
        if (!(hi[0] > lo[0]) || !(hi[1] > lo[1])) return;  // a point or a segment: leave as is
        const double zoom =
            std::min(2.0 * half_width / (hi[0] - lo[0]), 2.0 * half_height / (hi[1] - lo[1]));
        camera->Zoom(zoom);
        // After the zoom the projection has scaled by `zoom` about the centre; pan the rest.
        const double dx = 0.5 * (lo[0] + hi[0]) * zoom,
                     dy = 0.5 * (lo[1] + hi[1]) * zoom - centre_y;
        const double tan_half = std::tan(0.5 * camera->GetViewAngle() * M_PI / 180.0);
        const double reach = camera->GetDistance() * tan_half;
        double up[3], direction[3], right[3];
        camera->GetViewUp(up);
        camera->GetDirectionOfProjection(direction);
        right[0] = direction[1] * up[2] - direction[2] * up[1];
        right[1] = direction[2] * up[0] - direction[0] * up[2];
        right[2] = direction[0] * up[1] - direction[1] * up[0];
        double position[3], focal[3];
        camera->GetPosition(position);
        camera->GetFocalPoint(focal);
        for (int c = 0; c < 3; ++c) {
            const double move = dx * reach * aspect * right[c] + dy * reach * up[c];
            position[c] += move;
            focal[c] += move;
        }
        camera->SetPosition(position);
        camera->SetFocalPoint(focal);
    }
    renderer->ResetCameraClippingRange();
}

// ---- The display -------------------------------------------------------------------------------

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

/// A private X server: `Xvfb` on a display number it picks, for the lifetime of the object.
class PrivateXServer {
  public:
    PrivateXServer(int width, int height) {
        const std::string xvfb = find_on_path("Xvfb");
        if (xvfb.empty()) throw InputError(kNoDisplay);
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0) {
            throw InputError("write_checkerboard_png: cannot start Xvfb (no pipe)");
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
            throw InputError("write_checkerboard_png: cannot start Xvfb (fork failed)");
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
            throw InputError("write_checkerboard_png: " + xvfb +
                             " did not start; set DISPLAY to an X server instead");
        }
        number.pop_back();
        display_.push_back(':');  // not ":" + number: GCC 12 warns falsely (-Wrestrict)
        display_.append(number);
    }

    ~PrivateXServer() { stop(); }
    PrivateXServer(const PrivateXServer&) = delete;
    PrivateXServer& operator=(const PrivateXServer&) = delete;

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

struct DisplayCloser {
    void operator()(Display* display) const { XCloseDisplay(display); }
};
using DisplayConnection = std::unique_ptr<Display, DisplayCloser>;

/// A connection to an X server with GLX, or null.
DisplayConnection open_display(const char* name) {
    DisplayConnection display(XOpenDisplay(name));
    int opcode = 0, event = 0, error = 0;
    if (display && !XQueryExtension(display.get(), "GLX", &opcode, &event, &error)) {
        display.reset();
    }
    return display;
}

/// Collects VTK's messages instead of printing them.
class CatchingOutputWindow : public vtkOutputWindow {
  public:
    vtkTypeMacro(CatchingOutputWindow, vtkOutputWindow) static CatchingOutputWindow* New() {
        auto* window = new CatchingOutputWindow;
        window->InitializeObjectBase();
        return window;
    }
    void DisplayText(const char* text) override {
        if (text && messages.size() < 16) messages.emplace_back(text);
    }
    /// The first message on one line, or "".
    std::string first() const {
        if (messages.empty()) return "";
        std::string line = messages.front();
        std::replace(line.begin(), line.end(), '\n', ' ');
        while (!line.empty() && line.back() == ' ') line.pop_back();
        return line;
    }
    std::vector<std::string> messages;
};

/// Installs a CatchingOutputWindow as VTK's output window for its lifetime.
class CatchVtkMessages {
  public:
    CatchVtkMessages() : previous_(vtkOutputWindow::GetInstance()) {
        vtkOutputWindow::SetInstance(catcher_);
    }
    ~CatchVtkMessages() { vtkOutputWindow::SetInstance(previous_); }
    CatchVtkMessages(const CatchVtkMessages&) = delete;
    CatchVtkMessages& operator=(const CatchVtkMessages&) = delete;
    const CatchingOutputWindow& messages() const { return *catcher_; }

  private:
    vtkSmartPointer<vtkOutputWindow> previous_;
    vtkNew<CatchingOutputWindow> catcher_;
};

std::mutex& render_mutex() {
    static std::mutex mutex;
    return mutex;
}

/// Renders the scene on `display` and returns the picture.
vtkSmartPointer<vtkImageData> render(Display* display, const Eigen::MatrixXd& points,
                                     vtkPolyData* surface, const CheckerboardPicture& picture) {
    vtkNew<vtkTexture> texture;
    texture->SetInputData(make_checkerboard(picture));
    texture->RepeatOn();
    texture->InterpolateOn();
    texture->MipmapOn();
    texture->SetMaximumAnisotropicFiltering(8.0f);

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surface);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetTexture(texture);
    vtkProperty* property = actor->GetProperty();
    property->SetColor(1.0, 1.0, 1.0);
    property->SetInterpolationToGouraud();
    property->SetAmbient(0.2);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.0);

    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(picture.background.data());
    renderer->AddActor(actor);

    // The title: the fitted mesh stays below it.
    const int font_size = std::max(12, picture.height / 36);
    const int title_top = std::max(4, picture.height / 60);
    double top = 1.0 - 0.06;
    vtkNew<vtkTextActor> title;
    if (!picture.title.empty()) {
        title->SetInput(picture.title.c_str());
        vtkTextProperty* text = title->GetTextProperty();
        text->SetFontFamilyToArial();
        text->SetFontSize(font_size);
        text->SetColor(0.1, 0.1, 0.1);
        text->SetJustificationToCentered();
        text->SetVerticalJustificationToTop();
        title->SetDisplayPosition(picture.width / 2, picture.height - title_top);
        renderer->AddActor2D(title);
        top = 1.0 - 2.0 * (title_top + 1.8 * font_size) / picture.height;
    }

    renderer->ResetCamera();
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->Azimuth(picture.azimuth);
    camera->Elevation(picture.elevation);
    camera->OrthogonalizeViewUp();
    renderer->ResetCamera();
    fit_camera(renderer, points, double(picture.width) / picture.height, top);

    vtkNew<vtkRenderWindow> window;
    window->SetDisplayId(display);
    window->SetOffScreenRendering(1);
    window->SetSize(picture.width, picture.height);
    window->SetMultiSamples(8);
    window->AddRenderer(renderer);
    window->Render();

    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(grab->GetOutput());
    grab->SetInput(nullptr);
    window->Finalize();  // before the display connection closes
    return image;
}

}  // namespace

void write_checkerboard_png(const std::string& path, const Eigen::MatrixXd& positions,
                            const Eigen::MatrixXi& faces, const Eigen::MatrixXd& uv,
                            const CheckerboardPicture& picture) {
    check_input(positions, faces, uv, picture);
    Eigen::MatrixXd points = Eigen::MatrixXd::Zero(positions.rows(), 3);
    points.leftCols(positions.cols()) = positions;
    const vtkSmartPointer<vtkPolyData> surface = make_surface(points, faces, uv);

    std::lock_guard<std::mutex> lock(render_mutex());
    CatchVtkMessages caught;
    vtkSmartPointer<vtkImageData> image;
    {
        // Declared in this order so that the connection closes before the server stops.
        std::optional<PrivateXServer> server;
        const char* name = std::getenv("DISPLAY");
        DisplayConnection display = name && *name ? open_display(nullptr) : nullptr;
        if (!display) {
            server.emplace(picture.width, picture.height);
            display = open_display(server->display().c_str());
            if (!display) {
                throw InputError("write_checkerboard_png: cannot connect to the private Xvfb on " +
                                 server->display() + " (or it has no GLX)");
            }
        }
        image = render(display.get(), points, surface, picture);
    }
    int dims[3];
    image->GetDimensions(dims);
    if (dims[0] != picture.width || dims[1] != picture.height) {
        const std::string why = caught.messages().first();
        throw InputError("write_checkerboard_png: rendering gave a " + std::to_string(dims[0]) +
                         " x " + std::to_string(dims[1]) + " picture instead of " +
                         std::to_string(picture.width) + " x " + std::to_string(picture.height) +
                         (why.empty() ? "" : " (" + why + ")"));
    }

    AtomicFile file(path, true);
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(file.temporary_path().c_str());
    writer->SetInputData(image);
    writer->Write();
    if (writer->GetErrorCode() != 0) {
        const std::string why = caught.messages().first();
        throw InputError(path + ": cannot write the picture" +
                         (why.empty() ? "" : " (" + why + ")"));
    }
    file.commit();
}

}  // namespace sa
