// The software backend's exact rule for coplanar depth ties (layer_backend.h, set_facing):
// two exterior faces of volumes that touch face to face lie in one plane; their depths,
// interpolated from different vertices, differ by rounding. With facing given, the
// back-facing face wins the nearest test and the front-facing one the farthest test at
// every shared pixel, whatever the drawing order.
#include <gtest/gtest.h>

#include <vector>

#include "algorithms/stencil/software_backend.h"

using namespace vob;
using namespace vob::stencil;

namespace {

// Plane z = 0.5 x + 0.25 y with dyadic coordinates, so every vertex lies on it exactly. Face 0 is the big
// square, face 1 a smaller square inside it, listed the other way round (opposite normal).
void touching_faces(std::vector<Vec3>& pts, std::vector<int8_t>& sizes) {
  auto on_plane = [](double x, double y) { return Vec3{x, y, 0.5 * x + 0.25 * y}; };
  pts = {on_plane(-1, -1), on_plane(1, -1), on_plane(1, 1), on_plane(-1, 1),
         on_plane(-0.625, -0.625), on_plane(-0.625, 0.75), on_plane(0.75, 0.75), on_plane(0.75, -0.625)};
  sizes = {4, 4};
}

Camera view() {
  Camera c;
  c.eye = {0.3, -0.4, 6};
  c.target = {0, 0, 0};
  c.width = c.height = 64;
  return c;
}

struct Buffers {
  std::vector<uint32_t> colour;
  std::vector<uint8_t> shared;  // per pixel: both faces were drawn there (stencil 2)
};

Buffers draw(SoftwareBackend& b, bool far, const std::vector<int32_t>& ids) {
  const Camera c = view();
  b.begin_frame(c);
  far ? b.render_complexity(ids) : b.render_candidates(ids);
  Buffers out;
  out.colour.assign(size_t(c.width) * c.height, 0);
  out.shared.assign(out.colour.size(), 0);
  b.read_colour({0, 0, c.width, c.height}, out.colour.data());
  b.read_stencil({0, 0, c.width, c.height}, out.shared.data());
  for (uint8_t& s : out.shared) s = s == 2;
  return out;
}

}  // namespace

TEST(SoftwareBackendTies, CoplanarOppositeFacesOrderBackFacingFirstInEveryDrawingOrder) {
  std::vector<Vec3> pts;
  std::vector<int8_t> sizes;
  touching_faces(pts, sizes);
  for (uint8_t back : {0, 1}) {
    std::vector<uint8_t> front = {1, 1};
    front[back] = 0;
    SoftwareBackend b;
    b.set_primitives(pts, sizes);
    b.set_facing(&front);
    const uint32_t back_id = uint32_t(back) + 1, front_id = uint32_t(1 - back) + 1;
    for (const std::vector<int32_t>& ids : {std::vector<int32_t>{0, 1}, std::vector<int32_t>{1, 0}}) {
      const Buffers complexity = draw(b, true, ids);
      int shared = 0;
      for (uint8_t s : complexity.shared) shared += s;
      ASSERT_GT(shared, 100);
      const Buffers nearest = draw(b, false, ids);
      for (size_t p = 0; p < complexity.shared.size(); ++p) {
        if (!complexity.shared[p]) continue;
        EXPECT_EQ(nearest.colour[p], back_id) << "pixel " << p;
        EXPECT_EQ(complexity.colour[p], front_id) << "pixel " << p;
      }
    }
  }
}
