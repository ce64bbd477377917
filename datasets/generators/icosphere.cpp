#include "datasets/generators/icosphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace vob {

void append_icosphere(TriangleSoup& soup, Vec3 centre, double radius, int subdiv) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> pts = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : pts) p = normalize(p);
  std::vector<std::array<int32_t, 3>> tris = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdiv; ++level) {
    // Each edge's midpoint is made once, so neighbouring triangles share it.
    std::unordered_map<uint64_t, int32_t> mid;
    mid.reserve(tris.size() * 2);
    auto midpoint = [&](int32_t a, int32_t b) {
      const uint64_t key = (uint64_t(std::min(a, b)) << 32) | uint32_t(std::max(a, b));
      auto [it, fresh] = mid.try_emplace(key, static_cast<int32_t>(pts.size()));
      if (fresh) pts.push_back(normalize(pts[a] + pts[b]));
      return it->second;
    };
    std::vector<std::array<int32_t, 3>> next;
    next.reserve(tris.size() * 4);
    for (const auto& tr : tris) {
      const int32_t ab = midpoint(tr[0], tr[1]), bc = midpoint(tr[1], tr[2]),
                    ca = midpoint(tr[2], tr[0]);
      next.push_back({tr[0], ab, ca});
      next.push_back({tr[1], bc, ab});
      next.push_back({tr[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    tris.swap(next);
  }
  const auto first = static_cast<int32_t>(soup.points.size());
  for (const Vec3& p : pts) soup.points.push_back(centre + p * radius);
  for (const auto& tr : tris) soup.tris.push_back({first + tr[0], first + tr[1], first + tr[2]});
}

Scene make_sphere(Params& p) {
  const int subdiv = p.get_int("subdiv", 3, 0, 8);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  TriangleSoup soup;
  append_icosphere(soup, {0, 0, 0}, 1.0, subdiv);
  return Scene::from_soup("sphere", std::move(soup), p.to_json());
}

Scene make_spheres(Params& p) {
  const int subdiv = p.get_int("subdiv", 2, 0, 7);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  TriangleSoup soup;
  const Vec3 groups[3] = {{-2.3, 0.3, 0.2}, {0, 0, 0}, {2.3, -0.2, 0.4}};
  for (const Vec3& g : groups)
    for (double r : {1.0, 0.66, 0.33}) append_icosphere(soup, g, r, subdiv);
  return Scene::from_soup("spheres", std::move(soup), p.to_json());
}

}  // namespace vob
