#include "datasets/generators/real_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "datasets/io/data_cache.h"
#include "datasets/io/inr_reader.h"
#include "datasets/io/off_io.h"
#include "datasets/io/tetgen_bridge.h"
#include "harness/scene/input_error.h"

namespace vob {

const std::vector<RealModel>& real_models() {
  // Checked with TetGen 1.5 (Debian 12). Left out: bones, cow, pig, bull, camel, elk (self-
  // intersecting: tetgen aborts), mushroom, head (open: 0 tetrahedra).
  static const std::vector<RealModel> models = {
      {"elephant", "data/meshes/elephant.off", 1.414, "elephant (5.6k triangles)"},
      {"knot", "data/meshes/knot1.off", 1.414, "trefoil knot tube (6.4k triangles)"},
      {"femur", "data/meshes/femur.off", 1.414, "human femur (7.8k triangles)"},
      {"hand", "data/meshes/hand.off", 1.414, "hand (2.4k triangles)"},
      {"blobby", "data/meshes/blobby.off", 1.414, "blobby genus-3 shape (4k triangles)"},
      {"triceratops", "data/meshes/triceratops.off", 1.414, "triceratops (5.7k triangles)"},
      {"armadillo", "data/meshes/armadillo.off", 2.0, "Stanford armadillo (52k triangles)"},
  };
  return models;
}

Scene make_skull(Params& p) {
  const double threshold = p.get_double("threshold", 0.5, 0.0, 5.0);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  const std::string member = "data/images/skull_2.9.inr";
  VoxelGrid g = read_inr(cgal_data_file(member));
  g.threshold = static_cast<float>(threshold);
  return Scene::from_grid("skull", std::move(g), p.to_json());
}

namespace {
TriangleSoup load_surface(const RealModel& m) {
  TriangleSoup s = read_off(cgal_data_file(m.member));
  validate_triangle_soup(s, m.member);
  return s;
}
}  // namespace

Scene make_surface(const RealModel& m, Params& p) {
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  return Scene::from_soup("surface-" + m.name, load_surface(m), p.to_json());
}

Scene make_tet(const RealModel& m, Params& p) {
  const double quality = p.get_double("quality", m.quality, 1.05, 100.0);
  const double maxvol = p.get_double("maxvol", 0.0, 0.0, 1.0);
  if (p.dry_run()) return {};  // parameters checked, nothing generated
  const TriangleSoup surface = load_surface(m);
  check_closed_surface(surface, m.member);
  const Aabb box = surface.bounds();
  const Vec3 ext = box.hi - box.lo;
  // TetGen switch numbers are plain decimals (no exponent): 6 significant digits.
  auto plain = [](double v) {
    char buf[64];
    const int decimals = std::max(0, 5 - static_cast<int>(std::floor(std::log10(v))));
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string t = buf;
    if (t.find('.') != std::string::npos) {
      while (t.back() == '0') t.pop_back();
      if (t.back() == '.') t.pop_back();
    }
    return t;
  };
  // Built by appending: "a" + std::string trips a GCC 12 -Wrestrict false positive.
  std::string sw = "pq";
  sw += plain(quality);
  if (maxvol > 0) {  // maxvol is a fraction of the bounding-box volume
    sw += 'a';
    sw += plain(maxvol * ext.x * ext.y * ext.z);
  }
  CellMesh mesh = tetrahedralize_surface(surface, m.member, sw, "tet-" + m.name);
  const Vec3 c = box.center();
  const double r = box.radius();
  mesh.scalars.resize(mesh.num_points());
  for (size_t i = 0; i < mesh.num_points(); ++i)
    mesh.scalars[i] = 0.2 + 0.8 * std::max(0.0, 1.0 - length(mesh.points[i] - c) / r);
  // TetGen's files are input like any other: check face sharing as load_input does.
  build_mesh_faces(mesh, "tet-" + m.name);
  nlohmann::json params = p.to_json();
  params["tetgen"] = sw;
  return Scene::from_mesh("tet-" + m.name, std::move(mesh), params);
}

}  // namespace vob
