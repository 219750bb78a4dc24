// The fuzz targets in every build (fuzz_targets.h): each target's seeds, valid files, are read
// without error, and every input kept in tests/fuzz/regressions/<target>/ (inputs that once
// crashed a reader or made it misbehave, fixed since) ends in sa::Error or is read, nothing else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fuzz_targets.h"
#include "optim/errors.h"

namespace sa::fuzz {

// Found by argument-dependent lookup: in Target's own namespace.
void PrintTo(const Target& target, std::ostream* out) {
    *out << target.name;
}

namespace {

class FuzzTarget : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzTarget, SeedsAreRead) {
    const Target& target = GetParam();
    const std::vector<Bytes> seeds = target.seeds();
    EXPECT_FALSE(seeds.empty());
    for (std::size_t i = 0; i < seeds.size(); ++i) {
        SCOPED_TRACE("seed " + std::to_string(i));
        try {
            target.run(seeds[i].data(), seeds[i].size());
        } catch (const std::exception& e) {
            ADD_FAILURE() << e.what();
        }
    }
}

TEST_P(FuzzTarget, RegressionInputsAreRejectedOrRead) {
    const Target& target = GetParam();
    const std::filesystem::path folder = std::filesystem::path(SA_FUZZ_REGRESSIONS) / target.name;
    if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "no regression inputs";
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        SCOPED_TRACE(entry.path().string());
        std::ifstream in(entry.path(), std::ios::binary);
        const Bytes input((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        try {
            target.run(input.data(), input.size());
        } catch (const Error&) {
            // rejected, as it should be
        } catch (const std::exception& e) {
            ADD_FAILURE() << "not an sa::Error: " << e.what();
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Readers, FuzzTarget, ::testing::ValuesIn(targets()),
                         [](const ::testing::TestParamInfo<Target>& info) {
                             return std::string(info.param.name);
                         });

}  // namespace
}  // namespace sa::fuzz
