#include "frontends/cli/command_options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace sa::cli {
namespace {

// Range checks of the `sa` command's numeric options, as CLI11 validators: they run on the text
// the user typed, before it is converted, so that a bad value is reported under the option's own
// name ("--max-iterations: must be an integer >= 1, found '0'"), never under the name of the
// library field it ends up in. NaN is never in range; "inf" only where a check allows it.
// Below them, the options several commands share, defined once with one wording and one check.

std::string format(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

/// The value of `text` when all of it is a number, NaN otherwise.
double parse(const std::string& text) {
    if (text.empty()) return std::nan("");
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return std::nan("");
    return value;
}

CLI::Validator number_check(double low, bool strict, bool allow_inf) {
    const std::string rule = std::string(allow_inf ? "a number or inf " : "a finite number ") +
                             (strict ? "> " : ">= ") + format(low);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            const double value = parse(text);
            const bool finite_enough =
                allow_inf ? value == INFINITY || std::isfinite(value) : std::isfinite(value);
            if (finite_enough && (strict ? value > low : value >= low)) return {};
            return "must be " + rule + ", found '" + text + "'";
        },
        rule);
}

/// A finite number >= `low` (> `low` when `strict`).
CLI::Validator number_at_least(double low, bool strict = false) {
    return number_check(low, strict, false);
}

/// A number >= `low` (> `low` when `strict`), or inf.
CLI::Validator number_or_inf_at_least(double low, bool strict = false) {
    return number_check(low, strict, true);
}

/// An integer (digits, an optional sign) >= `low`.
CLI::Validator integer_at_least(long long low) {
    const std::string rule = "an integer >= " + std::to_string(low);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            std::size_t i = text.size() > 0 && (text[0] == '-' || text[0] == '+') ? 1 : 0;
            bool digits = i < text.size();
            for (; i < text.size(); ++i) digits = digits && text[i] >= '0' && text[i] <= '9';
            if (digits) {
                errno = 0;
                const long long value = std::strtoll(text.c_str(), nullptr, 10);
                if (errno == 0 && value >= low) return {};
            }
            return "must be " + rule + ", found '" + text + "'";
        },
        rule);
}

/// A seed: an integer from 0 to 2^64 - 1 (digits only).
CLI::Validator seed_value() {
    const std::string rule = "an integer from 0 to 18446744073709551615";
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            bool digits = !text.empty();
            for (const char c : text) digits = digits && c >= '0' && c <= '9';
            if (digits) {
                errno = 0;
                std::strtoull(text.c_str(), nullptr, 10);
                if (errno == 0) return {};
            }
            return "must be " + rule + ", found '" + text + "'";
        },
        rule);
}

/// --threads N: worker threads, 0 = all cores (an integer >= 0).
void add_threads_option(CLI::App& command, int& threads) {
    command.add_option("--threads", threads, "worker threads, 0 = all cores")
        ->check(integer_at_least(0))
        ->capture_default_str();
}

/// --max-iterations N (an integer >= 1), described as `description`.
void add_max_iterations_option(CLI::App& command, int& max_iterations,
                               const std::string& description) {
    command.add_option("--max-iterations", max_iterations, description)
        ->check(integer_at_least(1))
        ->capture_default_str();
}

/// --max-time S (a number or inf > 0): "wall-clock limit in seconds on SCOPE; the RESULT reached
/// by then is verified, written and reported as it is".
void add_max_time_option(CLI::App& command, double& max_time, const std::string& scope,
                         const std::string& result = "map") {
    command
        .add_option("--max-time", max_time,
                    "wall-clock limit in seconds on " + scope + "; the " + result +
                        " reached by then is verified, written and reported as it is")
        ->check(number_or_inf_at_least(0.0, true))
        ->capture_default_str();
}

/// --png FILE and --no-png, for PictureOutput (output_plan.h): `what` is the picture, "(default:
/// --out with .png)" is added.
void add_picture_options(CLI::App& command, std::string& png, bool& no_png,
                         const std::string& what) {
    command.add_option("--png", png, what + " (default: --out with .png)");
    command.add_flag("--no-png", no_png, "do not draw the picture");
}

/// --force (described as `force_description`) and --quiet (no progress rows on stderr).
void add_force_and_quiet(CLI::App& command, bool& force, bool& quiet,
                         const std::string& force_description = "overwrite existing output files") {
    command.add_flag("--force", force, force_description);
    command.add_flag("--quiet", quiet, "no progress rows on stderr");
}

}  // namespace

