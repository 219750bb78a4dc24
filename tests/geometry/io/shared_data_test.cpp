// Reads the real files of ../shared/data (SA_DATA_DIR) and checks their counts against its
// README. Skips when the folder is absent.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "geometry/io/dmat_io.h"
#include "geometry/io/frame_field_io.h"
#include "geometry/io/index_list_io.h"
#include "geometry/io/medit_io.h"
#include "geometry/io/mesh_file.h"
#include "geometry/io/obj_io.h"
#include "geometry/io/off_io.h"
#include "geometry/io/problem_io.h"
#include "geometry/io/tetgen_io.h"
#include "io_test_util.h"

namespace sa {
namespace {

namespace fs = std::filesystem;

class SharedData : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!fs::is_directory(root_)) GTEST_SKIP() << "no shared data at " << root_;
    }
    std::string path(const std::string& relative) const { return (root_ / relative).string(); }
    // The files of `folder` whose name ends with `suffix`, sorted.
    std::vector<std::string> files(const std::string& folder, const std::string& suffix) const {
        std::vector<std::string> result;
        for (const auto& entry : fs::directory_iterator(root_ / folder)) {
            const std::string name = entry.path().filename().string();
            if (name.size() >= suffix.size() &&
                name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
                result.push_back(entry.path().string());
        }
        std::sort(result.begin(), result.end());
        return result;
    }

    const fs::path root_{SA_DATA_DIR};
};

struct Counts {
    Index vertices;
    int dim;
    int init_dim;
    Index simplices;
    int k;
    std::size_t handles;
};

TEST_F(SharedData, TlcProblemsAndResults) {
    const std::map<std::string, Counts> expected{
        {"cube", {64, 3, 3, 162, 4, 56}},     {"param2d", {1024, 3, 2, 2000, 3, 46}},
        {"stgc-2d", {169, 2, 2, 288, 3, 48}}, {"stgc-3d", {630, 3, 3, 1722, 4, 583}},
        {"sea-2d", {51, 2, 2, 50, 3, 2}},
    };
    for (const auto& [name, counts] : expected) {
        SCOPED_TRACE(name);
        const MeshFile file = read_mesh_file(path("tlc/" + name + "/input"));
        EXPECT_EQ(file.mesh.num_vertices(), counts.vertices);
        EXPECT_EQ(file.mesh.ambient_dimension(), counts.dim);
        ASSERT_TRUE(file.initial.has_value());
        EXPECT_EQ(file.initial->rows(), counts.vertices);
        EXPECT_EQ(file.initial->cols(), counts.init_dim);
        EXPECT_EQ(file.mesh.num_simplices(), counts.simplices);
        EXPECT_EQ(file.mesh.simplices.cols(), counts.k);
        EXPECT_EQ(file.handles.size(), counts.handles);

        const Eigen::MatrixXd result = read_result_positions(path("tlc/" + name + "/result"));
        EXPECT_EQ(result.rows(), counts.vertices);
        EXPECT_EQ(result.cols(), counts.init_dim);
    }
}

TEST_F(SharedData, TetGenDeformationsAndHandles) {
    struct Deform {
        Index vertices;
        Index tets;
        std::size_t handles;
    };
    const std::map<std::string, Deform> expected{
        {"botijo", {15949, 57091, 1476}},
        {"rabbit", {26112, 102389, 1075}},
        {"stretch", {4913, 20480, 578}},
        {"untwist", {4961, 20000, 121}},
    };
    for (const auto& [name, counts] : expected) {
        Eigen::MatrixXi rest_tets;
        for (const char* stage : {"_rest", "_init", "_nh_soln"}) {
            const std::string node = "deform/" + name + "/" + name + stage + ".node";
            SCOPED_TRACE(node);
            const MeshFile file = read_mesh_file(path(node));
            EXPECT_EQ(file.mesh.num_vertices(), counts.vertices);
            EXPECT_EQ(file.mesh.ambient_dimension(), 3);
            EXPECT_EQ(file.mesh.num_simplices(), counts.tets);
            EXPECT_EQ(file.mesh.simplices.cols(), 4);
            // 1-based and 0-based files describe the same tets.
            if (rest_tets.size() == 0)
                rest_tets = file.mesh.simplices;
            else
                EXPECT_EQ(file.mesh.simplices, rest_tets);
        }
        const std::vector<Index> handles =
            read_index_list(path("deform/" + name + "/" + name + "_handles.txt")).indices;
        EXPECT_EQ(handles.size(), counts.handles) << name;
        EXPECT_LT(*std::max_element(handles.begin(), handles.end()), counts.vertices) << name;
    }
}

