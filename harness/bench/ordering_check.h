// An orderer's output must be a complete back-to-front permutation (orderer.h); this is the
// one check of that, used by the runner, the commands and probes alike.
#pragma once
#include <string>

#include "harness/bench/orderer.h"

namespace vob {

// Throws std::logic_error when the ordering is not a permutation of the scene's primitives
// (voxels: of its significant voxels); `who` names the orderer in the message.
void check_complete(const Scene& scene, const Ordering& ordering, const std::string& who);

}  // namespace vob
