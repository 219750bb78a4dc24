#include "frontends/cli/deform_command.h"

#include "frontends/cli/cli_support.h"
#include "geometry/io/mesh_file.h"
#include "optim/errors.h"

namespace sa::cli {

namespace {

/// "inf" or a number > 1, for the option `name`.
double parse_bound_option(const std::string& name, const std::string& text) {
    if (text == "inf" || text == "infinity" || text == "none") return kInfinity;
    try {
        std::size_t used = 0;
        const double k = std::stod(text, &used);
        if (used == text.size() && k > 1.0 && std::isfinite(k)) return k;
    } catch (const std::exception&) {
    }
    throw InvalidArgumentError(name + " " + text + ": expected a number > 1 or 'inf'");
}

}  // namespace

CLI::App* add_deform_command(CLI::App& app, DeformArguments& a) {
    CLI::App* deform = app.add_subcommand(
        "deform",
        "Pose a tet mesh (or a planar triangle mesh) by its handles: an ARAP start, then Simplex "
        "Assembly bounding the conformal and the volumetric distortion (section 5.4)");
    deform->add_option("--rest", a.rest, "rest mesh (.mesh .node/.ele .vtk .vtu .obj .off ...)")
        ->required();
    deform->add_option("--handles", a.handles,
                       "handle vertices, 0-based (without it, --targets lists `index x y z` rows)");
    deform
        ->add_option("--targets", a.targets,
                     "where the handles go: a mesh file or rows `x y z` (one per vertex or one "
                     "per handle), or rows `index x y z`")
        ->required();
    deform->add_flag("--optimal-bound", a.optimal_bound,
                     "find both bounds: rounds that take the largest conformal and volumetric "
                     "distortion reached as the next bounds (section 5.1)");
    deform->add_option("--optimal-bound-rounds", a.optimal_bound_rounds, "rounds at most")
        ->capture_default_str();
    deform
        ->add_option("--bound-conformal", a.bound_conformal,
                     "bound on the conformal distortion d^c, a number > 1 or inf")
        ->capture_default_str();
    deform
        ->add_option("--bound-volumetric", a.bound_volumetric,
                     "bound on the volumetric distortion (det A + 1/det A)/2, > 1 or inf")
        ->capture_default_str();
    deform->add_option("--mu", a.mu, "weight of E_m = sum |A - A0|^2 to the ARAP start")
        ->capture_default_str();
    deform
        ->add_option("--initialization", a.initialization,
                     "projection of the start's linear parts: rotation (default), similarity, "
                     "identity, random or bounded:K")
        ->capture_default_str();
    deform->add_option("--start-iterations", a.start_iterations, "ARAP iterations at most")
        ->capture_default_str();
    deform
        ->add_option("--start-tolerance", a.start_tolerance,
                     "ARAP stops when no vertex moves more than this times the diagonal")
        ->capture_default_str();
    deform->add_option("--out", a.out, "the posed mesh: .vtu .vtk .mesh .node (.obj .off in 2D)")
        ->required();
    deform->add_option("--png", a.png,
                       "a picture of the pose: the surface coloured by isometric distortion, "
                       "inverted simplices in red");
    deform->add_option("--report", a.report, "JSON report");
    deform->add_option("--max-time", a.max_time, "wall-clock limit in seconds")
        ->capture_default_str();
    deform->add_option("--threads", a.threads, "worker threads, 0 = all cores")
        ->capture_default_str();
    deform->add_flag("--force", a.force, "overwrite existing output files");
    deform->add_flag("--quiet", a.quiet, "no progress rows on stderr");
    return deform;
}

DeformOptions deform_options(const DeformArguments& a) {
    DeformOptions options;
    options.conformal_bound = parse_bound_option("--bound-conformal", a.bound_conformal);
    options.volumetric_bound = parse_bound_option("--bound-volumetric", a.bound_volumetric);
    options.optimal_bound = a.optimal_bound;
    if (a.optimal_bound &&
        (std::isfinite(options.conformal_bound) || std::isfinite(options.volumetric_bound))) {
        throw InvalidArgumentError(
            "--optimal-bound finds both bounds: drop --bound-conformal and --bound-volumetric");
    }
    if (a.optimal_bound_rounds < 1) {
        throw InvalidArgumentError("--optimal-bound-rounds " +
                                   std::to_string(a.optimal_bound_rounds) + ": expected >= 1");
    }
    options.optimal_bound_rounds = a.optimal_bound_rounds;
    if (!(a.mu >= 0.0 && std::isfinite(a.mu)))
        throw InvalidArgumentError("--mu " + std::to_string(a.mu) + ": expected a number >= 0");
    options.mu = a.mu;
    options.initialization = parse_initialization(a.initialization);
    if (a.start_iterations < 0) {
        throw InvalidArgumentError("--start-iterations " + std::to_string(a.start_iterations) +
                                   ": expected >= 0");
    }
    options.start.max_iterations = a.start_iterations;
    if (!(a.start_tolerance >= 0.0)) {
        throw InvalidArgumentError("--start-tolerance " + std::to_string(a.start_tolerance) +
                                   ": expected >= 0");
    }
    options.start.tolerance = a.start_tolerance;
    if (!(a.max_time > 0.0))
        throw InvalidArgumentError("--max-time " + std::to_string(a.max_time) + ": expected > 0");
    options.max_time_seconds = a.max_time;
    options.start.max_time_seconds = a.max_time;
    if (a.threads < 0)
        throw InvalidArgumentError("--threads " + std::to_string(a.threads) + ": expected >= 0");
    options.num_threads = a.threads;
    options.validate();
    return options;
}

DeformInput read_deform_input(const DeformArguments& a) {
    // Outputs first: a name that cannot be written should not cost reading a large mesh.
    for (const std::string* path : {&a.out, &a.png, &a.report}) {
        if (!path->empty()) check_writable(*path, a.force);
    }
    if (!a.png.empty() && extension(a.png) != ".png")
        throw InvalidArgumentError("--png " + a.png + ": expected a .png file name");
    if (!a.report.empty() && extension(a.report) != ".json")
        throw InvalidArgumentError("--report " + a.report + ": expected a .json file name");

    MeshFile rest = read_mesh_file(a.rest);
    DeformInput input;
    input.warnings = std::move(rest.warnings);
    input.mesh = std::move(rest.mesh);
    validate_mesh(input.mesh, a.rest);
    const int d = input.mesh.simplex_dimension();
    if (input.mesh.ambient_dimension() != d) {
        throw InputError(a.rest +
                         ": triangles in space; deformation poses tetrahedra, or triangles in "
                         "the plane");
    }
    check_output_format(a.out, d);
    input.handle_targets = read_handle_targets(a.handles, a.targets, input.mesh.num_vertices(), d);
    return input;
}

}  // namespace sa::cli
