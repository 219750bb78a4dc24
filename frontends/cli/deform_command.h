#pragma once
// `sa deform` (issue 22): a pose from the rest shape and the handles' targets alone, by an ARAP
// start and Simplex Assembly bounding the conformal and the volumetric distortion together
// (frontends/deform/deform_solve.h). Its arguments, the checks of its options, files and output
// locations (all before any solve), and the run.
//
//   sa deform --rest FILE [--handles FILE] --targets FILE
//             [--optimal-bound | --bound-conformal K1 --bound-volumetric K2] --out FILE
//             [--png FILE | --no-png] [--report FILE] [--initialization NAME] [--mu M] ...

#include <string>
#include <vector>

#include "frontends/cli/output_plan.h"
#include "frontends/deform/deform_options.h"
#include "frontends/deform/handle_targets.h"
#include "geometry/mesh/simplicial_mesh.h"

namespace sa::cli {

struct DeformArguments {
    std::string rest, handles, targets, out, png, report;
    std::string bound_conformal = "inf", bound_volumetric = "inf", initialization = "rotation";
    bool optimal_bound = false;
    int optimal_bound_rounds = 10;
    double mu = 1000.0;
    int start_iterations = 1000;
    double start_tolerance = 1e-9;
    double max_time = kInfinity;
    int threads = 0;
    bool force = false, quiet = false, no_png = false;
};

/// Adds the subcommand to `app`; `arguments` is filled when it is parsed.
/// The options, parsed and validated. Throws InvalidArgumentError naming the option and its
/// value (a bound that is not a number > 1 or inf, --optimal-bound with a bound, ...).
DeformOptions deform_options(const DeformArguments& arguments);

/// What the input files hold, checked.
struct DeformInput {
    SimplicialMesh mesh;
    HandleTargets handle_targets;
    std::vector<std::string> warnings;  ///< notes of the mesh reader
};

/// Declares the inputs and outputs on `plan` and checks them (OutputPlan::check(): two outputs
/// with one path, an output naming an input, an unwritable location, an existing file without
/// --force), and the extensions of --png and --report. Before anything is read. Returns the
/// picture (by default --out with .png), to draw after the solve.
PictureOutput plan_deform_files(const DeformArguments& arguments, OutputPlan& plan);

/// Reads and checks the rest mesh (planar triangles or tetrahedra, validated), the handles and
/// their targets (frontends/deform/handle_targets.h), and refuses an --out format that cannot
/// hold the mesh; before any solve, so that bad input costs nothing and writes nothing. Throws
/// InputError or InvalidArgumentError, one line naming the file, line, element or option.
DeformInput read_deform_input(const DeformArguments& arguments);

/// The command: exit 0 when the pose is verified (and within the bounds), 1 when it is written
/// but not verified; bad input throws before anything is written.
int run_deform_command(const DeformArguments& arguments);

}  // namespace sa::cli
