// What the HAVS tests share: view i of their 14-view set, and the face order HAVS draws a
// view in (its CPU sort, front to back).
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/havs/havs_frame.h"
#include "harness/view/view_set.h"

namespace vob::test {

inline constexpr int kHavsViews = 14;

inline Camera havs_view(const Scene& s, int i, int size) {
  ViewOptions o;
  o.width = o.height = size;
  return fibonacci_view(s.bounds(), kHavsViews, i, o);
}

inline std::vector<int32_t> havs_face_order(const havs::FaceData& fd, const Camera& cam) {
  havs::SortBuffers sb;
  std::vector<int32_t> order;
  havs::sort_faces(fd, cam, sb, order);
  return order;
}

}  // namespace vob::test
