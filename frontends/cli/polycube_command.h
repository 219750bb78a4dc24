#pragma once
// `sa polycube` (issue 21): a PolyCube map of a tetrahedral mesh. The arguments, their checks,
// and the steps before and after the solve (frontends/polycube/polycube_solve.h: a configuration
// of the Simplex Assembly driver and engine):
//
//   const PolycubePlan plan = check_polycube_arguments(arguments);     // bad options: throws
//   OutputPlan outputs(arguments.force);
//   PictureOutput picture = plan_polycube_files(arguments, plan, outputs);  // bad locations
//   const PreparedPolycube prepared = read_polycube_input(plan, logger);
//   const PolycubeSolve solve = solve_polycube(prepared, options, logger);
//   write_polycube_outputs(plan, prepared, solve.positions, solve.verification, report, outputs);
//   outputs.commit(summary);
//   // exit 0 only when solve.success (the driver's and verify_polycube()'s checks)
//
//   sa polycube --mesh TETS [--labels FLAGS | --labels LABELS.txt --label-surface SURFACE.obj]
//               [--bound K | --optimal-bound] --out OUT.mesh [--vtu V.vtu]
//               [--png P.png | --no-png]
//               [--report R.json] [--max-time S] [--threads N] [--force] [--quiet]

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

#include "frontends/cli/output_plan.h"
#include "frontends/polycube/polycube_preparation.h"

namespace sa::cli {

struct PolycubeArguments {
    std::string mesh, labels, label_surface, bound = "inf", out, vtu, png, report;
    double max_time = kInfinity;  ///< seconds, > 0; inf: no limit
    int threads = 0;
    bool optimal_bound = false, force = false, quiet = false, no_png = false;
    bool keep_orientation = false;
    bool keep_turning_boundaries = false;
};

/// Adds the `polycube` subcommand to `app`, filling `arguments` when parsed.
/// The checked arguments.
struct PolycubePlan {
    std::string mesh;
    PolycubeLabelInput labels;
    double bound = kInfinity;  ///< K on the conformal distortion (inf: none)
    bool optimal_bound = false;
    double max_time = kInfinity;
    int threads = 0;
    std::string out, rest, flags, vtu, png, report;  ///< rest, flags and png: beside out
    bool quiet = false;
};

/// Checks the options before anything is read or written: the mesh and label files exist,
/// --label-surface only with --labels, --bound a number > 1 or inf and not with --optimal-bound,
/// --out a .mesh (OUT.rest.mesh and OUT.flags go beside it), --vtu .vtu or .vtk, --png .png
/// (by default OUT.png; none with --no-png), --report .json, --max-time > 0, --threads >= 0.
/// Throws InvalidArgumentError or InputError naming the option or file.
PolycubePlan check_polycube_arguments(const PolycubeArguments& arguments);

/// Declares the inputs and every output of `plan` on `outputs` and checks them (OutputPlan::check:
/// distinct, none an input, writable, not existing without --force, the VTK writer loadable);
/// returns the picture to draw.
PictureOutput plan_polycube_files(const PolycubeArguments& arguments, const PolycubePlan& plan,
                                  OutputPlan& outputs);

/// Reads plan.mesh and prepares it with plan.labels (prepare_polycube()); warnings and progress
/// go to `logger`.
PreparedPolycube read_polycube_input(const PolycubePlan& plan, const Logger& logger);

/// Writes the map's files: OUT.mesh with OUT.rest.mesh and OUT.flags, and the --vtu, --png and
/// --report ones asked for. `report` receives the preparation and verification sections (under
/// "preparation" and "verification") before it is written; the caller adds the solve's.
/// Every file is written under its staged name on `outputs` (output_plan.h); the caller commits.
void write_polycube_outputs(const PolycubePlan& plan, const PreparedPolycube& prepared,
                            const Eigen::MatrixXd& positions,
                            const PolycubeVerification& verification, nlohmann::json report,
                            OutputPlan& outputs);

/// Runs `sa polycube`: returns the exit status (cli_support.h), throws on bad input.
int run_polycube_command(const PolycubeArguments& arguments);

}  // namespace sa::cli
