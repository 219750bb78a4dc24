// What the sa command does to its own process, tested on the command as built (run by
// scripts/check-package.sh against the Release build, where the command links jemalloc, OpenBLAS's
// buffer and its plugins as users get them; docs/building.md): under an address-space limit it
// starts or ends at once with one line, a VTK output whose plugin cannot be loaded is found before
// the solve, and OpenBLAS runs its own kernels for the CPU. In the test build (sanitizers) the
// tests that cannot run there skip.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_generators.h"
#include "tests/fixtures/grid_problem_text.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

// Built with -fsanitize=address: the runtime reserves terabytes of address space, so that a
// `ulimit -v` test cannot run.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Runs `command` in a shell: its stdout and stderr together, its status in `status`.
std::string shell(const std::string& command, int* status) {
    const fs::path out = fs::temp_directory_path() / ("sa_shell_" + std::to_string(::getpid()));
    *status = std::system((command + " > " + out.string() + " 2>&1").c_str());
    std::string text = read_file(out);
    fs::remove(out);
    return text;
}

TEST(MemoryLimit, StartsOrFailsAtOnceNeverHangs) {
    if (kSanitized) GTEST_SKIP() << "the sanitizer runtime cannot run under ulimit -v";
    // `sa --version` hung at 100% CPU below about 190 MB (OpenBLAS retried its buffer).
    for (const int kilobytes : {60000, 100000, 150000, 190000}) {
        int status = 0;
        const std::string text = shell("ulimit -v " + std::to_string(kilobytes) + "; timeout 20 " +
                                           std::string(SA_EXECUTABLE) + " --version",
                                       &status);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << kilobytes << ": " << text;
        EXPECT_EQ(text, "sa 0.1.0\n");
    }
}

// Every command that solves takes OpenBLAS's work buffer before it reads (OpenBLAS would retry
// the allocation for ever: `sa polycube` did, below 160 MB): under a limit too low for it, each
// ends at once with exit 4, before it even finds that its input does not exist.
TEST(MemoryLimit, EveryCommandThatSolvesEndsAtOnceWhenTheBlasBufferCannotBeHad) {
    if (kSanitized) GTEST_SKIP() << "the sanitizer runtime cannot run under ulimit -v";
    const fs::path folder = fs::temp_directory_path() / ("sa_blas_" + std::to_string(::getpid()));
    const std::string d = folder.string();
    for (const std::string& arguments : std::vector<std::string>{
             "map --rest " + d + "/p.txt --out " + d + "/o.vtu",
             "param --mesh " + d + "/m.obj --out " + d + "/o.obj",
             "seamless --mesh " + d + "/m.obj --out " + d + "/o.obj",
             "polycube --mesh " + d + "/m.mesh --out " + d + "/o.mesh",
             "hex --mesh " + d + "/m.mesh --out " + d + "/o.mesh",
             "deform --rest " + d + "/m.mesh --targets " + d + "/t.txt --out " + d + "/o.vtu",
             "demo --out-dir " + d + "/demo"}) {
        SCOPED_TRACE(arguments);
        int status = 0;
        const std::string text =
            shell("ulimit -v 150000; timeout 20 " + std::string(SA_EXECUTABLE) + " " + arguments,
                  &status);
        ASSERT_TRUE(WIFEXITED(status)) << text;
        EXPECT_EQ(WEXITSTATUS(status), 4) << text;
        EXPECT_NE(text.find("out of memory while reserving OpenBLAS's"), std::string::npos) << text;
        EXPECT_FALSE(fs::exists(folder));
    }
}

