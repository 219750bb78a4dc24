#include "frontends/cli/output_plan.h"

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "frontends/cli/cli_support.h"
#include "frontends/cli/out_of_memory.h"
#include "geometry/io/vtk_io.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"

namespace sa::cli {
namespace {

namespace fs = std::filesystem;

/// The path with symbolic links and `..` resolved as far as it exists, for comparisons.
std::string resolved(const std::string& path) {
    std::error_code error;
    const fs::path absolute = fs::absolute(path, error);
    if (error) return path;
    const fs::path canonical = fs::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal().string() : canonical.string();
}

/// The folder a file goes in ("." for a bare name).
fs::path folder_of(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

std::string describe(const std::string& option, const std::string& path) {
    return option + " " + path;
}

/// Throws InputError unless `folder` is an existing folder in which a file can be created.
void check_folder(const fs::path& folder, const std::string& option, const std::string& path) {
    std::error_code error;
    const fs::file_status status = fs::status(folder, error);
    if (!fs::exists(status))
        throw InputError(describe(option, path) + ": folder '" + folder.string() +
                         "' does not exist");
    if (!fs::is_directory(status))
        throw InputError(describe(option, path) + ": '" + folder.string() + "' is not a folder");
    // access() says yes to root on a read-only file system: try for real.
    const std::string probe = (folder / (".sa-probe-" + std::to_string(getpid()))).string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        const int reason = errno;
        if (reason != EEXIST)
            throw InputError(describe(option, path) + ": cannot write in folder '" +
                             folder.string() + "' (" + std::strerror(reason) + ")");
        return;
    }
    ::close(fd);
    ::unlink(probe.c_str());
}

}  // namespace

void flush_standard_output() {
    errno = 0;
    std::cout.flush();
    if (std::fflush(stdout) == 0 && std::ferror(stdout) == 0 && std::cout) return;
    const int reason = errno;
    if (reason == EPIPE) await_broken_pipe_cleanup();
    throw InputError(std::string("cannot write to standard output (") +
                     (reason != 0 ? std::strerror(reason) : "write error") + ")");
}

OutputPlan::OutputPlan(bool overwrite) : overwrite_(overwrite) {
    set_interruption_cleanup([this] { roll_back(); });
}

OutputPlan::~OutputPlan() {
    set_interruption_cleanup({});
    if (committed_) return;
    const auto lock = output_lock();
    roll_back();
}

void OutputPlan::input(const std::string& option, const std::string& path) {
    if (!path.empty()) inputs_.push_back({option, path});
}

void OutputPlan::file(const std::string& option, const std::string& path) {
    if (path.empty()) return;
    files_.push_back({option, path});
    // A TetGen output is two files (geometry/io/tetgen_io.h): the writer puts the other one next
    // to the staged name, so it is checked, renamed and rolled back with it.
    std::string extension = fs::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".node" || extension == ".ele")
        files_.push_back(
            {option,
             fs::path(path).replace_extension(extension == ".node" ? ".ele" : ".node").string()});
}

void OutputPlan::folder(const std::string& option, const std::string& path,
                        std::vector<std::string> marks) {
    if (!path.empty()) folders_.push_back({option, path, std::move(marks), {}, {}, false});
}

void OutputPlan::check() const {
    // Names: every output distinct, none an input.
    std::vector<std::pair<std::string, const Entry*>> outputs;
    for (const Entry& f : files_) outputs.push_back({resolved(f.path), &f});
    std::vector<Entry> folder_entries;
    for (const Folder& f : folders_) folder_entries.push_back({f.option, f.path});
    for (const Entry& f : folder_entries) outputs.push_back({resolved(f.path), &f});
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (outputs[i].first == outputs[j].first)
                throw InvalidArgumentError(outputs[j].second->option + " and " +
                                           outputs[i].second->option + " name the same file '" +
                                           outputs[i].second->path + "'");
        }
        for (const Entry& in : inputs_) {
            std::error_code error;
            if (outputs[i].first == resolved(in.path) ||
                fs::equivalent(outputs[i].second->path, in.path, error))
                throw InvalidArgumentError(outputs[i].second->option + " " +
                                           outputs[i].second->path + " is the input of " +
                                           in.option + "; write the output elsewhere");
        }
    }

    // Locations.
    for (const Folder& f : folders_) {
        std::error_code error;
        const fs::file_status status = fs::status(f.path, error);
        if (fs::exists(status)) {
            if (!fs::is_directory(status))
                throw InputError(describe(f.option, f.path) + ": exists and is not a folder");
            check_folder(f.path, f.option, f.path);
            for (const std::string& name : f.marks) {
                const fs::path existing = fs::path(f.path) / name;
                if (!overwrite_ && fs::exists(existing, error))
                    throw InputError(existing.string() + " exists; pass --force to overwrite it");
            }
            continue;
        }
        // Created with its parents: the nearest existing ancestor must take new folders.
        fs::path ancestor = fs::absolute(f.path, error).parent_path();
        while (!ancestor.empty() && !fs::exists(ancestor, error) &&
               ancestor != ancestor.root_path())
            ancestor = ancestor.parent_path();
        check_folder(ancestor, f.option, f.path);
    }
    for (const Entry& f : files_) {
        std::error_code error;
        const fs::file_status status = fs::status(f.path, error);
        if (fs::is_directory(status))
            throw InputError(describe(f.option, f.path) + ": is a directory");
        const std::string folder = resolved(folder_of(f.path).string());
        bool in_planned_folder = false;
        for (const Folder& planned : folders_)
            in_planned_folder = in_planned_folder || resolved(planned.path) == folder;
        if (!in_planned_folder || fs::is_directory(folder, error))
            check_folder(folder_of(f.path), f.option, f.path);
        if (fs::exists(status) && !overwrite_)
            throw InputError(f.path + " exists; pass --force to overwrite it");
    }

    // Writers that live in a plugin: found now, not after the solve.
    for (const Entry& f : files_) check_vtk_writer(f.option, f.path);
}

