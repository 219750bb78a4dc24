// The bad-input catalogue (issue 25): one generated case per kind of bad input, for every reader
// and every command of the `sa` executable, run as a user would. Each case writes its inputs into
// a fresh folder, runs one command and checks
//   - the exit status (README.md, "Exit status");
//   - for an error, that stderr is one line `sa: error: ...` naming the file and line, or the
//     option, that it is about;
//   - that the folder holds exactly its inputs afterwards, unchanged: no output and no temporary
//     (the hidden names outputs are written under) is left behind;
//   - for the few kinds of input that must now succeed (a byte-order mark, a mesh at 1e200, a
//     handle far away), the outputs and a verified result.
// Interruptions, which need a process to signal, come after. Memory limits and what the command
// does to its own process are tested on the Release command (command_process_test.cpp).
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <thread>
#include <tuple>

#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_generators.h"
#include "geometry/mesh/mesh_topology.h"
#include "geometry/quality/map_quality.h"
#include "tests/fixtures/grid_problem_text.h"

extern char** environ;

namespace sa {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Every file under `folder`: relative path -> content (its size and a hash when large, so that
/// a failure prints a short difference).
std::map<std::string, std::string> snapshot(const fs::path& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        const std::string name = fs::relative(entry.path(), folder).string();
        if (!entry.is_regular_file()) {
            files[name] = "<folder>";
            continue;
        }
        const std::string content = read_file(entry.path());
        files[name] = content.size() < 4096
                          ? content
                          : "<" + std::to_string(content.size()) + " bytes, hash " +
                                std::to_string(std::hash<std::string>{}(content)) + ">";
    }
    return files;
}

// ---------------------------------------------------------------------------------------------
// Generated inputs.

/// A bumpy square in space: a disk surface for `sa param`, scaled by `scale`.
SimplicialMesh bump(double scale = 1.0) {
    SimplicialMesh mesh = grid_triangles(8, 8);
    Eigen::MatrixXd lifted(mesh.num_vertices(), 3);
    for (Index v = 0; v < mesh.num_vertices(); ++v) {
        const double x = mesh.vertices(v, 0), y = mesh.vertices(v, 1);
        lifted.row(v) << scale * x, scale * y, scale * 0.2 * std::sin(4.0 * x) * y;
    }
    mesh.vertices = lifted;
    return mesh;
}

const std::string kGzip("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03\xcb\x48\xcd\xc9\xc9\x07\x00", 17);
const std::string kBom = "\xEF\xBB\xBF";

/// What a case writes into its folder before the command runs.
class Inputs {
  public:
    explicit Inputs(fs::path folder) : folder_(std::move(folder)) {}
    void text(const std::string& name, const std::string& content) const {
        std::ofstream(folder_ / name, std::ios::binary) << content;
    }
    void mesh(const std::string& name, const SimplicialMesh& m) const {
        write_mesh_file((folder_ / name).string(), m.vertices, m.simplices);
    }
    void folder(const std::string& name) const { fs::create_directories(folder_ / name); }
    std::string read(const std::string& name) const { return read_file(folder_ / name); }

