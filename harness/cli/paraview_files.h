// Files a ParaView user opens beside vobench's own outputs:
// - order_vtu: the cell mesh with cell arrays order_rank (position in the back-to-front
//   order, -1 for a cell the order leaves out), violating_fragments (the oracle's
//   per-cell count at that view: fragments of the cell drawn too late) and in_cycle (1 for
//   the cells the orderer reported in cycles; orderers report at most 1000).
// - violation_vti: a view's violation mask (1 = a violating sample in the pixel) as image
//   data, pixel (0,0) at the bottom left as in the camera's window.
// - camera_pvcc: the camera as ParaView's "Save camera" file (PVCameraConfiguration XML:
//   position, focal point, view up, view angle, parallel scale = half the ortho height,
//   parallel projection). ParaView's view size should be set to the image size too.
#pragma once
#include <string>

#include "harness/bench/orderer.h"
#include "harness/oracle/oracle.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

// `judged` must come from check_ordering with OracleOptions::per_primitive.
void write_order_vtu(const Scene& scene, const Ordering& ordering, const OracleResult& judged,
                     const std::string& path);
void write_violation_vti(const OracleResult& r, const std::string& path);  // needs violation_mask
void write_camera_pvcc(const Camera& cam, const std::string& path);

}  // namespace vob