TEST_F(SharedData, WrenchMeditAndLockedVertices) {
    for (const char* name : {"wrench-rest.mesh", "wrench-init.mesh"}) {
        SCOPED_TRACE(name);
        const MeshFile file = read_medit(path(std::string("deform/wrench/") + name));
        EXPECT_EQ(file.mesh.num_vertices(), 14798);
        EXPECT_EQ(file.mesh.ambient_dimension(), 3);
        EXPECT_EQ(file.mesh.num_simplices(), 50122);
        EXPECT_EQ(file.mesh.simplices.cols(), 4);
    }
    const std::vector<Index> locked =
        read_index_list(path("deform/wrench/wrench-lock.txt")).indices;
    EXPECT_EQ(locked.size(), 4792u);  // the count header "4792 #Vertices Locked" is dropped
    EXPECT_EQ(locked.front(), 0);
    EXPECT_LT(*std::max_element(locked.begin(), locked.end()), 14798);
}

TEST_F(SharedData, TetMeshes) {
    const std::map<std::string, std::pair<Index, Index>> expected{
        {"bunny", {5433, 34055}},     {"decimated-knight", {1822, 5452}},
        {"hand", {7234, 29998}},      {"marching_tets_input", {4809, 22132}},  // no End keyword
        {"octopus-low", {452, 1140}},
    };
    for (const auto& [name, counts] : expected) {
        SCOPED_TRACE(name);
        const MeshFile file = read_mesh_file(path("tet/" + name + ".mesh"));
        EXPECT_EQ(file.mesh.num_vertices(), counts.first);
        EXPECT_EQ(file.mesh.num_simplices(), counts.second);
        EXPECT_EQ(file.mesh.simplices.cols(), 4);
    }
    for (const char* folder : {"polycube/robustPolycube", "polycube/polycube_withHexEx"}) {
        for (const std::string& mesh : files(folder, ".mesh")) {
            SCOPED_TRACE(mesh);
            const MeshFile file = read_medit(mesh);
            EXPECT_GT(file.mesh.num_vertices(), 0);
            EXPECT_GT(file.mesh.num_simplices(), 0);
            EXPECT_EQ(file.mesh.simplices.cols(), 4);
        }
    }
}

TEST_F(SharedData, SurfaceMeshes) {
    const std::map<std::string, std::pair<Index, Index>> expected{
        {"param/annulus.obj", {4985, 9724}},
        {"param/bump-domain.obj", {4172, 8058}},
        {"param/camel_b.obj", {2032, 3576}},
        {"param/circle.obj", {5201, 10240}},
        {"param/face.obj", {25905, 51712}},
        {"param/golf.obj", {262, 515}},
        {"param/hand-uv.obj", {5011, 9960}},
        {"param/hemisphere.obj", {145, 256}},
        {"param/snail.obj", {871, 1653}},
        {"param/camelhead.off", {11381, 22704}},
        {"param/grid.off", {145, 256}},
        {"param/lion.off", {8356, 16674}},
        {"param/planexy.off", {25, 32}},
        {"surfaces/3holes.off", {3596, 7200}},
        {"surfaces/bumpy.off", {1250, 2496}},
        {"surfaces/bunny.off", {3485, 6966}},
        {"surfaces/cow.off", {2762, 5520}},
        {"surfaces/fertility.off", {4494, 9000}},
        {"deform/knight/decimated-knight.off", {502, 1000}},
        {"frame-fields/inspired_mesh.obj", {2244, 4288}},
        {"frame-fields/lilium.obj", {3389, 6590}},
        {"frame-fields/snail.obj", {871, 1653}},
        {"frame-fields/bumpy-cube.obj", {19970, 39936}},
        {"frame-fields/torus.obj", {576, 1152}},
        {"polycube/fastbndpolycube/boundary.obj", {10456, 20920}},
        {"polycube/validity-first-labeling/surface.obj", {9984, 19964}},
    };
    // Every .obj and .off of param/ and surfaces/ is in the table.
    std::size_t listed = 0;
    for (const char* folder : {"param", "surfaces"})
        for (const char* suffix : {".obj", ".off"}) listed += files(folder, suffix).size();
    EXPECT_EQ(listed, 18u);

    for (const auto& [name, counts] : expected) {
        SCOPED_TRACE(name);
        const MeshFile file = read_mesh_file(path(name));
        EXPECT_EQ(file.mesh.num_vertices(), counts.first);
        EXPECT_EQ(file.mesh.ambient_dimension(), 3);
        EXPECT_EQ(file.mesh.num_simplices(), counts.second);
        EXPECT_EQ(file.mesh.simplices.cols(), 3);
    }
    // hand-uv.obj: vt is a per-vertex UV map, read as the initial map.
    const MeshFile hand = read_obj(path("param/hand-uv.obj"));
    ASSERT_TRUE(hand.initial.has_value());
    EXPECT_EQ(hand.initial->rows(), 5011);
    EXPECT_EQ(hand.initial->cols(), 2);
    EXPECT_EQ(hand.face_texture_indices.rows(), 9960);
    EXPECT_TRUE(hand.warnings.empty());
    const MeshFile camel = read_obj(path("param/camel_b.obj"));
    EXPECT_EQ(camel.texture_coordinates.rows(), 2032);
    EXPECT_TRUE(camel.initial.has_value() || !camel.warnings.empty());
}

