// Probes of the stencil layering (Krishnan, Silva and Wei), registered in
// harness/bench/registry.cpp beside the orderers (docs/pipeline.md "Probes"):
//
//   stencil-read-scan     (needs a scene) Fig. 2: the shares of rendering, reading and
//                         scanning in the layer extraction, naive against blocked. Every
//                         variant (gl naive, gl blocked 32, gl blocked 64, software naive,
//                         software blocked 64) is prepared once; the views are run
//                         interleaved frame by frame (so a change in the machine's load hits
//                         every variant alike), each (view, variant) the fastest of
//                         ctx.repeats runs after ctx.warmup warm-up frames per variant on the
//                         first view. Result: per variant the seconds summed over the views,
//                         per phase and in total, and pixels read / layers per view.
//   stencil-layer-images  (needs a scene) Fig. 3: the layers of the suite's first view:
//                         triangles and footprint per layer, the oracle's verdict on the
//                         order, and PNGs: every triangle coloured by its layer (a) from the
//                         view and (b) from the opposite side, then one image per layer (its
//                         footprint), at most `images` of them (0: all).
//                         backend=gl (gl|software); images=12 (0..1000).
#pragma once
#include "harness/bench/probe.h"

namespace vob {
ProbeInfo stencil_read_scan_probe_info();
ProbeInfo stencil_layer_images_probe_info();
}  // namespace vob