CLI::App* add_map_command(CLI::App& app, MapArguments& a) {
    CLI::App* map = app.add_subcommand(
        "map", "Inversion-free map of a 2D/3D mesh with handles (Simplex Assembly)");
    map->add_option(
           "--rest", a.rest,
           "rest mesh (.obj .off .ply .stl .vtk .vtu .mesh .node/.ele) or a plain-text problem "
           "file carrying its initial map and handles")
        ->required();
    map->add_option(
        "--init", a.init,
        "initial map: a mesh file with the same vertices, result records (resV) or a problem file");
    map->add_option("--handles", a.handles,
                    "handle vertices, 0-based indices (default: those of the problem file)");
    map->add_option(
        "--targets", a.targets,
        "positions whose rows at the handles are their targets (default: the initial map); "
        "without --init the initial map is the rest shape with the handles moved there");
    map->add_option("--distortion", a.distortion,
                    "distortion in the barrier: conformal, volumetric or isometric")
        ->capture_default_str();
    map->add_option("--bound", a.bound, "bound K on that distortion, a number > 1 or inf")
        ->capture_default_str();
    map->add_option(
           "--energy", a.energy,
           "mapping energy E_m: none or a distortion (difference = |A - A0|^2 to the initial map)")
        ->capture_default_str();
    map->add_option("--mu", a.mu, "weight of E_m")
        ->check(number_at_least(0.0))
        ->capture_default_str();
    map->add_option("--s", a.s, "s in the barrier's exp(s d)")
        ->check(number_at_least(0.0, true))
        ->capture_default_str();
    map->add_option("--lambda-max", a.lambda_max,
                    "largest weight of the assembly terms (section 4.4)")
        ->check(number_at_least(SimplexAssemblyOptions{}.lambda_min))
        ->capture_default_str();
    map->add_option("--variant", a.variant,
                    "r (reduced, default), f (full) or v (vertex variables)")
        ->capture_default_str();
    map->add_option(
        "--initialization", a.initialization,
        "initial linear parts: similarity, rotation, identity, random or bounded:K (the "
        "closest with sigma_max/sigma_min <= K; default: similarity for conformal, rotation "
        "otherwise)");
    map->add_option("--seed", a.seed, "seed of --initialization random")
        ->check(seed_value())
        ->capture_default_str();
    add_max_iterations_option(*map, a.max_iterations, "Newton iterations at most");
    add_max_time_option(*map, a.max_time, "the solve (checked after each iteration)");
    add_threads_option(*map, a.threads);
    map->add_option(
           "--out", a.out,
           "output map: .vtu .vtk .obj .off .mesh .node; other names get result records (resV)")
        ->required();
    add_picture_options(*map, a.png, a.no_png,
                        "a picture of the map: 2D, the initial map and the result side by side "
                        "coloured by conformal distortion; 3D, the result's surface coloured by "
                        "isometric distortion; inverted simplices in red");
    map->add_option("--report", a.report, "JSON report: options, iterations, times, verification");
    map->add_option("--record", a.record,
                    "folder for a ParaView time series of the assembly (assembly.pvd)");
    map->add_option("--mode", a.mode,
                    "auto (submeshes for large meshes with few bad simplices or a fixed boundary), "
                    "full, submesh, or descent (from a start without foldovers: Newton on the "
                    "vertex positions alone)")
        ->capture_default_str();
    map->add_option("--rings", a.rings, "submesh mode: rings around the bad simplices (m)")
        ->check(integer_at_least(1))
        ->capture_default_str();
    map->add_option("--max-rings", a.max_rings,
                    "submesh mode: most rings a failing region grows to (m_max)")
        ->check(integer_at_least(1))
        ->capture_default_str();
    map->add_option("--max-rounds", a.max_rounds, "submesh mode: rounds after the first (l_max)")
        ->check(integer_at_least(0))
        ->capture_default_str();
    map->add_option("--linear-solver", a.linear_solver,
                    "auto (Eigen LDL^T below 2e6 factorization flops by CHOLMOD's count, CHOLMOD "
                    "supernodal above), "
                    "cholmod-supernodal, cholmod-simplicial or eigen-ldlt")
        ->capture_default_str();
    map->add_option("--projection", a.projection,
                    "per-simplex Hessian projection: clamp (eigenvalues to 1e-8), abs, shift (the "
                    "paper's) or none")
        ->capture_default_str();
    map->add_option("--translation-shift", a.translation_shift,
                    "Hessian shift on r-SA translations, times lambda (the paper's is 1e-6)")
        ->check(number_at_least(0.0))
        ->capture_default_str();
    map->add_flag(
        "--no-vertex-stage", a.no_vertex_stage,
        "keep the paper's schedule to its own termination at lambda_max instead of finishing in "
        "vertex variables once assembled");
    map->add_flag(
        "--until-valid", a.until_valid,
        "stop at the first map verified inversion-free (untangling only: no distortion stage)");
    add_force_and_quiet(*map, a.force, a.quiet);
    return map;
}

