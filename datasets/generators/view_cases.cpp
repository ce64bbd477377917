#include "datasets/generators/view_cases.h"

#include <algorithm>
#include <cmath>

#include "datasets/generators/kuhn_block.h"

namespace vob {

namespace {
constexpr double kPi = 3.14159265358979323846;

Scene block_scene(const char* name, Params& p, int def, int lo = 1) {
  const int n = p.get_int("n", def, lo, 100);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  CellMesh m;
  append_kuhn_block(m, {n, n, n, {0, 0, 0}, {1, 1, 1}});
  const Vec3 centre{n / 2.0, n / 2.0, n / 2.0};
  m.scalars.reserve(m.points.size());
  for (const Vec3& q : m.points)  // a soft ball of density in the middle of the block
    m.scalars.push_back(0.2 + 0.8 * std::exp(-dot(q - centre, q - centre) / (0.3 * n * n)));
  return Scene::from_mesh(name, std::move(m), p.to_json());
}

Camera base(int width, int height) {
  Camera c;
  c.width = width;
  c.height = height;
  return c;
}

// A perspective camera at `eye` (outside the box) looking at the box centre, with a field
// of view that holds the bounding sphere.
Camera look_at_box(const Aabb& box, Vec3 eye, Vec3 up, int width, int height) {
  Camera c = base(width, height);
  c.eye = eye;
  c.target = box.center();
  c.up = up;
  const double half = std::asin(std::min(1.0, box.radius() / length(box.center() - eye)));
  c.fov_deg = std::min(150.0, 2.0 * half * 180.0 / kPi * 1.1);
  return c;
}
}  // namespace

Scene make_edge_on(Params& p) { return block_scene("edge-on", p, 8); }
// n >= 4 so that the planes x=2, x=3, y=3 below hold faces of the block.
Scene make_eye_in_plane(Params& p) { return block_scene("eye-in-plane", p, 6, 4); }
Scene make_eye_inside(Params& p) { return block_scene("eye-inside", p, 6, 2); }

std::vector<Camera> edge_on_views(const Scene& s, int width, int height) {
  const Aabb box = s.bounds();
  const Vec3 c = box.center(), ext = box.hi - box.lo;
  const double extent = std::max({ext.x, ext.y, ext.z});
  // Pixel size: the smallest power of two whose image holds the block with a margin, so
  // that window coordinates map to world coordinates exactly.
  const double px = std::exp2(std::ceil(std::log2(1.25 * extent / std::min(width, height))));
  // Looking exactly along -axis: forward, right and up are exact unit vectors.
  auto ortho = [&](Vec3 eye, Vec3 dir, Vec3 up) {
    Camera cam = base(width, height);
    cam.ortho = true;
    cam.ortho_height = px * height;
    cam.eye = eye;
    cam.target = eye + dir * extent;
    cam.up = up;
    return cam;
  };
  std::vector<Camera> v;
  v.push_back(ortho({c.x, c.y, box.hi.z + 2 * extent}, {0, 0, -1}, {0, 1, 0}));
  // Pixel centre i+0.5 maps to eye.x + (i + 0.5 - width/2) * px: shifting the eye by half
  // a pixel (even sizes) puts pixel centres on integer coordinates, i.e. on grid lines.
  const double sx = width % 2 == 0 ? 0.5 * px : 0.0, sy = height % 2 == 0 ? 0.5 * px : 0.0;
  v.push_back(ortho({std::floor(c.x) - sx, std::floor(c.y) - sy, box.hi.z + 2 * extent},
                    {0, 0, -1}, {0, 1, 0}));
  v.push_back(ortho({box.hi.x + 2 * extent, c.y, c.z}, {-1, 0, 0}, {0, 0, 1}));
  v.push_back(ortho({c.x, box.hi.y + 2 * extent, c.z}, {0, -1, 0}, {0, 0, 1}));
  return v;
}

std::vector<Camera> eye_in_plane_views(const Scene& s, int width, int height) {
  const Aabb box = s.bounds();
  const double n = std::round(box.hi.x - box.lo.x);
  std::vector<Camera> v;
  // In planes x=2, y=3 and x-y=-1 (all hold faces of the block).
  v.push_back(look_at_box(box, box.lo + Vec3{2, 3, n + 4}, {0, 1, 0}, width, height));
  // On the block's main diagonal: in x=y, y=z and x=z, along the shared diagonal edges.
  v.push_back(look_at_box(box, box.lo + Vec3{-4, -4, -4}, {0, 0, 1}, width, height));
  // In planes x=3, z=1 and x-z=2.
  v.push_back(look_at_box(box, box.lo + Vec3{3, n + 3, 1}, {0, 0, 1}, width, height));
  return v;
}

std::vector<Camera> eye_inside_views(const Scene& s, int width, int height) {
  const Aabb box = s.bounds();
  const Vec3 c = box.center();
  std::vector<Camera> v;
  Camera a = base(width, height);
  a.eye = box.lo + (box.hi - box.lo) * 0.37 + Vec3{0.013, 0.029, 0.007};  // generic point
  a.target = box.hi - Vec3{0.5, 1.1, 2.3};
  a.up = {0, 0, 1};
  a.fov_deg = 90;
  v.push_back(a);
  Camera b = base(width, height);
  b.eye = {std::round(c.x), std::round(c.y), std::round(c.z)};  // an interior mesh vertex
  b.target = b.eye + Vec3{3, 1.5, 2};
  b.up = {0, 0, 1};
  b.fov_deg = 100;
  v.push_back(b);
  return v;
}

}  // namespace vob
