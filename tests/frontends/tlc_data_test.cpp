// The published untangling problems of ../shared/data/tlc, solved and verified. Skips when the
// data folder is absent.
#include <gtest/gtest.h>

#include <filesystem>

#include "frontends/simplex_assembly/map_solve.h"
#include "geometry/io/problem_io.h"
#include "geometry/quality/handle_feasibility.h"

namespace sa {
namespace {

std::string tlc_path(const std::string& name) {
    return std::string(SA_DATA_DIR) + "/tlc/" + name + "/input";
}

MappingProblem read_tlc(const std::string& path) {
    const MeshFile file = read_problem(path);
    MappingProblem p;
    p.mesh = file.mesh;
    p.initial = *file.initial;
    p.handles = file.handles;
    p.source = path;
    return p;
}

class TlcProblem : public ::testing::TestWithParam<const char*> {};

TEST_P(TlcProblem, UntanglesAndVerifies) {
    const std::string path = tlc_path(GetParam());
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    const SimplexAssemblyResult r = run_simplex_assembly(read_tlc(path), SimplexAssemblyOptions{});
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.verification.inverted, 0);
    EXPECT_LE(r.verification.handle_error, r.verification.handle_tolerance);
}

// stgc-3d's full solve cannot assemble: E~ stays at 2.2e-5 once lambda reaches lambda_max. It
// must stop there when E stops changing rather than run on to the iteration limit, and still
// hand a verified map over.
TEST(TlcFullSolve, StopsAtLambdaMaxWhenEConverges) {
    const std::string path = tlc_path("stgc-3d");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    SimplexAssemblyOptions options;
    options.mode = SolveMode::kFull;
    const SimplexAssemblyResult r = run_simplex_assembly(read_tlc(path), options);
    EXPECT_TRUE(r.success) << r.message;
    EXPECT_FALSE(r.assembled);
    EXPECT_EQ(r.stages.outcome<AssemblyStop>(Stage::kAssembly), AssemblyStop::kConvergedAtLambdaMax)
        << r.message;
    EXPECT_EQ(r.final_lambda, options.lambda_max);
    EXPECT_LT(r.newton.num_steps(), 60);
}

INSTANTIATE_TEST_SUITE_P(Tlc, TlcProblem,
                         ::testing::Values("stgc-2d", "sea-2d", "param2d", "cube", "stgc-3d"),
                         [](const auto& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// infeasible-star fixes every boundary vertex where 392 tets whose vertices are all handles are
// inverted: no map can exist, and the driver says so before optimizing anything.
TEST(TlcInfeasible, StarIsDiagnosedBeforeOptimizing) {
    const std::string path = tlc_path("infeasible-star");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
    try {
        run_simplex_assembly(read_tlc(path), SimplexAssemblyOptions{});
        ADD_FAILURE() << "no InfeasibleProblemError";
    } catch (const InfeasibleProblemError& e) {
        EXPECT_EQ(e.diagnosis().inverted.size() + e.diagnosis().flat.size(), 392u) << e.what();
    }
}

}  // namespace
}  // namespace sa
