#pragma once
// `sa polycube` (issue 21): a PolyCube map of a tetrahedral mesh. Prepared here: the arguments,
// their checks, and the steps before and after the solve. NOT registered in sa_main.cpp yet: the
// solve is a configuration of the Simplex Assembly engine (issue 20), wired when it lands:
//
//   const PolycubePlan plan = check_polycube_arguments(arguments);     // bad options: throws
//   const PreparedPolycube prepared = read_polycube_input(plan, logger);
//   Eigen::MatrixXd start = cube_cover_map(prepared.mesh, prepared.boundary,
//                                          prepared.charts).positions;
//   ... the engine: planarity and sliding terms, the 3D angle barriers, the conformal barrier
//       with plan.bound or the optimal-bound loop, within plan.max_time ...
//   const PolycubeVerification v = verify_polycube(prepared.layout(), positions,
//                                                  prepared.input_volume);
//   write_polycube_outputs(plan, prepared, positions, v, report);      // exit v.passed ? 0 : 1
//
//   sa polycube --mesh TETS [--labels FLAGS | --labels LABELS.txt --label-surface SURFACE.obj]
//               [--bound K | --optimal-bound] --out OUT.mesh [--vtu V.vtu] [--png P.png]
//               [--report R.json] [--max-time S] [--threads N] [--force] [--quiet]

#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

#include "frontends/polycube/polycube_preparation.h"

namespace sa::cli {

struct PolycubeArguments {
    std::string mesh, labels, label_surface, bound = "inf", out, vtu, png, report;
    double max_time = 0.0;  ///< seconds; 0 = no limit
    int threads = 0;
    bool optimal_bound = false, force = false, quiet = false;
};

/// Adds the `polycube` subcommand to `app`, filling `arguments` when parsed.
CLI::App* add_polycube_command(CLI::App& app, PolycubeArguments& arguments);

/// The checked arguments.
struct PolycubePlan {
    std::string mesh;
    PolycubeLabelInput labels;
    double bound = kInfinity;  ///< K on the conformal distortion (inf: none)
    bool optimal_bound = false;
    double max_time = kInfinity;
    int threads = 0;
    std::string out, rest, flags, vtu, png, report;  ///< rest and flags: beside out
    bool quiet = false;
};

/// Checks the arguments before anything is read or written: the mesh and label files exist,
/// --label-surface only with --labels, --bound a number > 1 or inf and not with --optimal-bound,
/// --out a .mesh (OUT.rest.mesh and OUT.flags go beside it), --vtu .vtu or .vtk, --png .png,
/// --report .json, every output distinct and, without --force, not existing, --max-time > 0,
/// --threads >= 0. Throws InvalidArgumentError or InputError naming the option or file.
PolycubePlan check_polycube_arguments(const PolycubeArguments& arguments);

/// Reads plan.mesh and prepares it with plan.labels (prepare_polycube()); warnings and progress
/// go to `logger`.
PreparedPolycube read_polycube_input(const PolycubePlan& plan, const Logger& logger);

/// Writes the map's files: OUT.mesh with OUT.rest.mesh and OUT.flags, and the --vtu, --png and
/// --report ones asked for. `report` receives the preparation and verification sections (under
/// "preparation" and "verification") before it is written; the caller adds the solve's.
void write_polycube_outputs(const PolycubePlan& plan, const PreparedPolycube& prepared,
                            const Eigen::MatrixXd& positions,
                            const PolycubeVerification& verification, nlohmann::json report);

}  // namespace sa::cli