TEST_F(SharedData, FrameFieldMatrices) {
    const std::map<std::string, std::pair<Index, Index>> expected{
        {"3holes-miq-FUV", {7200, 3}}, {"3holes-miq-UV", {4023, 2}},
        {"bumpy-cube", {22224, 7}},  // the one binary .dmat
        {"inspired_mesh", {4288, 7}},  {"inspired_mesh_b", {84, 1}},
        {"inspired_mesh_bc", {84, 6}}, {"lilium_b", {323, 1}},
        {"lilium_bc", {323, 6}},       {"snail", {27, 1}},
        {"snail1", {1653, 4}},         {"snail2", {1653, 7}},
        {"snail3", {1653, 10}},        {"snail4", {1653, 13}},
    };
    std::size_t checked = 0;
    for (const std::string& file : files("frame-fields", ".dmat")) {
        const std::string name = fs::path(file).stem().string();
        SCOPED_TRACE(name);
        const auto it = expected.find(name);
        ASSERT_NE(it, expected.end());
        const Eigen::MatrixXd matrix = read_dmat(file);
        EXPECT_EQ(matrix.rows(), it->second.first);
        EXPECT_EQ(matrix.cols(), it->second.second);
        ++checked;
    }
    EXPECT_EQ(checked, expected.size());
    EXPECT_EQ(read_dmat(path("deform/knight/decimated-knight-selection.dmat")).rows(), 502);
}

std::size_t count(const std::vector<unsigned char>& flags) {
    return static_cast<std::size_t>(std::count(flags.begin(), flags.end(), 1));
}

