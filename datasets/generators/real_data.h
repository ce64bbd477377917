// Real data from Debian's libcgal-demo archive (VOB_CGAL_DATA), extracted into the cache
// on first use (data_cache.h):
//   skull           data/images/skull_2.9.inr, a 64^3 float CT volume (spacing 3.94 x 3.94 x
//                   3.65); `threshold` (default 0.5) leaves out the near-zero air around it.
//   surface-<name>  a closed OFF surface as a triangle soup.
//   tet-<name>      the same surface meshed by TetGen (-pq<quality>[a<volume>]), cached per
//                   model and switches; point scalar = 1 near the centre of the bounding
//                   box, falling to 0.2 at its corners.
#pragma once
#include <string>
#include <vector>

#include "harness/bench/params.h"
#include "harness/scene/scene.h"

namespace vob {

struct RealModel {
  std::string name;     // registry suffix: surface-<name>, tet-<name>
  std::string member;   // path inside the archive
  double quality;       // default TetGen radius-edge bound
  std::string summary;  // what it is
};
// Closed, non-self-intersecting models that TetGen meshes cleanly in seconds.
const std::vector<RealModel>& real_models();

Scene make_skull(Params& p);                       // threshold=0.5
Scene make_surface(const RealModel& m, Params& p);  // no parameters
Scene make_tet(const RealModel& m, Params& p);      // quality=<model default> maxvol=0

}  // namespace vob
