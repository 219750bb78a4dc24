#pragma once
// The fuzz targets of the file readers (issue 25): one per reader, each taking the bytes of one
// input, writing them to the file(s) the reader expects and reading them. A bad input must end
// in sa::Error (InputError, InvalidArgumentError); anything else (another exception, a crash, a
// sanitizer report, an allocation beyond libFuzzer's limit) is a bug.
//
// Shared by the libFuzzer executables (fuzz_main.cpp, built with clang when SA_FUZZ is on), the
// seed corpus generator (fuzz_seeds.cpp) and the regression test (fuzz_regression_test.cpp, in
// every build), which runs every input kept in tests/fuzz/regressions/<target>/ and checks that
// the seeds, valid files, are read without error.
//
// How an input's bytes are laid out, per target:
//   problem, result_records, obj, off, medit, vtk, dmat, index_list   the file itself
//   tetgen        the .node file, a NUL byte, the .ele file
//   frame_field   the file; then a byte, the mesh's face count; then a byte, the reader: 0 a
//                 .crossfield, 1 a .dmat (read_frame_field), 2 libigl's pair b.dmat NUL bc.dmat
//   ply_stl       the file; then a byte: even a .ply, odd a .stl
//   rawfield      the file; then a byte, the mesh's face count
//   indexed_positions  the file; then a byte b: dimension 2 + (b & 1), vertex count (b >> 1) - 1
//                 (-1: no range check)
//   polycube_labels  the file; then a byte, the element count (tetrahedra or triangles); then a
//                 byte: even a .flags file (read_facet_flags), odd a labeling.txt
//                 (read_triangle_labels)

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sa::fuzz {

using Bytes = std::vector<std::uint8_t>;

struct Target {
    const char* name;
    /// Reads one input; throws what the reader throws.
    void (*run)(const std::uint8_t* data, std::size_t size);
    /// Small valid inputs, each read without error: the seed corpus.
    std::vector<Bytes> (*seeds)();
};

/// Every target, in a fixed order.
const std::vector<Target>& targets();

/// The target named `name`; throws std::invalid_argument when there is none.
const Target& target(const std::string& name);

}  // namespace sa::fuzz
