// The terms of the built-in per-simplex energies in dimension 3, declared in engine.h and
// simplex_term.h, compiled here once.
#include "frontends/simplex_assembly/simplex_term.h"

namespace sa {

SA_SIMPLEX_ENERGY_TERMS(, 3, SimplexEnergy<3>)
SA_SIMPLEX_ENERGY_TERMS(, 3, DistortionBarrier<3, BuiltinDistortion<3>>)
template class SimplexTermOf<3, SimplexEnergy<3>>;
template class SimplexTermOf<3, DistortionBarrier<3, BuiltinDistortion<3>>>;

}  // namespace sa
