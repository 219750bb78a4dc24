#include "geometry/io/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "optim/errors.h"

namespace sa {

AtomicFile::AtomicFile(std::string path, bool binary) : path_(std::move(path)) {
    const std::filesystem::path target(path_);
    const std::filesystem::path folder =
        target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(folder)) {
        throw InputError(path_ + ": cannot write, folder '" + folder.string() + "' does not exist");
    }
    std::string name = ".";  // built with append: GCC 12 warns falsely (-Wrestrict) on a + chain
    name.append(target.filename().string()).append(".tmp-").append(std::to_string(getpid()));
    temporary_ = (folder / name).string();
    stream_.open(temporary_, binary ? std::ios::out | std::ios::binary : std::ios::out);
    if (!stream_) {
        throw InputError(path_ + ": cannot write (" + std::strerror(errno) + ")");
    }
    stream_.precision(17);
}

AtomicFile::~AtomicFile() {
    if (!committed_) {
        stream_.close();
        std::remove(temporary_.c_str());
    }
}

void AtomicFile::commit() {
    stream_.flush();
    const bool ok = static_cast<bool>(stream_);
    stream_.close();
    if (!ok) throw InputError(path_ + ": writing failed (disk full?)");
    std::error_code error;
    std::filesystem::rename(temporary_, path_, error);
    if (error)
        throw InputError(path_ + ": cannot move the written file into place (" + error.message() +
                         ")");
    committed_ = true;
}

}  // namespace sa
