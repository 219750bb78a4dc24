#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "geometry/io/atomic_file.h"
#include "optim/errors.h"

namespace sa {
namespace {

std::string read_all(const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(AtomicFile, CommitReplacesAndAbandonLeavesNothing) {
    const auto folder = std::filesystem::temp_directory_path() / "sa_atomic_file_test";
    std::filesystem::create_directories(folder);
    const std::string path = (folder / "out.txt").string();
    {
        AtomicFile file(path);
        file.stream() << "first";
        file.commit();
    }
    EXPECT_EQ(read_all(path), "first");
    {
        AtomicFile file(path);
        file.stream() << "second, never committed";
    }
    EXPECT_EQ(read_all(path), "first");  // the user's file is intact
    std::size_t entries = 0;
    for (const auto& e : std::filesystem::directory_iterator(folder)) ++entries, (void)e;
    EXPECT_EQ(entries, 1u);  // no temporary left behind
    EXPECT_THROW(AtomicFile((folder / "missing" / "x.txt").string()), InputError);
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace sa