  private:
    fs::path folder_;
};

// A few inputs many cases share.
void problem(const Inputs& in) {
    in.text("p.txt", grid_problem(4, grid_boundary(4), {{5, {0.4, 0.5}}}));
}
void bump_off(const Inputs& in) {
    in.mesh("bump.off", bump());
}
void sphere_off(const Inputs& in) {
    in.mesh("sphere.off", sphere_triangles(3));
}
void tets_mesh(const Inputs& in) {
    in.mesh("t.mesh", grid_tetrahedra(2, 2, 2));
}

struct Case {
    std::string name;
    std::function<void(const Inputs&)> inputs;
    std::string command;  ///< `{D}` is replaced by the case's folder
    int status;
    std::vector<std::string> parts;         ///< in stderr's one line (errors) or stdout (successes)
    std::vector<std::string> outputs = {};  ///< files a success writes
    bool full_stdout = false;               ///< stdout goes to /dev/full
};

std::string expand(std::string text, const std::string& folder) {
    for (std::size_t at; (at = text.find("{D}")) != std::string::npos;) text.replace(at, 3, folder);
    return text;
}

// ---------------------------------------------------------------------------------------------
// The catalogue.

std::vector<Case> catalogue() {
    const auto none = [](const Inputs&) {};
    std::vector<Case> cases = {
        // The command line: one line, exit 2, before anything runs.
        {"UnknownCommand", none, "frobnicate", 2, {"unknown command 'frobnicate' (expected map"}},
        {"UnknownCommandWithHelp", none, "unmake --help", 2, {"unknown command 'unmake'"}},
        {"NoCommand", none, "", 2, {"a command is required: map, demo"}},
        {"MissingRequiredOption", problem, "map --rest {D}/p.txt", 2, {"--out is required"}},
        {"UnknownOption", problem, "map --rest {D}/p.txt --out {D}/o.vtu --frob 1", 2, {"--frob"}},
        {"NotANumber",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --max-iterations abc",
         2,
         {"--max-iterations", "'abc'"}},
        {"NegativeSeed",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --seed -1",
         2,
         {"--seed: must be an integer from 0 to 18446744073709551615, found '-1'"}},
        {"SeedAboveTwoToTheSixtyFour",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --seed 18446744073709551616",
         2,
         {"--seed: must be an integer from 0 to 18446744073709551615, found "
          "'18446744073709551616'"}},
        {"TranslationShiftInfiniteTimesLambda",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --translation-shift 1e308",
         2,
         {"--translation-shift 1e+308: times --lambda-max (1e+16) it is not a finite number"}},
        {"ZeroMaxTime",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --max-time 0",
         2,
         {"--max-time: must be a number or inf > 0"}},
        {"NanMu", problem, "map --rest {D}/p.txt --out {D}/o.vtu --mu nan", 2, {"--mu", "'nan'"}},
        {"ZeroS", problem, "map --rest {D}/p.txt --out {D}/o.vtu --s 0", 2, {"--s: must be"}},
        {"LowLambdaMax",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --lambda-max 1",
         2,
         {"--lambda-max: must be a finite number >= 1000"}},
        {"NegativeTranslationShift",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --translation-shift -1",
         2,
         {"--translation-shift"}},
        {"MaxRingsBelowRings",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --rings 5 --max-rings 3",
         2,
         {"--max-rings 3: must be >= --rings (5)"}},
        {"BoundBelowOne",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --bound 0.9",
         2,
         {"--bound 0.9: expected a number > 1"}},
        {"UnknownDistortion",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --distortion frob",
         2,
         {"--distortion frob: expected conformal, volumetric or isometric"}},
        {"EnergyAsBarrierDistortion",  // a mapping energy, not a distortion a barrier bounds
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --distortion dirichlet",
         2,
         {"--distortion dirichlet: expected conformal, volumetric or isometric"}},
        {"ParamVolumetricDistortion",
         bump_off,
         "param --mesh {D}/bump.off --out {D}/uv.obj --distortion volumetric",
         2,
         {"--distortion volumetric: expected conformal or isometric"}},
        {"UnknownEnergy",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --energy frob",
         2,
         {"--energy frob: unknown distortion 'frob'"}},
        {"UnknownMode",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --mode frob",
         2,
         {"--mode frob: unknown mode 'frob'"}},
        {"NegativeParamRounds",
         bump_off,
         "param --mesh {D}/bump.off --out {D}/uv.obj --optimal-bound --optimal-bound-rounds -1",
         2,
         {"--optimal-bound-rounds: must be an integer >= 1"}},
        {"ParamRoundsWithoutOptimalBound",
         bump_off,
         "param --mesh {D}/bump.off --out {D}/uv.obj --optimal-bound-rounds 3",
         2,
         {"--optimal-bound-rounds requires --optimal-bound"}},
        {"NegativeParamThreads",
         bump_off,
         "param --mesh {D}/bump.off --out {D}/uv.obj --threads -1",
         2,
         {"--threads: must be an integer >= 0"}},
        {"SeamlessZeroScale",
         sphere_off,
         "seamless --mesh {D}/sphere.off --out {D}/s.obj --scale 0",
         2,
         {"--scale: must be a finite number > 0, found '0'"}},
        {"SeamlessZeroIterations",
         sphere_off,
         "seamless --mesh {D}/sphere.off --out {D}/s.obj --max-iterations 0",
         2,
         {"--max-iterations: must be an integer >= 1"}},
        {"SubdivideTooManyLevels",
         bump_off,
         "subdivide --mesh {D}/bump.off --out {D}/s.obj --levels 9",
         2,
         {"--levels"}},
        {"DemoNegativeThreads", none, "demo --out-dir {D}/demo --threads -1", 2, {"--threads"}},

        // Output locations: checked before anything is read or solved.
        {"OutAndReportTheSame",
         problem,
         "map --rest {D}/p.txt --out {D}/same.json --report {D}/same.json",
         2,
         {"--out and --report name the same file"}},
        {"ParamOutAndLayoutTheSame",
         bump_off,
         "param --mesh {D}/bump.off --out {D}/uv.vtu --layout {D}/./uv.vtu",
         2,
         {"--out and --layout name the same file"}},
        {"SeamlessVtuAndReportTheSame",
         sphere_off,
         "seamless --mesh {D}/sphere.off --out {D}/s.obj --vtu {D}/r.vtu --report {D}/r.vtu",
         2,
         {"--vtu and --report name the same file"}},
        {"OutInMissingFolder",
         problem,
         "map --rest {D}/p.txt --out {D}/missing/o.vtu",
         2,
         {"--out {D}/missing/o.vtu: folder '{D}/missing' does not exist"}},
        {"ReportUnderARegularFile",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --report {D}/p.txt/r.json",
         2,
         {"--report {D}/p.txt/r.json: '{D}/p.txt' is not a folder"}},
        {"OutIsADirectory",
         [](const Inputs& in) {
             problem(in);
             in.folder("o.vtu");
         },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"--out {D}/o.vtu: is a directory"}},
        {"OutIsTheInput",
         problem,
         "map --rest {D}/p.txt --out {D}/p.txt --force",
         2,
         {"--out {D}/p.txt is the input of --rest"}},
        {"OutExistsWithoutForce",
         [](const Inputs& in) {
             problem(in);
             in.text("o.vtu", "precious");
         },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/o.vtu exists; pass --force"}},
        {"RecordIsAFile",
         [](const Inputs& in) {
             problem(in);
             in.text("rec", "not a folder");
         },
         "map --rest {D}/p.txt --out {D}/o.vtu --record {D}/rec",
         2,
         {"--record {D}/rec: exists and is not a folder"}},
        {"RecordIsTheInput",
         problem,
         "map --rest {D}/p.txt --out {D}/o.vtu --record {D}/p.txt",
         2,
         {"--record {D}/p.txt is the input of --rest"}},
        {"TrianglesAsNode",
         problem,
         "map --rest {D}/p.txt --out {D}/o.node",
         2,
         {"o.node: .node holds tetrahedra"}},
        {"OutAsPly", problem, "map --rest {D}/p.txt --out {D}/o.ply", 2, {"is read, not written"}},
        {"ParamOutFormat",
         bump_off,
         "param --mesh {D}/bump.off --out {D}/uv.off",
         2,
         {"uv.off: the parameterized surface is written as .obj, .vtu or .vtk"}},
        {"SeamlessOutFormat",
         sphere_off,
         "seamless --mesh {D}/sphere.off --out {D}/s.vtu",
         2,
         {"s.vtu: the seamless map is written as .obj"}},
        {"DemoOutDirIsAFile",
         [](const Inputs& in) { in.text("demo", "x"); },
         "demo --out-dir {D}/demo",
         2,
         {"--out-dir {D}/demo: exists and is not a folder"}},
        {"SubdivideOutMissingFolder",
         bump_off,
         "subdivide --mesh {D}/bump.off --out {D}/no/s.obj",
         2,
         {"--out {D}/no/s.obj: folder '{D}/no' does not exist"}},

        // Input files that are not files.
        {"MissingRest",
         none,
         "map --rest {D}/absent.txt --out {D}/o.vtu",
         2,
         {"{D}/absent.txt: cannot open (No such file or directory)"}},
        {"InitIsAFolder",
         [](const Inputs& in) {
             problem(in);
             in.folder("init");
         },
         "map --rest {D}/p.txt --init {D}/init --out {D}/o.vtu",
         2,
         {"{D}/init: cannot open (Is a directory)"}},
        {"TargetsIsAFolder",
         [](const Inputs& in) {
             problem(in);
             in.folder("targets");
         },
         "map --rest {D}/p.txt --targets {D}/targets --out {D}/o.vtu",
         2,
         {"{D}/targets: cannot open (Is a directory)"}},
        {"ParamInitIsAFolder",
         [](const Inputs& in) {
             bump_off(in);
             in.folder("init");
         },
         "param --mesh {D}/bump.off --init {D}/init --out {D}/uv.obj",
         2,
         {"{D}/init: cannot open (Is a directory)"}},
        {"HandlesIsAFolder",
         [](const Inputs& in) {
             problem(in);
             in.folder("h");
         },
         "map --rest {D}/p.txt --handles {D}/h --out {D}/o.vtu",
         2,
         {"{D}/h: cannot open (Is a directory)"}},
        {"FieldIsAFolder",
         [](const Inputs& in) {
             sphere_off(in);
             in.folder("f.dmat");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.dmat --out {D}/s.obj",
         2,
         {"{D}/f.dmat: cannot open (Is a directory)"}},

        // The plain-text problem.
        {"ProblemBadNumber",
         [](const Inputs& in) { in.text("p.txt", "3 2\n0 0\n1 x\n0 1\n"); },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt:3:", "'x'"}},
        {"ProblemShortRow",
         [](const Inputs& in) { in.text("p.txt", "3 2\n0 0\n1\n0 1\n"); },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt:3: expected 2 coordinates"}},
        {"ProblemIndexOutOfRange",
         [](const Inputs& in) {
             in.text("p.txt", "3 2\n0 0\n1 0\n0 1\n3 2\n0 0\n1 0\n0 1\n1 3\n0 1 3\n");
         },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt:10: vertex 3 out of range"}},
        {"ProblemRepeatedHandle",
         [](const Inputs& in) {
             in.text("p.txt", "3 2\n0 0\n1 0\n0 1\n3 2\n0 0\n1 0\n0 1\n1 3\n0 1 2\n2\n1\n1\n");
         },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt:13: handle 1 repeated (first on line 12)"}},
        {"ProblemEndsEarly",
         [](const Inputs& in) { in.text("p.txt", "3 2\n0 0\n1 0\n"); },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt: file ends after 2 of 3"}},
        {"ProblemHugeCount",
         [](const Inputs& in) { in.text("p.txt", "2000000000 2\n0 0\n"); },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt: file ends after 1 of 2000000000"}},
        {"ProblemPlanarRestSpatialInit",
         [](const Inputs& in) {
             in.text("p.txt", grid_problem(3, {0, 8}, {}, 1.0, 3));
         },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt:13: initial position of vertex 1 has z = 0.5",
          "the rest shape is 2D (header on line 11)"}},
        {"ProblemGzip",
         [](const Inputs& in) { in.text("p.txt", kGzip); },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt:1: not a text file (byte 0x1f"}},
        {"ProblemDegenerateRest",
         [](const Inputs& in) {
             in.text("p.txt", "3 2\n0 0\n1 0\n2 0\n3 2\n0 0\n1 0\n2 0\n1 3\n0 1 2\n");
         },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt: simplex 0 is degenerate in the rest shape"}},
        {"InitialCoordinateOverflows",
         [](const Inputs& in) {
             in.text("p.txt", grid_problem(4, grid_boundary(4), {{5, {1e308, 0.3}}}));
         },
         "map --rest {D}/p.txt --out {D}/o.vtu",
         2,
         {"{D}/p.txt: the initial map's affine part of simplex", "not finite"}},

        // Result records given as --init.
        {"ResultWithoutResV",
         [](const Inputs& in) {
             problem(in);
             in.text("r.res", "resX 2\n1 2\n# no resV record\n");
         },
         "map --rest {D}/p.txt --init {D}/r.res --out {D}/o.vtu",
         2,
         {"{D}/r.res: no 'resV n d' record"}},
        {"ResultWrongValueCount",
         [](const Inputs& in) {
             problem(in);
             in.text("r.res", "resV 16 2\n1 2 3\n");
         },
         "map --rest {D}/p.txt --init {D}/r.res --out {D}/o.vtu",
         2,
         {"{D}/r.res:2: expected 32 values"}},
        {"ResultWrongRowCount",
         [](const Inputs& in) {
             problem(in);
             in.text("r.res", "resV 2 2\n1 2 3 4\n");
         },
         "map --rest {D}/p.txt --init {D}/r.res --out {D}/o.vtu",
         2,
         {"{D}/r.res: 2 positions, the mesh has 16 vertices"}},

        // Handle lists.
        {"HandleCountCommentDisagrees",
         [](const Inputs& in) {
             problem(in);
             in.text("h.txt", "4 # handles\n0\n1\n");
         },
         "map --rest {D}/p.txt --handles {D}/h.txt --out {D}/o.vtu",
         2,
         {"{D}/h.txt:1: count header says 4 but 2 indices follow"}},
        {"HandleCountAmbiguous",
         [](const Inputs& in) {
             problem(in);
             in.text("h.txt", "3\n0 1\n2 3\n");
         },
         "map --rest {D}/p.txt --handles {D}/h.txt --out {D}/o.vtu",
         2,
         {"{D}/h.txt:1: the first line holds one number, 3, apart from the 4 indices"}},
        {"HandleOutOfRange",
         [](const Inputs& in) {
             problem(in);
             in.text("h.txt", "0 99\n");
         },
         "map --rest {D}/p.txt --handles {D}/h.txt --out {D}/o.vtu",
         2,
         {"{D}/h.txt:1: handle vertex 99 outside [0, 16)"}},
        {"HandleNegative",
         [](const Inputs& in) {
             problem(in);
             in.text("h.txt", "0\n-2\n");
         },
         "map --rest {D}/p.txt --handles {D}/h.txt --out {D}/o.vtu",
         2,
         {"{D}/h.txt:2: index -2 is negative"}},
        {"HandleGzip",
         [](const Inputs& in) {
             problem(in);
             in.text("h.txt", kGzip);
         },
         "map --rest {D}/p.txt --handles {D}/h.txt --out {D}/o.vtu",
         2,
         {"{D}/h.txt:1: not a text file"}},
        {"GarbageMeshWithHandles",
         [](const Inputs& in) {
             in.text("g.obj", "this is no mesh\n");
             in.text("h.txt", "0 1 2\n");
         },
         "map --rest {D}/g.obj --handles {D}/h.txt --out {D}/o.vtu",
         2,
         {"{D}/g.obj: the mesh has no vertices"}},

        // OBJ, OFF, Medit, TetGen, VTK, PLY, STL.
        {"ObjQuad",
         [](const Inputs& in) {
             in.text("q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
         },
         "param --mesh {D}/q.obj --out {D}/uv.obj",
         2,
         {"{D}/q.obj:5: face with 4 vertices; only triangles"}},
        {"ObjIndexZero",
         [](const Inputs& in) { in.text("z.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"); },
         "param --mesh {D}/z.obj --out {D}/uv.obj",
         2,
         {"{D}/z.obj:4: vertex index 0"}},
        {"ObjGzip",
         [](const Inputs& in) { in.text("g.obj", kGzip); },
         "param --mesh {D}/g.obj --out {D}/uv.obj",
         2,
         {"{D}/g.obj:1: not a text file"}},
        {"OffBadHeader",
         [](const Inputs& in) { in.text("b.off", "PLY\n3 1 0\n"); },
         "param --mesh {D}/b.off --out {D}/uv.obj",
         2,
         {"{D}/b.off:1: expected the header 'OFF'"}},
        {"OffFaceOutOfRange",
         [](const Inputs& in) { in.text("b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"); },
         "param --mesh {D}/b.off --out {D}/uv.obj",
         2,
         {"{D}/b.off:6: vertex 7 out of range"}},
        {"OffHugeCount",
         [](const Inputs& in) { in.text("b.off", "OFF\n2000000000 1 0\n0 0 0\n"); },
         "param --mesh {D}/b.off --out {D}/uv.obj",
         2,
         {"{D}/b.off: file ends after 1 of 2000000000 vertices"}},
        {"MeditUnknownKeyword",
         [](const Inputs& in) { in.text("m.mesh", "MeshVersionFormatted 2\nDimension 3\nFrob\n"); },
         "param --mesh {D}/m.mesh --out {D}/uv.obj",
         2,
         {"{D}/m.mesh:3: unknown keyword 'Frob'"}},
        {"MeditVertexOutOfRange",
         [](const Inputs& in) {
             in.text("m.mesh",
                     "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\n0 1 0 "
                     "0\nTriangles\n1\n1 2 4 0\nEnd\n");
         },
         "param --mesh {D}/m.mesh --out {D}/uv.obj",
         2,
         {"{D}/m.mesh:10: vertex 4 out of range"}},
        {"MeditBoundaryTriangleOutOfRange",  // beside valid tets, in the section not kept
         [](const Inputs& in) {
             in.text("m.mesh",
                     "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 "
                     "0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nTriangles\n1\n1 2 999 0\nEnd\n");
         },
         "deform --rest {D}/m.mesh --targets {D}/m.mesh --out {D}/o.vtu",
         2,
         {"{D}/m.mesh:14: vertex 999 out of range [1, 4]"}},
        {"TetgenRowOutOfSequence",
         [](const Inputs& in) {
             in.text("t.node", "2 3 0 0\n0 0 0 0\n5 1 0 0\n");
             in.text("t.ele", "0 4 0\n");
         },
         "map --rest {D}/t.node --targets {D}/t.node --out {D}/o.vtu",
         2,
         {"{D}/t.node:3: row index 5 out of sequence"}},
        {"TetgenEleMissing",
         [](const Inputs& in) { in.text("t.node", "1 3 0 0\n0 0 0 0\n"); },
         "map --rest {D}/t.node --targets {D}/t.node --out {D}/o.vtu",
         2,
         {"{D}/t.ele: cannot open (No such file or directory)"}},
        {"VtkNotVtk",
         [](const Inputs& in) { in.text("v.vtk", "hello\n"); },
         "param --mesh {D}/v.vtk --out {D}/uv.obj",
         2,
         {"{D}/v.vtk:1: expected '# vtk DataFile Version x.y', found 'hello'"}},
        {"VtkGzip",
         [](const Inputs& in) { in.text("v.vtk", kGzip); },
         "param --mesh {D}/v.vtk --out {D}/uv.obj",
         2,
         {"{D}/v.vtk: not a text file (byte 0x1f"}},
        {"VtkQuads",
         [](const Inputs& in) {
             in.text("v.vtk",
                     "# vtk DataFile Version 3.0\nq\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 "
                     "double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n9\n");
         },
         "param --mesh {D}/v.vtk --out {D}/uv.obj",
         2,
         {"{D}/v.vtk: cell 0 has type 9 (vtkQuad)"}},
        {"VtuGzip",
         [](const Inputs& in) { in.text("v.vtu", kGzip); },
         "param --mesh {D}/v.vtu --out {D}/uv.obj",
         2,
         {"{D}/v.vtu: not a text file (byte 0x1f"}},
        {"VtuNotXml",
         [](const Inputs& in) { in.text("v.vtu", "hello\n"); },
         "param --mesh {D}/v.vtu --out {D}/uv.obj",
         2,
         {"{D}/v.vtu: not a VTU (XML) file: it does not start with '<'"}},
        {"PlyNotPly",
         [](const Inputs& in) { in.text("p.ply", "hello\n"); },
         "param --mesh {D}/p.ply --out {D}/uv.obj",
         2,
         {"{D}/p.ply:1: not a PLY file: expected 'ply', found 'hello'"}},
        {"PlyQuad",
         [](const Inputs& in) {
             in.text("p.ply",
                     "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float "
                     "y\nproperty float z\nelement face 1\nproperty list uchar int "
                     "vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
         },
         "param --mesh {D}/p.ply --out {D}/uv.obj",
         2,
         {"{D}/p.ply:14: face 0 with 4 vertices; only triangles"}},
        {"PlyMoreFacesThanDeclared",  // the second face is no hole in a one-face mesh
         [](const Inputs& in) {
             in.text("p.ply",
                     "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float "
                     "y\nproperty float z\nelement face 1\nproperty list uchar int "
                     "vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n"
                     "3 0 2 3\n");
         },
         "param --mesh {D}/p.ply --out {D}/uv.obj",
         2,
         {"{D}/p.ply:15: unexpected data after the PLY body (element 'face' declares 1 row): "
          "'3'"}},
        {"PlyPropertyBeforeElement",
         [](const Inputs& in) {
             in.text("p.ply",
                     "ply\nformat ascii 1.0\nelemXnt vertex 3\nproperty float x\nend_header\n");
         },
         "param --mesh {D}/p.ply --out {D}/uv.obj",
         2,
         {"{D}/p.ply:3: not a PLY header line: 'elemXnt'"}},
        {"PlyNoEndHeader",
         [](const Inputs& in) { in.text("p.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"); },
         "param --mesh {D}/p.ply --out {D}/uv.obj",
         2,
         {"{D}/p.ply: the PLY header has no 'end_header' line"}},
        {"StlNotStl",
         [](const Inputs& in) { in.text("s.stl", "hello\n"); },
         "param --mesh {D}/s.stl --out {D}/uv.obj",
         2,
         {"{D}/s.stl: not an STL file"}},
        {"StlGzip",
         [](const Inputs& in) { in.text("s.stl", kGzip); },
         "param --mesh {D}/s.stl --out {D}/uv.obj",
         2,
         {"{D}/s.stl: not an STL file", "found binary data"}},

        // Frame fields.
        {"DmatShort",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.dmat", "3 2\n1\n0\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.dmat --out {D}/s.obj",
         2,
         {"{D}/f.dmat: file ends after 2 of 6 values"}},
        {"DmatGzip",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.dmat", kGzip);
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.dmat --out {D}/s.obj",
         2,
         {"{D}/f.dmat:1: not a text file"}},
        {"CrossfieldWrongFaceCount",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.crossfield", "2 5\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.crossfield --out {D}/s.obj",
         2,
         {"{D}/f.crossfield:1: header gives 5 faces; expected 72"}},
        {"FieldAndConstraints",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.dmat", "1 1\n0\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.dmat --constraints {D}/f.dmat {D}/f.dmat "
         "--out {D}/s.obj",
         2,
         {"give --field or --constraints, not both"}},
        {"RawfieldNotAFrameField",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.rawfield", "2 72\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.rawfield --out {D}/s.obj",
         2,
         {"{D}/f.rawfield:1: N = 2 vectors per face"}},
        {"RawfieldWrongFaceCount",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.rawfield", "4 5\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.rawfield --out {D}/s.obj",
         2,
         {"{D}/f.rawfield:1: header gives 5 faces; expected 72"}},
        {"RawfieldShortRow",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.rawfield", "4 72\n1 0 0 0 1 0\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.rawfield --out {D}/s.obj",
         2,
         {"{D}/f.rawfield:2: face 0: expected 12 numbers", "found 6"}},
        {"RawfieldNotSymmetric",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.rawfield", "4 72\n1 0 0 0 1 0 1 0 0 0 -1 0\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.rawfield --out {D}/s.obj",
         2,
         {"{D}/f.rawfield:2: face 0: the third and fourth vectors are not -u and -v"}},
        {"RawfieldEndsEarly",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.rawfield", "4 72\n1 0 0 0 1 0 -1 0 0 0 -1 0\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.rawfield --out {D}/s.obj",
         2,
         {"{D}/f.rawfield: file ends after 1 of 72 faces"}},
        {"RawfieldNotANumber",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.rawfield", "4 72\n1 0 0 0 1 0 -1 0 0 0 -1 zero\n");
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.rawfield --out {D}/s.obj",
         2,
         {"{D}/f.rawfield:2:", "zero"}},
        {"RawfieldGzip",
         [](const Inputs& in) {
             sphere_off(in);
             in.text("f.rawfield", kGzip);
         },
         "seamless --mesh {D}/sphere.off --field {D}/f.rawfield --out {D}/s.obj",
         2,
         {"{D}/f.rawfield:1: not a text file"}},

        // Meshes the commands cannot take, named by their file.
        {"ParamNotADisk",
         [](const Inputs& in) { in.mesh("s.off", sphere_triangles(2)); },
         "param --mesh {D}/s.off --out {D}/uv.obj",
         2,
         {"{D}/s.off: the mesh is closed"}},
        {"ParamTetrahedra",
         tets_mesh,
         "param --mesh {D}/t.mesh --out {D}/uv.obj",
         2,
         {"{D}/t.mesh: a parameterization needs a triangle mesh"}},
        {"SeamlessNonManifold",
         [](const Inputs& in) {
             in.text("n.obj",
                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf "
                     "1 2 5\n");
         },
         "seamless --mesh {D}/n.obj --out {D}/s.obj",
         2,
         {"{D}/n.obj: the mesh is not manifold"}},
        {"SeamlessFlipped",
         [](const Inputs& in) {
             SimplicialMesh s = sphere_triangles(2);
             std::swap(s.simplices(0, 1), s.simplices(0, 2));
             in.mesh("f.off", s);
         },
         "seamless --mesh {D}/f.off --out {D}/s.obj",
         2,
         {"{D}/f.off: triangles", "oriented inconsistently"}},
        {"SubdivideTetrahedra",
         tets_mesh,
         "subdivide --mesh {D}/t.mesh --out {D}/s.obj",
         2,
         {"{D}/t.mesh: Loop subdivision needs a triangle mesh"}},
        {"MapTetrahedraToObj",
         [](const Inputs& in) { tets_mesh(in); },
         "map --rest {D}/t.mesh --targets {D}/t.mesh --out {D}/o.obj",
         2,
         {"o.obj: .obj holds triangles"}},

        // Inputs that must succeed, verified.
        {"ProblemWithByteOrderMark",
         [](const Inputs& in) { in.text("p.txt", kBom + grid_problem(4, grid_boundary(4))); },
         "map --rest {D}/p.txt --out {D}/o.obj --quiet",
         0,
         {"success: verified"},
         {"o.obj", "o.png"}},
        {"LargestSeed",
         [](const Inputs& in) { in.text("p.txt", grid_problem(4, grid_boundary(4))); },
         "map --rest {D}/p.txt --out {D}/o.obj --initialization random --seed "
         "18446744073709551615 --quiet",
         0,
         {"success: verified"},
         {"o.obj", "o.png"}},
        {"ObjWithByteOrderMark",
         [](const Inputs& in) {
             in.text("bump.obj", kBom + "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.1\nf 1 2 3\nf 2 4 3\n");
         },
         "param --mesh {D}/bump.obj --out {D}/uv.obj --quiet",
         0,
         {"2 triangles, 4 vertices"},
         {"uv.obj", "uv.png"}},
        {"OffWithByteOrderMark",
         [](const Inputs& in) {
             bump_off(in);
             in.text("b.off", kBom + in.read("bump.off"));
         },
         "param --mesh {D}/b.off --out {D}/uv.obj --quiet",
         0,
         {"success: verified"},
         {"uv.obj", "uv.png"}},
        {"HandlesOnTheFirstLine",
         [](const Inputs& in) {
             in.text("p.txt", grid_problem(6, {0, 5, 30, 35}));
             in.text("h.txt", "3 10 20 30\n");
         },
         "map --rest {D}/p.txt --handles {D}/h.txt --out {D}/o.obj --quiet",
         0,
         {"4 handles", "success: verified"},
         {"o.obj", "o.png"}},
        // One per line, the first number equal to the count after it: an index, said so.
        {"HandlesFirstNumberCouldBeACount",
         [](const Inputs& in) {
             in.text("p.txt", grid_problem(6, {0, 5, 30, 35}));
             in.text("h.txt", "3\n0\n5\n35\n");
         },
         "map --rest {D}/p.txt --handles {D}/h.txt --out {D}/o.obj --quiet --no-png",
         0,
         {"4 handles", "h.txt:1: 3 read as an index", "success: verified"},
         {"o.obj"}},
        {"MeshAt1e200",
         [](const Inputs& in) {
             in.text("p.txt", grid_problem(4, grid_boundary(4), {{5, {0.9e200, 0.9e200}}}, 1e200));
         },
         "map --rest {D}/p.txt --out {D}/o.obj --quiet",
         0,
         {"result:      0 inverted, 0 degenerate; conformal max 1 ", "success: verified"},
         {"o.obj", "o.png"}},
        {"MeshAt1eMinus200",
         [](const Inputs& in) {
             in.text("p.txt",
                     grid_problem(4, grid_boundary(4), {{5, {0.9e-200, 0.9e-200}}}, 1e-200));
         },
         "map --rest {D}/p.txt --out {D}/o.obj --quiet",
         0,
         {"result:      0 inverted, 0 degenerate; conformal max 1 ", "success: verified"},
         {"o.obj", "o.png"}},
        {"SurfaceAt1e200",
         [](const Inputs& in) { in.mesh("b.off", bump(1e200)); },
         "param --mesh {D}/b.off --out {D}/uv.obj --quiet",
         0,
         {"success: verified"},
         {"uv.obj", "uv.png"}},
        {"SurfaceAt1eMinus200",
         [](const Inputs& in) { in.mesh("b.off", bump(1e-200)); },
         "param --mesh {D}/b.off --out {D}/uv.obj --quiet",
         0,
         {"success: verified"},
         {"uv.obj", "uv.png"}},
    };
    // The same scales to `sa seamless` and `sa polycube`: solved as at unit scale.
    for (const auto& [name, scale] :
         std::vector<std::pair<std::string, double>>{{"1e100", 1e100}, {"1eMinus100", 1e-100}}) {
        cases.push_back({"SeamlessSphereAt" + name,
                         [scale = scale](const Inputs& in) {
                             SimplicialMesh sphere = sphere_triangles(3);
                             sphere.vertices *= scale;
                             in.mesh("s.off", sphere);
                         },
                         "seamless --mesh {D}/s.off --out {D}/uv.obj --quiet --no-png",
                         0,
                         {"success: verified"},
                         {"uv.obj", "uv.vtu"}});
        cases.push_back({"PolycubeBoxAt" + name,
                         [scale = scale](const Inputs& in) {
                             SimplicialMesh box = grid_tetrahedra(2, 2, 2);
                             box.vertices *= scale;
                             in.mesh("b.mesh", box);
                         },
                         "polycube --mesh {D}/b.mesh --out {D}/p.mesh --quiet --no-png",
                         0,
                         {"success: PolyCube verified"},
                         {"p.mesh", "p.rest.mesh", "p.flags"}});
    }
    // A corner moved far from a 3 x 3 grid whose boundary is fixed: the initial map is
    // inversion-free, so the problem is solvable. (Beyond about 1e14 the verification calls the
    // unit triangles degenerate: its test is relative to the largest simplex of the map.)
    for (const auto& [name, far] : std::vector<std::pair<std::string, double>>{
             {"30", 30.0}, {"1e3", 1e3}, {"1e6", 1e6}, {"1e12", 1e12}}) {
        cases.push_back({"HandleMovedTo" + name,
                         // An init-capture: clang 14 cannot capture a structured binding.
                         [far = far](const Inputs& in) {
                             in.text("p.txt", grid_problem(3, grid_boundary(3), {{8, {far, far}}}));
                         },
                         "map --rest {D}/p.txt --out {D}/o.obj --quiet",
                         0,
                         {"success: verified"},
                         {"o.obj", "o.png"}});
    }
    // Two handles, one moved far: the best map is a similarity.
    cases.push_back({"TwoHandlesFarApart",
                     [](const Inputs& in) {
                         in.text("p.txt", grid_problem(3, {0, 8}, {{8, {1e6, 1e6}}}));
                     },
                     "map --rest {D}/p.txt --out {D}/o.obj --quiet",
                     0,
                     {"conformal max 1 ", "success: verified"},
                     {"o.obj", "o.png"}});
    // Pinched surfaces: a bowtie to `sa seamless`, two boxes touching at a corner to `sa
    // polycube`.
    cases.push_back({"SeamlessBowtie",
                     [](const Inputs& in) {
                         in.text("bow.off",
                                 "OFF\n5 2 0\n0 0 0\n1 0 0\n0.5 0.5 0\n0 1 0\n1 1 0\n"
                                 "3 0 1 2\n3 2 4 3\n");
                     },
                     "seamless --mesh {D}/bow.off --out {D}/s.obj",
                     2,
                     {"{D}/bow.off: pinched at vertex 2"}});
    cases.push_back({"PolycubeTwoBoxesTouchingAtACorner",
                     [](const Inputs& in) {
                         // The unit cube's tetrahedra and a copy moved by (1, 1, 1), whose corner
                         // at (1, 1, 1) is the cube's own vertex there.
                         const SimplicialMesh box = grid_tetrahedra(1, 1, 1);
                         const Index n = box.num_vertices();
                         Index corner = 0, origin = 0;
                         for (Index v = 0; v < n; ++v) {
                             if (box.vertices.row(v).minCoeff() == 1.0) corner = v;
                             if (box.vertices.row(v).maxCoeff() == 0.0) origin = v;
                         }
                         SimplicialMesh two;
                         two.vertices.resize(2 * n, 3);
                         two.vertices << box.vertices,
                             box.vertices.rowwise() + Eigen::RowVector3d(1, 1, 1);
                         two.simplices.resize(2 * box.num_simplices(), 4);
                         two.simplices << box.simplices, box.simplices.array() + int(n);
                         for (Index t = box.num_simplices(); t < two.num_simplices(); ++t)
                             for (int k = 0; k < 4; ++k)
                                 if (two.simplices(t, k) == int(n + origin))
                                     two.simplices(t, k) = int(corner);
                         // The copy's origin is used by no tetrahedron now: moved far off.
                         two.vertices.row(n + origin) << 9, 9, 9;
                         in.mesh("two.mesh", two);
                     },
                     "polycube --mesh {D}/two.mesh --out {D}/p.mesh",
                     2,
                     {"{D}/two.mesh: pinched at vertex"}});
    // `sa deform`: a 2 x 2 x 2 box of tetrahedra, its x = 0 face fixed and its x = 1 face
    // lifted, as rows `index x y z`.
    const auto lifted_box = [](const Inputs& in) {
        const SimplicialMesh box = grid_tetrahedra(2, 2, 2);
        in.mesh("box.mesh", box);
        std::ostringstream rows;
        for (Index v = 0; v < box.num_vertices(); ++v) {
            const double x = box.vertices(v, 0);
            if (x > 0.0 && x < 1.0) continue;
            rows << v << ' ' << x << ' ' << box.vertices(v, 1) + (x > 0.5 ? 0.2 : 0.0) << ' '
                 << box.vertices(v, 2) << '\n';
        }
        in.text("t.txt", rows.str());
    };
    // Standard output that cannot be written: the summary goes out before the outputs are put in
    // place, so every command ends with exit 2 and leaves nothing.
    for (const auto& [name, inputs, command] :
         std::vector<std::tuple<std::string, std::function<void(const Inputs&)>, std::string>>{
             {"Map", problem, "map --rest {D}/p.txt --out {D}/o.vtu --report {D}/r.json"},
             {"Param", bump_off, "param --mesh {D}/bump.off --out {D}/uv.obj --layout {D}/l.vtu"},
             {"Seamless", sphere_off, "seamless --mesh {D}/sphere.off --out {D}/s.obj"},
             {"Polycube", tets_mesh, "polycube --mesh {D}/t.mesh --out {D}/o.mesh"},
             {"Hex", tets_mesh, "hex --mesh {D}/t.mesh --hexes 50 --out {D}/o.mesh"},
             {"Deform", lifted_box,
              "deform --rest {D}/box.mesh --targets {D}/t.txt --out {D}/o.vtu"},
             {"Demo", none, "demo --size 4 --out-dir {D}/demo"},
             {"Subdivide", bump_off, "subdivide --mesh {D}/bump.off --out {D}/s.obj"}}) {
        const bool quiet = name != "Subdivide";
        cases.push_back({"StdoutFull" + name,
                         inputs,
                         command + (quiet ? " --quiet --no-png" : ""),
                         2,
                         {"sa: error: cannot write to standard output (No space left on device)"},
                         {},
                         true});
    }
    cases.push_back({"DeformPosesABox",
                     lifted_box,
                     "deform --rest {D}/box.mesh --targets {D}/t.txt --out {D}/o.vtu --report "
                     "{D}/r.json --quiet",
                     0,
                     {"ARAP start:", "success: verified"},
                     {"o.vtu", "o.png", "r.json"}});
    cases.push_back({"DeformHandleOutOfRange",
                     [&](const Inputs& in) {
                         lifted_box(in);
                         in.text("h.txt", "0\n1\n99\n");
                     },
                     "deform --rest {D}/box.mesh --handles {D}/h.txt --targets {D}/t.txt --out "
                     "{D}/o.vtu",
                     2,
                     {"{D}/h.txt:3:", "handle vertex 99 outside [0, 27)"}});
    cases.push_back({"DeformHandleTwiceWithTwoTargets",
                     [&](const Inputs& in) {
                         lifted_box(in);
                         in.text("t.txt", "0 0 0 0\n0 0.5 0 0\n");
                     },
                     "deform --rest {D}/box.mesh --targets {D}/t.txt --out {D}/o.vtu",
                     2,
                     {"{D}/t.txt:2:"}});
    cases.push_back({"DeformTargetBeyondDoubleArithmetic",
                     [&](const Inputs& in) {
                         lifted_box(in);
                         in.text("t.txt", in.read("t.txt") + "13 1e308 0 0\n");  // the centre
                     },
                     "deform --rest {D}/box.mesh --targets {D}/t.txt --out {D}/o.vtu",
                     2,
                     {"{D}/t.txt:", "the target of handle vertex 13 lies 1e+308 from the rest"}});
    cases.push_back({"DeformOptimalBoundWithABound",
                     lifted_box,
                     "deform --rest {D}/box.mesh --targets {D}/t.txt --out {D}/o.vtu "
                     "--optimal-bound --bound-volumetric 2",
                     2,
                     {"--optimal-bound finds both bounds"}});
    cases.push_back({"DeformSurfaceInSpace",
                     [&](const Inputs& in) {
                         lifted_box(in);
                         bump_off(in);
                     },
                     "deform --rest {D}/bump.off --targets {D}/t.txt --out {D}/o.vtu",
                     2,
                     {"{D}/bump.off", "triangles in space"}});
    // A planar mesh in a format of three coordinates (OFF), z = 0 at every vertex, posed in the
    // plane: its right side lifted, rows `index x y`.
    cases.push_back({"DeformPosesAPlanarOff",
                     [](const Inputs& in) {
                         const SimplicialMesh grid = grid_triangles(4, 4);
                         in.mesh("plane.off", grid);
                         std::ostringstream rows;
                         for (Index v = 0; v < grid.num_vertices(); ++v) {
                             const double x = grid.vertices(v, 0);
                             if (x > 0.0 && x < 1.0) continue;
                             rows << v << ' ' << x << ' '
                                  << grid.vertices(v, 1) + (x > 0.5 ? 0.2 : 0.0) << '\n';
                         }
                         in.text("t.txt", rows.str());
                     },
                     "deform --rest {D}/plane.off --targets {D}/t.txt --out {D}/o.obj --quiet "
                     "--no-png",  // a picture renders through Mesa (run-tests.sh)
                     0,
                     {"success: verified"},
                     {"o.obj"}});
    // The same posed by a handle list and rows `x y 0`, one per handle (z = 0, as a planar
    // target saved with three coordinates): their first numbers, 0 and 1, read as indices would
    // give vertices 0 and 1 two targets each, so the rows are positions.
    const auto planar_handles = [](const Inputs& in, bool indices_fit) {
        const SimplicialMesh grid = grid_triangles(4, 4);
        in.mesh("plane.off", grid);
        std::ostringstream handles, rows;
        for (Index v = 0; v < grid.num_vertices(); ++v) {
            const double x = grid.vertices(v, 0);
            if (x > 0.0 && x < 1.0) continue;
            handles << v << '\n';
            if (indices_fit) {
                rows << v << ' ' << x + 0.1 * double(v % 3) << " 0\n";
            } else {
                rows << x << ' ' << grid.vertices(v, 1) + (x > 0.5 ? 0.2 : 0.0) << " 0\n";
            }
        }
        in.text("h.txt", handles.str());
        in.text("t.txt", rows.str());
    };
    cases.push_back({"DeformPlanarTargetsXy0PerHandle",
                     [&](const Inputs& in) { planar_handles(in, false); },
                     "deform --rest {D}/plane.off --handles {D}/h.txt --targets {D}/t.txt --out "
                     "{D}/o.obj --quiet --no-png",
                     0,
                     {"rows `x y 0` of", "one per handle", "success: verified"},
                     {"o.obj"}});
    // Rows whose first numbers are the handles and whose last are 0 fit both readings.
    cases.push_back({"DeformPlanarTargetsFitTwoReadings",
                     [&](const Inputs& in) { planar_handles(in, true); },
                     "deform --rest {D}/plane.off --handles {D}/h.txt --targets {D}/t.txt --out "
                     "{D}/o.obj",
                     2,
                     {"{D}/t.txt: rows of three numbers fit both `index x y`", "`x y 0`"}});
    cases.push_back({"DeformOutAndReportTheSame",
                     lifted_box,
                     "deform --rest {D}/box.mesh --targets {D}/t.txt --out {D}/o.vtu --report "
                     "{D}/o.vtu",
                     2,
                     {"name the same file"}});
    return cases;
}

void PrintTo(const Case& c, std::ostream* out) {
    *out << c.name;
}

class BadInputCatalogue : public ::testing::TestWithParam<Case> {
  protected:
    void SetUp() override {
        base_ = fs::temp_directory_path() /
                ("sa_catalogue_" + std::to_string(::getpid()) + "_" + GetParam().name);
        fs::remove_all(base_);
        folder_ = base_ / "case";
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(base_); }

    fs::path base_, folder_;
};

TEST_P(BadInputCatalogue, OneLineTheRightStatusAndNothingLeft) {
    const Case& c = GetParam();
    const std::string folder = folder_.string();
    c.inputs(Inputs(folder_));
    const std::map<std::string, std::string> before = snapshot(folder_);
    const std::string out = (base_ / "stdout").string(), err = (base_ / "stderr").string();
    const std::string command = std::string(SA_EXECUTABLE) + " " + expand(c.command, folder) +
                                (c.full_stdout ? " > /dev/full" : " > " + out) + " 2> " + err;
    const int code = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(code)) << command;
    const std::string printed = read_file(out), errors = read_file(err);
    EXPECT_EQ(WEXITSTATUS(code), c.status) << command << "\n" << printed << errors;

    std::map<std::string, std::string> after = snapshot(folder_);
    if (c.status == 2) {
        EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n'), 1) << errors;
        EXPECT_EQ(errors.rfind("sa: error: ", 0), 0u) << errors;
        for (const std::string& part : c.parts)
            EXPECT_NE(errors.find(expand(part, folder)), std::string::npos)
                << "'" << expand(part, folder) << "' not in: " << errors;
    } else {
        for (const std::string& part : c.parts)
            EXPECT_NE(printed.find(part), std::string::npos) << part << " not in: " << printed;
    }
    for (const std::string& output : c.outputs) {
        EXPECT_TRUE(after.count(output)) << output << " was not written";
        after.erase(output);
    }
    // Nothing else: no output, no hidden temporary, every input unchanged.
    EXPECT_EQ(after, before) << command;
}

INSTANTIATE_TEST_SUITE_P(Sa, BadInputCatalogue, ::testing::ValuesIn(catalogue()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return info.param.name;
                         });

// ---------------------------------------------------------------------------------------------
// Interruptions: the process gets the signal while it writes (or records), and afterwards the
// folder holds only the inputs.

class Interruption : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() /
                  ("sa_interruption_" + std::to_string(::getpid()) + "_" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    /// Starts `sa` with `arguments` (stdout to `stdout_fd`, by default /dev/null, and stderr to
    /// `stderr_path`), with default signal dispositions, as from an interactive shell; with
    /// `sigpipe_ignored`, SIGPIPE ignored, as under nohup.
    pid_t start(const std::vector<std::string>& arguments, int stdout_fd = -1,
                const std::string& stderr_path = "/dev/null", bool sigpipe_ignored = false) {
        std::vector<std::string> args = {SA_EXECUTABLE};
        args.insert(args.end(), arguments.begin(), arguments.end());
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        if (stdout_fd >= 0) {
            posix_spawn_file_actions_adddup2(&actions, stdout_fd, 1);
        } else {
            posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
        }
        posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawnattr_t attributes;
        posix_spawnattr_init(&attributes);
        sigset_t defaults;
        sigemptyset(&defaults);
        for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, s);
        if (!sigpipe_ignored) sigaddset(&defaults, SIGPIPE);
        posix_spawnattr_setsigdefault(&attributes, &defaults);
        posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
        // An ignored signal stays ignored in the child.
        struct sigaction ignore {
        }, previous{};
        ignore.sa_handler = SIG_IGN;
        if (sigpipe_ignored) sigaction(SIGPIPE, &ignore, &previous);
        pid_t pid = -1;
        EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ), 0);
        if (sigpipe_ignored) sigaction(SIGPIPE, &previous, nullptr);
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attributes);
        return pid;
    }

    /// Waits until `ready()` (polling), the process ends or two minutes pass; true when ready()
    /// held. Does not reap the process (so that its pid stays its own until waitpid).
    static bool wait_until(pid_t pid, const std::function<bool()>& ready) {
        const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (std::chrono::steady_clock::now() < limit) {
            if (ready()) return true;
            siginfo_t info{};
            if (waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid)
                return false;
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
        return false;
    }

    /// Any hidden file (an output being written) in the folder tree.
    bool writing() const {
        for (const auto& entry : fs::recursive_directory_iterator(folder_)) {
            if (entry.path().filename().string().rfind(".", 0) == 0) return true;
        }
        return false;
    }

    fs::path folder_;
};

TEST_F(Interruption, WhileWritingLeavesNoFile) {
    // A large output, so that the signal arrives while it is written.
    const SimplicialMesh big = grid_triangles(300, 300);
    write_mesh_file((folder_ / "big.off").string(), big.vertices, big.simplices);
    const auto before = snapshot(folder_);
    for (const int signal : {SIGTERM, SIGINT}) {
        SCOPED_TRACE(signal);
        const pid_t pid = start({"subdivide", "--mesh", (folder_ / "big.off").string(), "--levels",
                                 "1", "--out", (folder_ / "fine.obj").string()});
        ASSERT_GT(pid, 0);
        const bool caught = wait_until(pid, [&] { return writing(); });
        kill(pid, signal);
        int status = 0;
        waitpid(pid, &status, 0);
        if (!caught) {
            ADD_FAILURE() << "the command ended before it wrote";
            continue;
        }
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << status;
        EXPECT_EQ(snapshot(folder_), before);
    }
}

TEST_F(Interruption, WhileRecordingRemovesTheRecording) {
    // A folded grid: the assembly records a frame per iteration.
    const int n = 40;
    std::vector<int> handles = grid_boundary(n);
    std::map<int, std::pair<double, double>> moved;
    for (int v = 0; v < n * n; ++v) {
        const int i = v % n, j = v / n;
        if (i > 0 && j > 0 && i < n - 1 && j < n - 1)
            moved[v] = {0.5 + 0.3 * std::sin(7.0 * v), 0.5 + 0.3 * std::cos(5.0 * v)};
    }
    std::ofstream(folder_ / "p.txt") << grid_problem(n, handles, moved);
    const auto before = snapshot(folder_);
    const pid_t pid =
        start({"map", "--rest", (folder_ / "p.txt").string(), "--out", (folder_ / "o.vtu").string(),
               "--record", (folder_ / "rec").string(), "--mode", "full"});
    ASSERT_GT(pid, 0);
    const bool recording = wait_until(pid, [&] {
        std::error_code error;
        return fs::exists(folder_ / "rec" / "iteration_0001.vtu", error);
    });
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(recording) << "the command ended before it recorded a frame";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
    EXPECT_EQ(snapshot(folder_), before);
}

// Standard output a pipe whose reader has gone: the summary is written before the outputs are
// put in place, so its SIGPIPE removes them and ends the command by that signal (README, "Exit
// status"); with SIGPIPE ignored, the write error is exit 2 and one line. Nothing is left.
TEST_F(Interruption, AClosedOutputPipeLeavesNothing) {
    std::ofstream(folder_ / "p.txt") << grid_problem(4, grid_boundary(4), {{5, {0.4, 0.5}}});
    const fs::path errors =
        fs::temp_directory_path() / ("sa_closed_pipe_" + std::to_string(::getpid()) + ".err");
    const auto before = snapshot(folder_);
    for (const bool ignored : {false, true}) {
        SCOPED_TRACE(ignored ? "SIGPIPE ignored" : "SIGPIPE by default");
        int ends[2];
        ASSERT_EQ(pipe(ends), 0);
        close(ends[0]);  // no reader
        const pid_t pid = start(
            {"map", "--rest", (folder_ / "p.txt").string(), "--out", (folder_ / "o.vtu").string(),
             "--report", (folder_ / "r.json").string(), "--quiet"},
            ends[1], errors.string(), ignored);
        close(ends[1]);
        ASSERT_GT(pid, 0);
        int status = 0;
        waitpid(pid, &status, 0);
        const std::string said = read_file(errors);
        if (ignored) {
            EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << status;
            EXPECT_EQ(said, "sa: error: cannot write to standard output (Broken pipe)\n");
        } else {
            EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGPIPE) << status;
            EXPECT_EQ(said, "");
        }
        EXPECT_EQ(snapshot(folder_), before);
    }
    fs::remove(errors);
}

}  // namespace
}  // namespace sa