CLI::App* add_demo_command(CLI::App& app, DemoArguments& a) {
    CLI::App* demo = app.add_subcommand(
        "demo", "Figure 1 in miniature: a folded harmonic map of a square onto a star, repaired");
    demo->add_option("--out-dir", a.out_dir, "folder for the .vtu files and their pictures (.png)")
        ->capture_default_str();
    demo->add_option("--size", a.size, "grid cells per side")
        ->check(CLI::Range(4, 400))
        ->capture_default_str();
    add_threads_option(*demo, a.threads);
    demo->add_option("--initialization", a.initialization,
                     "the disassembly's projection (as in sa map): similarity (default), "
                     "rotation, identity, random or bounded:K (the paper's Figure 6)");
    demo->add_flag("--no-png", a.no_png, "do not draw the pictures");
    add_force_and_quiet(*demo, a.force, a.quiet, "overwrite existing files in the folder");
    return demo;
}

CLI::App* add_param_command(CLI::App& app, ParamArguments& a) {
    CLI::App* param = app.add_subcommand(
        "param", "Planar parameterization of a disk-topology surface (Simplex Assembly)");
    param
        ->add_option("--mesh", a.mesh,
                     "the surface: .obj .off .ply .stl .vtk .vtu .mesh (a disk: one boundary loop)")
        ->required();
    param
        ->add_option(
            "--init", a.init,
            "initial map: lscm (free boundary), tutte (mean-value weights, circle), tutte-uniform, "
            "harmonic (cotangent, circle), or a file (an OBJ's vt, or positions)")
        ->capture_default_str();
    param->add_option("--distortion", a.distortion, "conformal or isometric")
        ->capture_default_str();
    param->add_option("--bound", a.bound, "bound K on that distortion, a number > 1 or inf")
        ->capture_default_str();
    param->add_flag(
        "--optimal-bound", a.optimal_bound,
        "rounds that take the largest distortion as the next bound until it stops improving (5.1)");
    param
        ->add_option("--optimal-bound-rounds", a.optimal_bound_rounds,
                     "most rounds of --optimal-bound (default 20)")
        ->check(integer_at_least(1))
        ->needs("--optimal-bound");
    param
        ->add_option("--optimal-bound-tolerance", a.optimal_bound_tolerance,
                     "--optimal-bound stops when a round lowers the largest distortion K by less "
                     "than this share of K - 1")
        ->check(CLI::Range(0.0, 0.5))
        ->capture_default_str()
        ->needs("--optimal-bound");
    param
        ->add_option("--energy", a.energy,
                     "E_m: difference (area-weighted |A - A0|^2 to the initial map), lscm, or none")
        ->capture_default_str();
    param->add_option("--mu", a.mu, "weight of E_m")
        ->check(number_at_least(0.0))
        ->capture_default_str();
    param->add_flag(
        "--free-boundary-injective", a.free_boundary_injective,
        "keep every boundary angle sum below 2 pi (the barrier E_theta of 5.1; full mode)");
    param->add_flag("--no-fallback", a.no_fallback,
                    "keep the requested start's result even when it does not verify (no restart "
                    "from a Tutte map)");
    param->add_option("--mode", a.mode, "auto, full, submesh or descent (as sa map's)")
        ->capture_default_str();
    add_threads_option(*param, a.threads);
    add_max_iterations_option(*param, a.max_iterations, "Newton iterations at most, per stage");
    add_max_time_option(
        *param, a.max_time,
        "the whole solve (every stage, fallback and bound round takes what is left)");
    param
        ->add_option("--out", a.out,
                     "the surface with its map: .obj (vt per vertex) or .vtu/.vtk (point data uv)")
        ->required();
    param->add_option("--layout", a.layout, "the UV layout as .vtu/.vtk, with per-face distortion");
    add_picture_options(
        *param, a.png, a.no_png,
        "a picture of the UV layout coloured by conformal distortion, inverted triangles in red");
    param->add_option("--report", a.report, "JSON report");
    add_force_and_quiet(*param, a.force, a.quiet);
    return param;
}

