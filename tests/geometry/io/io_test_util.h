#pragma once
// Helpers shared by the geometry/io tests: a fresh temporary folder per test, files written from
// strings, and checks of InputError messages.

#include <gtest/gtest.h>
#include <unistd.h>
#include <Eigen/Core>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>

#include "optim/errors.h"

namespace sa::test {

/// A fresh folder named after the running test, removed with its contents at the end.
class TempFolder {
  public:
    TempFolder() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = "sa_io_" + std::to_string(getpid());
        if (info != nullptr)
            name += std::string("_") + info->test_suite_name() + "_" + info->name();
        for (char& c : name)
            if (c == '/') c = '_';
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    /// The path of `name` in the folder.
    std::string path(const std::string& name) const { return (path_ / name).string(); }
    /// Writes `content` (as is, binary) to `name` and returns its path.
    std::string write(const std::string& name, const std::string& content) const {
        const std::string file = path(name);
        std::ofstream out(file, std::ios::binary);
        out << content;
        return file;
    }
    /// The number of entries in the folder (to check that no temporary is left behind).
    std::size_t entries() const {
        std::size_t n = 0;
        for (const auto& entry : std::filesystem::directory_iterator(path_)) ++n, (void)entry;
        return n;
    }
    const std::filesystem::path& root() const { return path_; }

  private:
    std::filesystem::path path_;
};

inline std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Success when `f()` throws InputError whose message is one line and contains every part.
template <class F>
::testing::AssertionResult throws_input_error(F&& f, std::initializer_list<std::string> parts) {
    try {
        f();
    } catch (const InputError& error) {
        const std::string message = error.what();
        if (message.find('\n') != std::string::npos)
            return ::testing::AssertionFailure() << "message has several lines: " << message;
        for (const std::string& part : parts) {
            if (message.find(part) == std::string::npos)
                return ::testing::AssertionFailure()
                       << "message '" << message << "' lacks '" << part << "'";
        }
        return ::testing::AssertionSuccess() << message;
    } catch (const std::exception& error) {
        return ::testing::AssertionFailure() << "threw another exception: " << error.what();
    }
    return ::testing::AssertionFailure() << "did not throw";
}

/// Success when `f()` throws InvalidArgumentError whose message contains `part`.
template <class F>
::testing::AssertionResult throws_invalid_argument(F&& f, const std::string& part) {
    try {
        f();
    } catch (const InvalidArgumentError& error) {
        const std::string message = error.what();
        if (message.find(part) == std::string::npos)
            return ::testing::AssertionFailure()
                   << "message '" << message << "' lacks '" << part << "'";
        return ::testing::AssertionSuccess() << message;
    } catch (const std::exception& error) {
        return ::testing::AssertionFailure() << "threw another exception: " << error.what();
    }
    return ::testing::AssertionFailure() << "did not throw";
}

/// The writer contract: writing into a missing folder throws InputError and leaves nothing; a write
/// that fails (`bad_write`, which must throw) leaves an existing file untouched; a successful
/// `write` replaces it. Each callable takes the destination path. No temporary is left behind.
template <class Write, class BadWrite>
void check_atomic_writes(const TempFolder& folder, const std::string& name, Write write,
                         BadWrite bad_write) {
    const std::string missing = folder.path("missing/" + name);
    EXPECT_THROW(write(missing), InputError);
    EXPECT_FALSE(std::filesystem::exists(folder.path("missing")));

    const std::string path = folder.write(name, "old content");
    const std::size_t entries = folder.entries();
    EXPECT_THROW(bad_write(path), Error);
    EXPECT_EQ(read_all(path), "old content");
    EXPECT_EQ(folder.entries(), entries);
    write(path);
    EXPECT_NE(read_all(path), "old content");
    EXPECT_EQ(folder.entries(), entries);
}

inline  // A binary .dmat: `0 0`, `cols rows`, then little-endian doubles column by column, then
        // `extra`.
    std::string
    binary_dmat(const Eigen::MatrixXd& matrix, const std::string& extra = "") {
    std::string bytes =
        "0 0\n" + std::to_string(matrix.cols()) + " " + std::to_string(matrix.rows()) + "\n";
    for (Eigen::Index j = 0; j < matrix.cols(); ++j) {
        for (Eigen::Index i = 0; i < matrix.rows(); ++i) {
            const double value = matrix(i, j);
            std::uint64_t bits = 0;
            std::memcpy(&bits, &value, sizeof bits);
            for (int b = 0; b < 8; ++b)
                bytes.push_back(static_cast<char>((bits >> (8 * b)) & 0xff));
        }
    }
    return bytes + extra;
}

}  // namespace sa::test
