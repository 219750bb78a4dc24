#include "geometry/bar_deformation.h"

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/mesh_generators.h"
#include "optim/errors.h"

namespace sa {

std::string to_string(BarPose pose) {
    switch (pose) {
        case BarPose::kBend:
            return "bend";
        case BarPose::kTwist:
            return "twist";
        case BarPose::kTranslate:
            return "translate";
    }
    return "unknown";
}

BarPose parse_bar_pose(const std::string& name) {
    for (BarPose pose : {BarPose::kBend, BarPose::kTwist, BarPose::kTranslate}) {
        if (to_string(pose) == name) return pose;
    }
    throw InvalidArgumentError("unknown bar pose '" + name +
                               "' (expected bend, twist or translate)");
}

void BarDeformationOptions::validate() const {
    auto fail = [](const std::string& what) {
        throw InvalidArgumentError("BarDeformationOptions: " + what);
    };
    if (length_cells < 1) fail("length_cells = " + std::to_string(length_cells) + " < 1");
    if (cross_cells < 1) fail("cross_cells = " + std::to_string(cross_cells) + " < 1");
    if (!(length > 0.0 && std::isfinite(length)))
        fail("length = " + std::to_string(length) + " must be positive");
    if (!(width > 0.0 && std::isfinite(width)))
        fail("width = " + std::to_string(width) + " must be positive");
    if (!(slab >= 0.0 && slab < 0.5))
        fail("slab = " + std::to_string(slab) + " must be in [0, 0.5)");
    for (auto [name, value] :
         {std::pair{"bend_degrees", bend_degrees}, std::pair{"twist_degrees", twist_degrees},
          std::pair{"shift", shift}}) {
        if (!std::isfinite(value)) fail(std::string(name) + " must be finite");
    }
}

BarDeformation bar_deformation(BarPose pose, const BarDeformationOptions& options) {
    options.validate();
    BarDeformation bar;
    bar.name = "bar-" + to_string(pose);
    bar.mesh = grid_tetrahedra(options.length_cells, options.cross_cells, options.cross_cells);
    // grid_tetrahedra's box is the cells' counts over the largest one: rescale each axis.
    const Eigen::RowVector3d lo = bar.mesh.vertices.colwise().minCoeff(),
                             hi = bar.mesh.vertices.colwise().maxCoeff();
    const Eigen::RowVector3d size(options.length, options.width, options.width);
    for (Index v = 0; v < bar.mesh.num_vertices(); ++v) {
        bar.mesh.vertices.row(v) =
            ((bar.mesh.vertices.row(v) - lo).array() / (hi - lo).array() * size.array()).matrix();
    }

    // The right end's rigid motion p -> R p + t.
    const double L = options.length, c = 0.5 * options.width;
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    switch (pose) {
        case BarPose::kBend: {
            const double angle = options.bend_degrees * M_PI / 180.0;
            R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
            // The centre line (s, c, c) becomes the arc of radius L / angle bending towards +y;
            // its end goes to (r sin(angle), c + r (1 - cos(angle)), c).
            Eigen::Vector3d end(L, c, c);
            if (std::abs(angle) > 1e-12) {
                const double r = L / angle;
                end = Eigen::Vector3d(r * std::sin(angle), c + r * (1.0 - std::cos(angle)), c);
            }
            t = end - R * Eigen::Vector3d(L, c, c);
            break;
        }
        case BarPose::kTwist: {
            const double angle = options.twist_degrees * M_PI / 180.0;
            R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).toRotationMatrix();
            t = Eigen::Vector3d(0, c, c) - R * Eigen::Vector3d(0, c, c);
            break;
        }
        case BarPose::kTranslate:
            t = Eigen::Vector3d(0.0, options.shift * options.width, 0.0);
            break;
    }

    const double reach = options.slab * L + 1e-9 * L;
    std::vector<Eigen::RowVector3d> targets;
    for (Index v = 0; v < bar.mesh.num_vertices(); ++v) {
        const Eigen::Vector3d p = bar.mesh.vertices.row(v).transpose();
        if (p.x() <= reach) {
            bar.handles.push_back(v);
            targets.push_back(p.transpose());
        } else if (p.x() >= L - reach) {
            bar.handles.push_back(v);
            targets.push_back((R * p + t).transpose());
        }
    }
    bar.targets.resize(static_cast<Eigen::Index>(targets.size()), 3);
    for (std::size_t k = 0; k < targets.size(); ++k) bar.targets.row(k) = targets[k];
    return bar;
}

}  // namespace sa