void check_vtk_writer(const std::string& option, const std::string& path) {
    const std::string format = extension(path);
    if (format != ".vtu" && format != ".vtk") return;
    set_activity("loading the VTK file writer (libsa_vtk_io.so) for " + option + " " + path);
    try {
        require_vtk_io();  // once per process: the later calls return at once
    } catch (const Error& e) {
        throw InputError(describe(option, path) + ": " + e.what());
    }
}

void OutputPlan::open_folders() {
    const auto lock = output_lock();
    for (Folder& f : folders_) {
        if (f.opened) continue;
        std::error_code error;
        if (fs::is_directory(f.path, error)) {
            for (const auto& entry : fs::directory_iterator(f.path, error))
                f.existing.insert(entry.path().filename().string());
        } else {
            fs::path top = fs::absolute(f.path, error);
            while (!fs::exists(top.parent_path(), error) && top.parent_path() != top.root_path())
                top = top.parent_path();
            fs::create_directories(f.path, error);
            if (error || !fs::is_directory(f.path))
                throw InputError(describe(f.option, f.path) + ": cannot create the folder (" +
                                 error.message() + ")");
            f.created = top.string();
        }
        f.opened = true;
    }
}

std::string OutputPlan::staged(const std::string& path) const {
    const fs::path p(path);
    std::string name = ".";
    name.append(p.stem().string())
        .append(".sa-")
        .append(std::to_string(getpid()))
        .append(p.extension().string());
    return (p.parent_path() / name).string();
}

void OutputPlan::commit(const std::string& summary) {
    std::cout << summary;
    flush_standard_output();
    const auto lock = output_lock();
    std::vector<std::string> renamed;
    for (const Entry& f : files_) {
        std::error_code error;
        if (!fs::exists(staged(f.path), error)) continue;  // not written (e.g. an optional picture)
        fs::rename(staged(f.path), f.path, error);
        if (error) {
            for (const std::string& done : renamed) fs::remove(done, error);
            throw InputError(describe(f.option, f.path) +
                             ": cannot move the written file into place (" + error.message() + ")");
        }
        renamed.push_back(f.path);
    }
    committed_ = true;
}

void OutputPlan::roll_back() noexcept {
    if (committed_) return;
    try {
        remove_outputs();
    } catch (...) {
        // Out of memory while removing: what is left stays (hidden names), nothing else to do.
    }
}

void OutputPlan::remove_outputs() const {
    std::error_code error;
    for (const Entry& f : files_) {
        const std::string staged_path = staged(f.path);
        fs::remove(staged_path, error);
        // The temporary of an AtomicFile (geometry/io/atomic_file.h) writing it, if any. Built
        // by appending: `"." + std::string` trips GCC 12's -Wrestrict (bug 105329).
        const fs::path s(staged_path);
        std::string temporary = ".";
        temporary.append(s.filename().string()).append(".tmp-").append(std::to_string(getpid()));
        fs::remove(s.parent_path() / temporary, error);
        // check()'s probe, when the run was interrupted between its creation and removal.
        fs::remove(folder_of(f.path) / (".sa-probe-" + std::to_string(getpid())), error);
    }
    for (const Folder& f : folders_) {
        if (!f.opened) continue;
        if (!f.created.empty()) {
            fs::remove_all(f.created, error);
            continue;
        }
        std::vector<fs::path> added;
        for (const auto& entry : fs::directory_iterator(f.path, error)) {
            if (!f.existing.count(entry.path().filename().string())) added.push_back(entry.path());
        }
        for (const fs::path& entry : added) fs::remove_all(entry, error);
    }
}

PictureOutput::PictureOutput(const std::string& png, bool no_png, const std::string& out,
                             double max_time_seconds)
    : path_(no_png        ? ""
            : png.empty() ? with_extension(out, ".png")
                          : png),
      option_(png.empty() ? "--png (from --out)" : "--png"),
      asked_(!png.empty()),
      max_time_seconds_(max_time_seconds) {
    if (!path_.empty() && extension(path_) != ".png")
        throw InvalidArgumentError(option_ + " " + path_ + ": expected a .png file");
}

void PictureOutput::plan(OutputPlan& plan) const {
    plan.file(option_, path_);
}

void PictureOutput::draw(OutputPlan& plan, const std::function<void(const std::string&)>& draw) {
    if (path_.empty()) return;
    const double elapsed = since_start_.seconds();
    if (!asked_ && elapsed > max_time_seconds_) {
        char limit[96];
        std::snprintf(limit, sizeof limit, "--max-time %g had run out (%.2f s)", max_time_seconds_,
                      elapsed);
        failure_ = std::string(limit) + "; --png " + path_ + " draws it all the same";
        return;
    }
    set_activity("drawing --png " + path_);
    const Stopwatch drawing;
    try {
        plan.write(path_, draw);
        char took[64];
        std::snprintf(took, sizeof took, " (%.2f s)", drawing.seconds());
        drawn_ = path_ + took;
    } catch (const Error& e) {
        failure_ = one_line(e.what());
        std::error_code error;
        fs::remove(plan.staged(path_), error);  // a picture begun is not committed
    }
}

std::string PictureOutput::wrote() const {
    return drawn_.empty() ? "" : ", " + drawn_;
}

void PictureOutput::warn(std::ostream& out) const {
    if (!failure_.empty()) out << "sa: warning: no picture " << path_ << ": " << failure_ << '\n';
}

}  // namespace sa::cli
