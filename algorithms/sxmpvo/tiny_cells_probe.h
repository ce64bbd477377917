// Probe sxmpvo-tiny-cells (Cook et al. Table 6): cells no pixel centre sees, per image size.
#pragma once
#include "harness/bench/probe.h"

namespace vob {
ProbeInfo sxmpvo_tiny_cells_probe_info();
}  // namespace vob