// A VTK output needs the plugin that writes it (libsa_vtk_io.so, in the lib/ beside the program's
// bin/): a program moved away from it says so before it reads, not after the solve.
TEST(Plugins, AMissingVtkWriterIsFoundBeforeTheSolve) {
    if (kSanitized) GTEST_SKIP() << "the sanitized sa finds its shared libraries by their folder";
    const fs::path folder = fs::temp_directory_path() / ("sa_moved_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder / "bin");
    fs::copy_file(SA_EXECUTABLE, folder / "bin" / "sa");
    std::ofstream(folder / "p.txt") << grid_problem(4, grid_boundary(4));
    const SimplicialMesh box = grid_tetrahedra(1, 1, 1);
    write_mesh_file((folder / "box.mesh").string(), box.vertices, box.simplices);
    const std::string d = folder.string();
    for (const auto& [arguments, output] : std::vector<std::pair<std::string, std::string>>{
             {"map --rest " + d + "/p.txt --out " + d + "/o.vtu", "--out " + d + "/o.vtu"},
             {"polycube --mesh " + d + "/box.mesh --out " + d + "/o.mesh --vtu " + d + "/o.vtk",
              "--vtu " + d + "/o.vtk"},
             {"hex --mesh " + d + "/box.mesh --out " + d + "/o.mesh --vtu " + d + "/o.vtk",
              "--vtu " + d + "/o.vtk"}}) {
        SCOPED_TRACE(arguments);
        int status = 0;
        const std::string text = shell((folder / "bin" / "sa").string() + " " + arguments, &status);
        ASSERT_TRUE(WIFEXITED(status)) << text;
        EXPECT_EQ(WEXITSTATUS(status), 2) << text;
        EXPECT_EQ(text.rfind("sa: error: " + output + ": cannot load libsa_vtk_io.so", 0), 0u)
            << text;
        EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    }
    for (const char* name : {"o.vtu", "o.vtk", "o.mesh", "o.png", "o.rest.mesh", "o.flags"})
        EXPECT_FALSE(fs::exists(folder / name)) << name;
    fs::remove_all(folder);
}

TEST(MemoryLimit, RunningOutIsOneLineAndExitFour) {
    if (kSanitized) GTEST_SKIP() << "the sanitizer runtime cannot run under ulimit -v";
    const fs::path folder =
        fs::temp_directory_path() / ("sa_memory_limit_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    fs::create_directories(folder);
    const int n = 120;
    std::map<int, std::pair<double, double>> moved;
    for (int v = n + 1; v < n * n - n - 1; v += 7) moved[v] = {0.5, 0.5};
    std::ofstream(folder / "p.txt") << grid_problem(n, grid_boundary(n), moved);
    int out_of_memory = 0;
    for (int megabytes = 160; megabytes <= 400; megabytes += 40) {
        SCOPED_TRACE(megabytes);
        int status = 0;
        const std::string text = shell(
            "ulimit -v " + std::to_string(megabytes * 1024) + "; timeout 120 " +
                std::string(SA_EXECUTABLE) + " map --quiet --mode full --rest " +
                (folder / "p.txt").string() + " --out " + (folder / "o.vtu").string() + " --force",
            &status);
        ASSERT_TRUE(WIFEXITED(status)) << text;
        const int code = WEXITSTATUS(status);
        EXPECT_NE(code, 124) << "timed out: " << text;  // timeout's status: a hang
        if (code == 4) {
            ++out_of_memory;
            const std::string last = text.substr(text.rfind("sa: error: "));
            EXPECT_EQ(std::count(last.begin(), last.end(), '\n'), 1) << last;
            EXPECT_NE(last.find("out of memory while "), std::string::npos) << last;
            EXPECT_NE(last.find("address-space limit (ulimit -v)"), std::string::npos) << last;
            EXPECT_FALSE(fs::exists(folder / "o.vtu"));
        } else {
            EXPECT_TRUE(code == 0 || code == 1) << text;
        }
    }
    EXPECT_GT(out_of_memory, 0) << "no limit was low enough to run out";
    fs::remove_all(folder);
}

// ---------------------------------------------------------------------------------------------
// The command's BLAS: OpenBLAS's SSE3 fallback for a CPU model it does not know is replaced by
// its AVX-512 or AVX2 kernels (runtime_settings.cpp). OPENBLAS_VERBOSE=2 prints "Core: NAME" at
// each pick.

TEST(CommandBlas, NotTheSse3FallbackOnACpuWithAvx2) {
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
        GTEST_SKIP() << "this CPU has no AVX2 and FMA";
    int status = 0;
    const std::string text = shell(
        "unset OPENBLAS_CORETYPE; OPENBLAS_VERBOSE=2 " + std::string(SA_EXECUTABLE) + " --version",
        &status);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << text;
    const std::size_t last = text.rfind("Core: ");
    if (last == std::string::npos) GTEST_SKIP() << "the BLAS is not OpenBLAS built for every core";
    EXPECT_NE(text.substr(last, text.find('\n', last) - last), "Core: Prescott") << text;
    EXPECT_NE(text.find("sa 0.1.0\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace sa
