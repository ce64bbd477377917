// Issue 4's stability study of XMPVO: per hard case (and a few ordinary meshes), how many
// sign decisions -- arrow signs, front/back facing, edge crossings, sides of projected
// edges at arrangement vertices -- plain double arithmetic gets wrong against the exact
// predicate, and whether the order built from the double signs fails the oracle where the
// exact one does not. Writes xmpvo-stability.md / .json to ctx.out_dir.
#pragma once
#include "harness/cli/experiments.h"

namespace vob {

int xmpvo_stability(const ExperimentContext& ctx);

}  // namespace vob
