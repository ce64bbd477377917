// havs-gl probe: the shader k-buffer (gl_kbuffer.h) on OSMesa against the software k-buffer
// (havs_frame.h) for the same face order, per view of a mesh: times, 8-bit image
// differences, pixels whose GL coverage differs from the harness rasterizer's, and the
// pixels a batched (racy, the paper's Fig. 5) frame changes against the race-free
// serialized frame. Only the public interface of gl_kbuffer.h is used.
#pragma once
#include "harness/bench/probe.h"

namespace vob {

ProbeInfo havs_gl_probe_info();

}  // namespace vob