TEST_F(SharedData, FrameFields) {
    struct Field {
        std::string mesh;
        std::size_t given;
        std::size_t constrained;
        Index vectors;  // per face
        bool has_v;
    };
    const std::map<std::string, Field> expected{
        {"inspired_mesh.dmat", {"inspired_mesh", 4288, 84, 2, true}},  // flag, u, v; all given
        {"snail1.dmat", {"snail", 27, 27, 1, false}},  // flag + k vectors, only flagged faces
        {"snail2.dmat", {"snail", 27, 27, 2, true}},
        {"snail3.dmat", {"snail", 27, 27, 3, false}},
        {"snail4.dmat", {"snail", 27, 27, 4, false}},
        {"bumpy-cube.dmat", {"bumpy-cube", 22224, 22224, 2, true}},  // binary face-index list
        {"lilium.crossfield", {"lilium", 6590, 323, 2, true}},
        {"torus_twosings.rawfield", {"torus", 1152, 0, 4, true}},  // Directional, N = 4
    };
    std::map<std::string, Index> faces;
    for (const auto& [name, field] : expected) {
        if (faces.count(field.mesh) == 0)
            faces[field.mesh] =
                read_mesh_file(path("frame-fields/" + field.mesh + ".obj")).mesh.num_simplices();
    }
    std::map<std::string, FrameFieldFile> read;
    for (const auto& [name, field] : expected) {
        SCOPED_TRACE(name);
        const Index num_faces = faces.at(field.mesh);
        const FrameFieldFile file = read_frame_field(path("frame-fields/" + name), num_faces);
        EXPECT_EQ(file.u.rows(), num_faces);
        EXPECT_EQ(file.vectors.rows(), num_faces);
        EXPECT_EQ(file.vectors.cols(), 3 * field.vectors);
        EXPECT_EQ(file.v.rows(), field.has_v ? num_faces : 0);
        EXPECT_EQ(count(file.given), field.given);
        EXPECT_EQ(count(file.constrained), field.constrained);
        read.emplace(name, file);
    }
    // The flagged faces of snail1-4 are the list snail.dmat, with the same first vector.
    const Eigen::MatrixXd snail = read_dmat(path("frame-fields/snail.dmat"));
    ASSERT_EQ(snail.rows(), 27);
    for (const char* name : {"snail1.dmat", "snail2.dmat", "snail3.dmat", "snail4.dmat"}) {
        const FrameFieldFile& file = read.at(name);
        for (Eigen::Index i = 0; i < snail.rows(); ++i) {
            const auto face = static_cast<Index>(snail(i, 0));
            EXPECT_TRUE(file.constrained[static_cast<std::size_t>(face)]) << name << " " << face;
            EXPECT_EQ(file.u.row(face), read.at("snail1.dmat").u.row(face)) << name;
        }
    }
    // snail3: u and u turned by 60 and 120 degrees; snail4: u and u turned by 135, -90 and 45
    // degrees (so vector 2 is perpendicular to u): PolyVectors, not frames.
    auto cosine = [](const Eigen::MatrixXd& vectors, Eigen::Index f, int a, int b) {
        const Eigen::Vector3d x = vectors.block<1, 3>(f, 3 * a).transpose();
        const Eigen::Vector3d y = vectors.block<1, 3>(f, 3 * b).transpose();
        return x.dot(y) / (x.norm() * y.norm());
    };
    for (Eigen::Index i = 0; i < snail.rows(); ++i) {
        const auto face = static_cast<Eigen::Index>(snail(i, 0));
        const Eigen::MatrixXd& three = read.at("snail3.dmat").vectors;
        EXPECT_NEAR(cosine(three, face, 0, 1), 0.5, 1e-9);
        EXPECT_NEAR(cosine(three, face, 0, 2), -0.5, 1e-9);
        const Eigen::MatrixXd& four = read.at("snail4.dmat").vectors;
        EXPECT_NEAR(cosine(four, face, 0, 1), -std::sqrt(0.5), 1e-9);
        EXPECT_NEAR(cosine(four, face, 0, 2), 0.0, 1e-9);
        EXPECT_NEAR(cosine(four, face, 0, 3), std::sqrt(0.5), 1e-9);
    }

    // libigl's _b.dmat / _bc.dmat pairs give the flagged faces of the dense files.
    for (const auto& [stem, dense] : std::map<std::string, std::string>{
             {"inspired_mesh", "inspired_mesh.dmat"}, {"lilium", "lilium.crossfield"}}) {
        SCOPED_TRACE(stem);
        const FrameFieldFile pair =
            read_frame_field_constraints(path("frame-fields/" + stem + "_b.dmat"),
                                         path("frame-fields/" + stem + "_bc.dmat"), faces.at(stem));
        const FrameFieldFile& full = read.at(dense);
        EXPECT_EQ(pair.given, full.constrained);
        EXPECT_EQ(pair.constrained, full.constrained);
        for (std::size_t f = 0; f < pair.given.size(); ++f) {
            if (!pair.given[f]) continue;
            const auto face = static_cast<Eigen::Index>(f);
            EXPECT_LT((pair.u.row(face) - full.u.row(face)).norm(), 1e-5) << face;
            EXPECT_LT((pair.v.row(face) - full.v.row(face)).norm(), 1e-5) << face;
        }
    }
    // snail.dmat is a face list without vectors: not a field.
    EXPECT_TRUE(test::throws_input_error(
        [&] { read_frame_field(path("frame-fields/snail.dmat"), faces.at("snail")); },
        {"snail.dmat: 27 rows x 1 columns; expected 1653 rows"}));
}

}  // namespace
}  // namespace sa
