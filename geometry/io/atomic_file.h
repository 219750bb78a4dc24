#pragma once
// Writes a file under a temporary name in the destination's folder and renames it into place on
// commit(), so that a failed or interrupted write never leaves a partial file at `path` and an
// existing file there is replaced only by a complete one. Without commit() the temporary is
// removed when the writer is destroyed.
//
//   AtomicFile file(path);
//   file.stream() << ...;          // or write to file.temporary_path() with another library
//   file.commit();                 // throws InputError if writing or renaming failed

#include <fstream>
#include <string>

namespace sa {

class AtomicFile {
  public:
    /// Opens a text stream on the temporary file (binary when `binary`); throws InputError when
    /// the folder is not writable.
    explicit AtomicFile(std::string path, bool binary = false);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::ofstream& stream() { return stream_; }
    const std::string& path() const { return path_; }
    /// For libraries that write by file name (VTK): write there, then commit().
    const std::string& temporary_path() const { return temporary_; }
    /// Flushes, checks for write errors and renames the temporary file to path().
    void commit();

  private:
    std::string path_;
    std::string temporary_;
    std::ofstream stream_;
    bool committed_ = false;
};

}  // namespace sa
