// The start of deformation posing alone (issue 22, before the solve): the ARAP deformation of a
// rest shape with its handles at their targets (frontends/deform/deform_start.h), on files or on
// the generated bar of the paper's Figure 16. Prints one JSON line: the case, its size, the
// start's inverted and degenerate simplices, its distortion (max and volume-weighted mean, the
// rules of geometry/quality/map_quality.h), the iterations and why they stopped, the time, and how
// many inverted simplices show on the boundary surface (have a boundary facet).
//
//   bench_deform_start --rest R --targets T [--handles H] [--name NAME]
//   bench_deform_start --bar bend|twist|translate
//   ... [--png FILE] [--start-iterations N] [--anderson M] [--verbose] [--start-tolerance E]
//   [--threads N] [--rest-start]
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "frontends/deform/deform_start.h"
#include "frontends/output/pose_picture.h"
#include "geometry/io/mesh_file.h"
#include "geometry/mesh/mesh_topology.h"
#include "optim/errors.h"
#include "optim/stopwatch.h"
#include "tests/fixtures/bar_deformation.h"

int main(int argc, char** argv) {
    CLI::App app{"The ARAP start of deformation posing, measured"};
    std::string rest, handles, targets, bar, name, png;
    int iterations = 1000, threads = 0, anderson = sa::ArapOptions{}.anderson_history;
    bool verbose = false, rest_start = false;
    double tolerance = 1e-9;
    app.add_option("--rest", rest, "rest mesh");
    app.add_option("--handles", handles, "handle list");
    app.add_option("--targets", targets, "targets (frontends/deform/handle_targets.h)");
    app.add_option("--bar", bar, "a generated Figure 16 case: bend, twist or translate");
    app.add_option("--name", name, "the case's name in the output");
    app.add_option("--start-iterations", iterations)->capture_default_str();
    app.add_option("--start-tolerance", tolerance)->capture_default_str();
    app.add_option("--threads", threads, "0 = all cores")->capture_default_str();
    app.add_option("--anderson", anderson, "Anderson history (0 = plain iterations)")
        ->capture_default_str();
    app.add_option("--png", png, "a picture of the start (frontends/output/pose_picture.h)");
    app.add_flag("--verbose", verbose, "progress rows on stderr");
    app.add_flag("--rest-start", rest_start,
                 "start from the rest shape with the handles moved, not from the handle rotations");
    CLI11_PARSE(app, argc, argv);
    std::unique_ptr<tbb::global_control> control;
    if (threads > 0) {
        control = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, threads);
    }
    try {
        sa::Stopwatch reading;
        sa::SimplicialMesh mesh;
        sa::HandleTargets handle_targets;
        if (!bar.empty()) {
            sa::BarDeformation b = sa::bar_deformation(sa::parse_bar_pose(bar));
            if (name.empty()) name = b.name;
            mesh = std::move(b.mesh);
            handle_targets = {std::move(b.handles), std::move(b.targets)};
        } else {
            if (rest.empty() || targets.empty()) {
                std::cerr << "give --bar, or --rest and --targets\n";
                return 2;
            }
            if (name.empty()) name = rest;
            mesh = sa::read_mesh_file(rest).mesh;
            sa::validate_mesh(mesh, rest);
            handle_targets = sa::read_handle_targets(handles, targets, mesh.num_vertices(),
                                                     mesh.simplex_dimension());
        }
        const double read_seconds = reading.seconds();
        sa::ArapOptions options;
        options.max_iterations = iterations;
        options.tolerance = tolerance;
        options.anderson_history = anderson;
        options.rotation_start = !rest_start;
        sa::Logger logger;
        if (verbose) logger = [](const std::string& line) { std::cerr << line << '\n'; };
        const sa::DeformStart start = sa::deform_start(mesh, handle_targets, options, logger);
        // Inverted simplices that have a boundary facet: those a picture of the surface shows.
        const sa::MeshTopology topology = sa::mesh_topology(mesh, name);
        std::vector<unsigned char> on_boundary(mesh.num_simplices(), 0);
        for (const sa::BoundaryFacet& f : topology.boundary_facets) on_boundary[f.simplex] = 1;
        long visible = 0;
        for (sa::Index s = 0; s < mesh.num_simplices(); ++s)
            visible += start.quality.per_simplex[s].inverted && on_boundary[s];
        if (!png.empty()) sa::write_pose_png(png, mesh, start.positions);
        const sa::MapQuality& q = start.quality;
        std::printf(
            "{\"case\": \"%s\", \"vertices\": %ld, \"simplices\": %ld, \"handles\": %ld, "
            "\"inverted\": %ld, \"inverted_on_boundary\": %ld, \"degenerate\": %ld, "
            "\"isometric\": [%.6g, %.6g], \"conformal\": [%.6g, %.6g], \"volumetric\": [%.6g, "
            "%.6g], \"iterations\": %d, \"rejected\": %d, \"stop\": \"%s\", \"Q\": [%.6g, %.6g], "
            "\"start\": \"%s\", \"start_seconds\": %.4f, \"iteration_seconds\": %.4f, "
            "\"read_seconds\": %.3f}\n",
            name.c_str(), long(mesh.num_vertices()), long(mesh.num_simplices()),
            long(handle_targets.handles.size()), long(q.inverted), visible, long(q.degenerate),
            q.isometric.max, q.isometric.mean, q.conformal.max, q.conformal.mean, q.volumetric.max,
            q.volumetric.mean, start.arap.iterations, start.arap.rejected, start.arap.stop.c_str(),
            start.arap.initial_energy, start.arap.energy, start.arap.start.c_str(), start.seconds,
            start.arap.seconds, read_seconds);
    } catch (const sa::Error& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 2;
    }
    return 0;
}
