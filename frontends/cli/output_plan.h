#pragma once
// The outputs of one run of an `sa` command: checked before anything is read, written all or
// nothing.
//
//   OutputPlan plan(force);
//   plan.input("--rest", rest);  plan.file("--out", out);  plan.folder("--record", frames);
//   plan.check();                  // before reading or solving
//   ... read, solve ...
//   plan.open_folders();           // creates the folders (before the solve that records)
//   plan.write(out, [&](const std::string& path) { write_mesh_file(path, ...); });
//   plan.commit(summary);          // the summary to stdout, then every file renamed into place
//
// check() rejects, naming the option: two outputs with one path, an output that names an input
// (even with --force), an output that is a directory, a folder that does not exist, is not a
// folder or cannot be written (tried by creating a file in it), and an existing file without
// --force.
//
// Each file is written under a hidden name in its own folder, `.NAME.sa-PID.EXT` (the same
// extension, so that the writers choose the same format), and commit() renames them all into
// place. Until then a failure (an exception, or an interruption: interruption.h) removes every
// hidden file, a folder the run created, and what the run added to a folder that existed: no
// output is left and existing files keep their content. The run's summary goes to standard
// output before the renames, so that a summary that cannot be written (a closed pipe, a full
// disk) leaves no output either.

#include <functional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "optim/stopwatch.h"

#include "frontends/cli/interruption.h"

namespace sa::cli {

/// When `path` (given as `option`) is a .vtu or .vtk file, loads the plugin that writes it, or
/// throws InputError `OPTION PATH: cannot load libsa_vtk_io.so ...`: found with the output
/// checks, not after the solve. OutputPlan::check() calls it on its files.
void check_vtk_writer(const std::string& option, const std::string& path);

/// Flushes standard output; throws InputError `cannot write to standard output (WHY)` when it
/// fails (a full disk). On a closed pipe with SIGPIPE handled it does not return: the
/// interruption's cleanup ends the process by SIGPIPE (interruption.h).
void flush_standard_output();

class OutputPlan {
  public:
    /// `overwrite`: --force, existing files may be replaced.
    explicit OutputPlan(bool overwrite);
    /// Removes the outputs of an uncommitted run.
    ~OutputPlan();
    OutputPlan(const OutputPlan&) = delete;
    OutputPlan& operator=(const OutputPlan&) = delete;

    /// An input file, which no output may name. Empty paths are ignored.
    void input(const std::string& option, const std::string& path);
    /// An output file. Empty paths are ignored. A .node or .ele file brings its TetGen
    /// companion (the same name with the other extension), which the writer also writes.
    void file(const std::string& option, const std::string& path);
    /// An output folder (created when missing, with its parents). Without --force, none of the
    /// files named in `marks` may exist in it (they mark an earlier run). Empty paths are ignored.
    void folder(const std::string& option, const std::string& path,
                std::vector<std::string> marks = {});

    /// Throws InvalidArgumentError (two outputs with one path, an output naming an input) or
    /// InputError (a location that cannot be written, an existing file without --force), naming
    /// the option and the path.
    void check() const;

    /// Creates the folders; from here on what the run adds to them is removed on failure.
    void open_folders();

    /// The hidden name `path` is written under until commit().
    std::string staged(const std::string& path) const;

    /// Calls `write(staged(path))` under the output lock.
    template <class Write>
    void write(const std::string& path, Write&& write) {
        const auto lock = output_lock();
        write(staged(path));
    }

    /// Writes `summary` to standard output and flushes it, then renames every written file into
    /// place (under the output lock). Throws InputError `cannot write to standard output (WHY)`
    /// when the summary cannot be written (the outputs are removed then; a closed pipe ends the
    /// process by SIGPIPE after removing them, as interruption.h says), and when a rename fails,
    /// after removing the files renamed so far.
    void commit(const std::string& summary);

  private:
    struct Entry {
        std::string option, path;
    };
    struct Folder {
        std::string option, path;
        std::vector<std::string> marks;
        std::string created;             ///< the topmost folder open_folders() created, if any
        std::set<std::string> existing;  ///< entries before the run, when it existed
        bool opened = false;
    };
    /// Removes the staged files and what the run added to the folders (output lock held).
    void roll_back() noexcept;
    void remove_outputs() const;

    bool overwrite_;
    bool committed_ = false;
    std::vector<Entry> inputs_, files_;
    std::vector<Folder> folders_;
};

/// The picture a command draws beside its main output, the same in every command: `--png P`,
/// by default `--out` with .png, none with `--no-png`. Its path is planned with the other
/// outputs (checked before the solve); drawing it may fail (no OpenGL, no X server) without
/// costing the run anything else: the other outputs are written and one warning line says why.
/// `--max-time` bounds the whole command's wall-clock time: the default picture is not drawn
/// once the command has run for longer than that (a 3D picture takes a second or more, most of
/// it starting VTK's OpenGL context), and the warning says so; a picture asked for with `--png`
/// is drawn whatever the time.
///
///   const PictureOutput picture(a.png, a.no_png, a.out, a.max_time);  // throws unless P is .png
///   picture.plan(plan);                                    // before plan.check()
///   ... solve, write the other outputs ...
///   picture.draw(plan, [&](const std::string& path) { write_..._png(path, ...); });
///   summary << "wrote " << a.out << picture.wrote() << ...;
///   plan.commit(summary.str());
///   picture.warn(std::cerr);                               // after the summary
class PictureOutput {
  public:
    /// Throws InvalidArgumentError `--png P: expected a .png file` for another extension.
    /// `max_time_seconds` is the command's --max-time, counted from this construction.
    PictureOutput(const std::string& png, bool no_png, const std::string& out,
                  double max_time_seconds);

    /// The picture's path; "" with --no-png.
    const std::string& path() const { return path_; }
    /// Declares the picture on `plan` (nothing with --no-png).
    void plan(OutputPlan& plan) const;
    /// Calls `draw(staged path)` through plan.write(); an sa::Error it throws is kept for warn().
    void draw(OutputPlan& plan, const std::function<void(const std::string&)>& draw);
    /// ", PATH (T s)" once drawn; "" otherwise.
    std::string wrote() const;
    /// Writes `sa: warning: no picture PATH: WHY` when drawing failed.
    void warn(std::ostream& out) const;

  private:
    std::string path_, option_, drawn_, failure_;
    bool asked_;  ///< given with --png (drawn whatever the time)
    double max_time_seconds_;
    Stopwatch since_start_;
};

}  // namespace sa::cli