CLI::App* add_subdivide_command(CLI::App& app, SubdivideArguments& a) {
    CLI::App* sub =
        app.add_subcommand("subdivide", "Loop subdivision of a triangle mesh (OpenMesh)");
    sub->add_option("--mesh", a.mesh, "triangle mesh")->required();
    sub->add_option("--levels", a.levels, "each level multiplies the triangles by 4")
        ->check(CLI::Range(0, 8))
        ->capture_default_str();
    sub->add_option("--out", a.out, "output mesh (.obj .off .vtu .vtk .mesh)")->required();
    sub->add_flag("--force", a.force, "overwrite an existing output");
    return sub;
}

CLI::App* add_seamless_command(CLI::App& app, SeamlessArguments& a) {
    CLI::App* cmd = app.add_subcommand(
        "seamless",
        "Seamless parameterization from a frame field made integrable by Simplex Assembly");
    cmd->add_option("--mesh", a.mesh, "the surface: .obj .off .ply .stl .vtk .vtu (triangles)")
        ->required();
    cmd->add_option("--field", a.field,
                    "per-face frame or cross field: libigl .dmat (ASCII or binary) or "
                    ".crossfield, or Directional .rawfield (N = 4); faces it leaves free are "
                    "filled by the smoothest cross field. "
                    "Without it (and without --constraints), the smoothest cross field");
    cmd->add_option("--constraints", a.constraints,
                    "libigl's pair B.dmat BC.dmat: constrained faces and their vectors; the "
                    "smoothest cross field through them")
        ->expected(2);
    cmd->add_option("--scale", a.scale,
                    "H: mesh length per unit of (u, v), one checkerboard square (default: 1/30 of "
                    "the bounding-box diagonal)")
        ->check(number_at_least(0.0, true));
    cmd->add_option("--mu", a.mu, "weight of E_m = |phi' - phi|^2")
        ->check(number_at_least(0.0))
        ->capture_default_str();
    add_threads_option(*cmd, a.threads);
    add_max_iterations_option(*cmd, a.max_iterations, "Newton iterations at most");
    add_max_time_option(
        *cmd, a.max_time,
        "the whole run (the field's assembly and its local repairs take what is left)");
    cmd->add_option("--out", a.out, "the surface with per-corner texture coordinates (.obj)")
        ->required();
    cmd->add_option("--vtu", a.vtu,
                    "the cut surface for ParaView: uv, fields, curls, distortion (default: --out "
                    "with .vtu)");
    cmd->add_flag("--no-vtu", a.no_vtu, "do not write the .vtu");
    add_picture_options(*cmd, a.png, a.no_png,
                        "the surface textured with a checkerboard of (u, v), rendered with VTK");
    cmd->add_option("--report", a.report, "JSON report");
    add_force_and_quiet(*cmd, a.force, a.quiet);
    return cmd;
}

CLI::App* add_polycube_command(CLI::App& app, PolycubeArguments& a) {
    CLI::App* polycube = app.add_subcommand(
        "polycube", "PolyCube map of a tetrahedral mesh (Simplex Assembly, section 5.3)");
    polycube->add_option("--mesh", a.mesh, "the tetrahedral mesh: .mesh .vtk .vtu .node/.ele")
        ->required();
    polycube->add_option(
        "--labels", a.labels,
        "the boundary's labels: one per tet facet (.flags, label / 2 = axis; the side is taken "
        "from the geometry), or one per triangle of --label-surface; computed when absent");
    polycube->add_option("--label-surface", a.label_surface,
                         "the boundary surface (.obj) that per-triangle --labels refer to");
    polycube->add_flag("--keep-orientation", a.keep_orientation,
                       "computed labels in the input's own axes (by default the mesh is "
                       "labelled turned so that its boundary faces the axes best)");
    polycube->add_flag("--keep-turning-boundaries", a.keep_turning_boundaries,
                       "computed labels whose chart boundaries turn back along their PolyCube "
                       "edge are kept as they are (by default patches are relabelled to remove "
                       "the reversals)");
    polycube->add_option("--bound", a.bound, "bound K on the conformal distortion, > 1 or inf")
        ->capture_default_str();
    polycube->add_flag("--optimal-bound", a.optimal_bound,
                       "rounds that take the largest distortion as the next bound (5.1)");
    polycube
        ->add_option("--out", a.out,
                     "the mapped mesh (.mesh); OUT.rest.mesh and OUT.flags are written beside it")
        ->required();
    polycube->add_option("--vtu", a.vtu, "the map with per-tet distortion and facet labels");
    add_picture_options(*polycube, a.png, a.no_png,
                        "a picture of the PolyCube coloured by conformal distortion");
    polycube->add_option("--report", a.report, "JSON report");
    add_max_time_option(*polycube, a.max_time, "the solve (every bound round takes what is left)");
    add_threads_option(*polycube, a.threads);
    add_force_and_quiet(*polycube, a.force, a.quiet);
    return polycube;
}

