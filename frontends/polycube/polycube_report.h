#pragma once
// The JSON of a PolyCube run's input side and of a verification (the parts of `sa polycube`'s
// report that do not depend on the solve):
//   polycube_preparation_json   input sizes, where the labels came from (and the sign
//                               convention of a file, or the clean-up of computed labels), the
//                               charts, the squashed elements and the splits, stage times;
//   polycube_verification_json  every check of verify_polycube() with its measure, the quality
//                               at the input's volume (as quality_json), the failures.

#include <nlohmann/json.hpp>

#include "frontends/polycube/polycube_preparation.h"

namespace sa {

nlohmann::json polycube_preparation_json(const PreparedPolycube& prepared);

nlohmann::json polycube_verification_json(const PolycubeVerification& verification);

}  // namespace sa
