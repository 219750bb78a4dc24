// The terms of the built-in per-simplex energies in dimension 2, declared in engine.h and
// simplex_term.h, compiled here once.
#include "frontends/simplex_assembly/simplex_term.h"

namespace sa {

SA_SIMPLEX_ENERGY_TERMS(, 2, SimplexEnergy<2>)
SA_SIMPLEX_ENERGY_TERMS(, 2, DistortionBarrier<2, BuiltinDistortion<2>>)
template class SimplexTermOf<2, SimplexEnergy<2>>;
template class SimplexTermOf<2, DistortionBarrier<2, BuiltinDistortion<2>>>;

}  // namespace sa