CLI::App* add_hex_command(CLI::App& app, HexArguments& a) {
    CLI::App* hex =
        app.add_subcommand("hex", "hexahedral mesh of a tetrahedral mesh through its PolyCube map");
    PolycubeArguments& p = a.polycube;
    hex->add_option("--mesh", p.mesh, "the tetrahedral mesh: .mesh .vtk .vtu .node/.ele")
        ->required();
    hex->add_option("--labels", p.labels,
                    "the boundary's labels, as for `sa polycube`; computed when absent");
    hex->add_option("--label-surface", p.label_surface,
                    "the boundary surface (.obj) that per-triangle --labels refer to");
    hex->add_flag("--keep-orientation", p.keep_orientation,
                  "computed labels in the input's own axes (as for `sa polycube`)");
    hex->add_option("--hexes", a.hexes,
                    "the number of hexes aimed at (default " + std::to_string(kDefaultHexes) +
                        ": a first look; the grid follows the PolyCube, so the count is near)");
    hex->add_option("--hex-size", a.hex_size,
                    "the hexes' edge length in the input's units, instead of --hexes");
    hex->add_option("--padding", a.padding,
                    "depth of the layer of hexes added along the boundary when a hex corner "
                    "there is inverted or flat, a fraction of its edge length; 0: never")
        ->capture_default_str();
    hex->add_option("--bound", p.bound,
                    "bound K on the PolyCube's conformal distortion, > 1 or inf")
        ->capture_default_str();
    hex->add_option("--out", a.out, "the hex mesh (.mesh, Medit Hexahedra)")->required();
    hex->add_option("--polycube", a.polycube_out,
                    "the PolyCube on the grid (.mesh, grid units), with P.rest.mesh and P.flags");
    hex->add_option("--vtu", a.vtu, "the hex mesh with per-hex scaled Jacobian (.vtu or .vtk)");
    add_picture_options(*hex, a.png, a.no_png,
                        "the hex mesh cut in half, coloured by scaled Jacobian");
    hex->add_option("--report", a.report, "JSON report");
    add_max_time_option(*hex, p.max_time, "both PolyCube solves");
    add_threads_option(*hex, p.threads);
    add_force_and_quiet(*hex, p.force, p.quiet);
    return hex;
}

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
    add_picture_options(
        *deform, a.png, a.no_png,
        "a picture of the pose: the surface coloured by isometric distortion, inverted simplices "
        "in red");
    deform->add_option("--report", a.report, "JSON report");
    add_max_time_option(*deform, a.max_time,
                        "the whole solve (the ARAP start and Simplex Assembly take what is left)",
                        "pose");
    add_threads_option(*deform, a.threads);
    add_force_and_quiet(*deform, a.force, a.quiet);
    return deform;
}

namespace {

template <class Arguments>
void parse_words(CLI::App* (*add)(CLI::App&, Arguments&), std::vector<std::string> words,
                 Arguments& arguments) {
    CLI::App app;
    CLI::App* command = add(app, arguments);
    words.insert(words.begin(), command->get_name());
    std::reverse(words.begin(), words.end());  // CLI11 takes them last first
    try {
        app.parse(words);
    } catch (const CLI::ParseError& e) {
        throw CommandLineError(e.what());
    }
}

}  // namespace

void parse_command_line(const std::vector<std::string>& words, MapArguments& arguments) {
    parse_words(add_map_command, words, arguments);
}
void parse_command_line(const std::vector<std::string>& words, ParamArguments& arguments) {
    parse_words(add_param_command, words, arguments);
}
void parse_command_line(const std::vector<std::string>& words, SeamlessArguments& arguments) {
    parse_words(add_seamless_command, words, arguments);
}
void parse_command_line(const std::vector<std::string>& words, PolycubeArguments& arguments) {
    parse_words(add_polycube_command, words, arguments);
}
void parse_command_line(const std::vector<std::string>& words, HexArguments& arguments) {
    parse_words(add_hex_command, words, arguments);
}
void parse_command_line(const std::vector<std::string>& words, DeformArguments& arguments) {
    parse_words(add_deform_command, words, arguments);
}

}  // namespace sa::cli
