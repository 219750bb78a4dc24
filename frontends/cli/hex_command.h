#pragma once
// `sa hex` (issue 48): a hexahedral mesh of a tetrahedral one, through its PolyCube map
// (frontends/hex/hex_meshing.h). The labels and the PolyCube options are `sa polycube`'s.
//
//   sa hex --mesh TETS [--labels FLAGS | --labels LABELS.txt --label-surface SURFACE.obj]
//          [--hexes N | --hex-size H] [--padding D] --out OUT.mesh [--polycube P.mesh] [--vtu
//          V.vtu]
//          [--png P.png | --no-png] [--report R.json] [--bound K] [--max-time S] [--threads N]
//          [--force] [--quiet]
//
// Exit 0 only when the hex mesh verifies (no inverted hex, a closed boundary); 1 when a stage
// did not verify (the report and the summary name it; no hex mesh is written without one).

#include <string>

#include "frontends/cli/polycube_command.h"

namespace sa::cli {

struct HexArguments {
    PolycubeArguments polycube;  ///< mesh, labels, bound, max_time, threads, force, quiet
    std::string hexes;           ///< the target count; empty: the default
    std::string hex_size;        ///< the cell size in the input's units; empty: from hexes
    double padding = 0.5;        ///< HexMeshingOptions::padding
    std::string out, polycube_out, vtu, png, report;
    bool no_png = false;
};

/// Hexes aimed at without --hexes or --hex-size: a first look in seconds at most sizes.
inline constexpr Index kDefaultHexes = 10000;

/// Runs `sa hex`: returns the exit status (cli_support.h), throws on bad input.
int run_hex_command(const HexArguments& arguments);

}  // namespace sa::cli
