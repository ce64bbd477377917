// Every generator gives a valid, conforming, deterministic scene; counts match the papers.
#include <algorithm>
#include <map>

#include "datasets/generators/gap.h"
#include "datasets/generators/helix.h"
#include "harness/geometry/predicates.h"
#include "harness/scene/mesh_faces.h"
#include "tests/datasets/test_util.h"

using namespace vob;
using namespace vob::test;

namespace {
// Small but non-trivial parameters for every synthetic dataset (real data: real_data_test).
const std::map<std::string, std::vector<std::pair<std::string, std::string>>> kSmall = {
    {"gap", {{"nx", "4"}, {"ny", "3"}, {"nz", "9"}, {"gaps", "2"}}},
    {"helix", {{"cells", "3000"}}},
    {"zoo", {}},
    {"sphere", {{"subdiv", "2"}}},
    {"spheres", {{"subdiv", "1"}}},
    {"block", {{"nx", "24"}, {"ny", "20"}, {"nz", "16"}}},
    {"shells", {{"nx", "24"}, {"ny", "24"}, {"nz", "24"}}},
    {"sparse", {{"nx", "32"}, {"ny", "32"}, {"nz", "32"}}},
    {"offset", {}},
    {"slivers", {{"n", "4"}}},
    {"edge-on", {{"n", "3"}}},
    {"eye-in-plane", {}},
    {"eye-inside", {{"n", "4"}}},
    {"cycle", {}},
    {"cycle-sticks", {}},
    {"tiny", {{"count", "300"}}},
};

bool is_real(const std::string& name) {
  return name == "skull" || name.rfind("surface-", 0) == 0 || name.rfind("tet-", 0) == 0;
}

void expect_valid(const Scene& s) {
  switch (s.kind()) {
    case SceneKind::Cells: {
      EXPECT_NO_THROW(validate_cell_mesh(s.mesh(), s.name()));
      EXPECT_NO_THROW(build_mesh_faces(s.mesh(), s.name()));
      EXPECT_EQ(s.mesh().scalars.size(), s.mesh().num_points()) << "every point needs a scalar";
      break;
    }
    case SceneKind::Triangles: EXPECT_NO_THROW(validate_triangle_soup(s.soup(), s.name())); break;
    case SceneKind::Voxels: EXPECT_NO_THROW(validate_voxel_grid(s.grid(), s.name())); break;
  }
  EXPECT_GT(s.num_primitives(), 0u);
}
}  // namespace

TEST(Generators, EverySyntheticDatasetIsListedHere) {
  for (const auto& info : dataset_registry())
    if (!is_real(info.name)) {
      EXPECT_TRUE(kSmall.count(info.name)) << info.name << " has no small test";
    }
}

TEST(Generators, EveryDatasetIsValidAtSmallSize) {
  for (const auto& [name, params] : kSmall) {
    SCOPED_TRACE(name);
    const Scene s = make(name, params);
    EXPECT_EQ(s.kind(), find_dataset(name).kind);
    EXPECT_EQ(s.name(), name);
    expect_valid(s);
  }
}

TEST(Generators, DefaultsOfTheSmallDatasetsAreValid) {
  for (const char* name : {"helix", "zoo", "sphere", "spheres", "block", "shells", "sparse", "offset",
                           "slivers", "edge-on", "eye-in-plane", "eye-inside", "cycle", "tiny"}) {
    SCOPED_TRACE(name);
    expect_valid(make(name));
  }
}

TEST(Generators, ParameterCornersAreValid) {
  const std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> corners = {
      {"gap", {{"nx", "1"}, {"ny", "1"}, {"nz", "1"}}},
      {"gap", {{"nx", "2"}, {"ny", "3"}, {"nz", "96"}, {"gaps", "95"}}},
      {"helix", {{"turns", "20"}, {"cells", "2160"}}},
      {"helix", {{"turns", "1"}, {"cells", "108"}}},
      {"offset", {{"offset", "1e9"}}},
      {"offset", {{"offset", "-1e9"}, {"shape", "gap"}}},
      {"slivers", {{"n", "20"}, {"flatness", "1e-12"}}},
      {"slivers", {{"n", "1"}, {"flatness", "0.25"}}},
      {"cycle", {{"cells", "6"}, {"twist", "30"}}},
      {"cycle", {{"cells", "6"}, {"twist", "5"}}},
      {"cycle", {{"cells", "64"}, {"twist", "30"}}},
      {"cycle", {{"cells", "64"}, {"twist", "5"}}},
      {"tiny", {{"count", "1"}, {"size", "0.05"}}},
      {"tiny", {{"count", "20000"}, {"size", "1e-9"}}},
      {"edge-on", {{"n", "1"}}},
      {"eye-inside", {{"n", "2"}}},
      {"eye-in-plane", {{"n", "4"}}},
      {"sphere", {{"subdiv", "0"}}},
      {"block", {{"nx", "2"}, {"ny", "2"}, {"nz", "2"}}},
      {"sparse", {{"blobs", "0"}, {"nx", "8"}, {"ny", "8"}, {"nz", "8"}}},
  };
  for (const auto& [name, params] : corners) {
    std::string trace = name;
    for (const auto& [k, v] : params) trace += " " + k + "=" + v;
    SCOPED_TRACE(trace);
    expect_valid(make(name, params));
  }
}

TEST(Generators, Deterministic) {
  for (const auto& [name, params] : kSmall) {
    SCOPED_TRACE(name);
    const Scene a = make(name, params), b = make(name, params);
    if (a.kind() == SceneKind::Cells) {
      EXPECT_TRUE(a.mesh().points == b.mesh().points);
      EXPECT_EQ(a.mesh().conn, b.mesh().conn);
      EXPECT_EQ(a.mesh().scalars, b.mesh().scalars);
    } else if (a.kind() == SceneKind::Triangles) {
      EXPECT_TRUE(a.soup().points == b.soup().points);
      EXPECT_EQ(a.soup().tris, b.soup().tris);
    } else {
      EXPECT_EQ(a.grid().values, b.grid().values);
    }
  }
}

TEST(Generators, ZooHasThePapersCellCounts) {
  const Scene s = make("zoo");
  std::map<CellType, int> n;
  for (CellType t : s.mesh().types) ++n[t];
  EXPECT_EQ(n[CellType::Tetra], 240);
  EXPECT_EQ(n[CellType::Pyramid], 960);
  EXPECT_EQ(n[CellType::Wedge], 1200);
  EXPECT_EQ(n[CellType::Hexahedron], 4800);
  const Scene s2 = make("zoo", {{"scale", "2"}});
  EXPECT_EQ(s2.mesh().num_cells(), 7200u * 8);
  expect_valid(s2);
  // Six disconnected spheres: no face is shared across spheres, each is closed.
  const MeshFaces f = build_mesh_faces(s.mesh(), "zoo");
  EXPECT_EQ(f.boundary.size(), 6u * (2 * 20 + 20 * 8));
}

TEST(Generators, GapHasSixTetsPerHexahedron) {
  for (auto [nx, ny, nz, g] : {std::array{3, 4, 5, 0}, std::array{2, 2, 7, 6}, std::array{5, 1, 3, 1}}) {
    const Scene s = make("gap", {{"nx", std::to_string(nx)}, {"ny", std::to_string(ny)},
                                 {"nz", std::to_string(nz)}, {"gaps", std::to_string(g)}});
    EXPECT_EQ(s.mesh().num_cells(), size_t(6) * nx * ny * nz);
    expect_valid(s);
  }
}

TEST(Generators, GapsAddBoundaryFacesAndEmptySpace) {
  const Scene a = make("gap", {{"nx", "5"}, {"ny", "4"}, {"nz", "12"}, {"gaps", "0"}});
  const Scene b = make("gap", {{"nx", "5"}, {"ny", "4"}, {"nz", "12"}, {"gaps", "3"}});
  const MeshFaces fa = build_mesh_faces(a.mesh(), "a"), fb = build_mesh_faces(b.mesh(), "b");
  EXPECT_EQ(a.mesh().num_cells(), b.mesh().num_cells());
  // Each gap adds two slab ends of 2 triangles per hexahedron face.
  EXPECT_EQ(fb.boundary.size(), fa.boundary.size() + 3 * 2 * 2 * 5 * 4);
  EXPECT_DOUBLE_EQ(b.bounds().hi.z - a.bounds().hi.z, 3 * kGapWidth);
}

TEST(Generators, HelixMeetsItsTargetWithinTenPercent) {
  for (int target : {324, 400, 1000, 5000, 20000, 123456}) {
    const HelixResolution r = helix_resolution(target, 3);
    EXPECT_NEAR(double(r.cells()), target, 0.1 * target) << target;
  }
  for (int target : {1000000, 4500000}) {  // the paper's sizes, without building them
    const HelixResolution r = helix_resolution(target, 3);
    EXPECT_NEAR(double(r.cells()), target, 0.01 * target) << target;
  }
  const Scene s = make("helix", {{"cells", "5000"}});
  EXPECT_NEAR(double(s.mesh().num_cells()), 5000, 500);
  expect_valid(make("helix", {{"cells", "324"}}));  // the smallest helix is still valid
  expect_valid(make("helix", {{"cells", "700"}, {"turns", "1"}}));
}

TEST(Generators, HelixTubesHaveDistinctScalarsAndEmptySpaceBetween) {
  const Scene s = make("helix", {{"cells", "2000"}});
  const CellMesh& m = s.mesh();
  // Inner tube: radius from the axis <= 1.36 and scalars <= 0.3; outer: >= 1.8 and >= 0.7.
  for (size_t i = 0; i < m.num_points(); ++i) {
    const double r = std::hypot(m.points[i].x, m.points[i].y);
    if (m.scalars[i] <= 0.3)
      EXPECT_LT(r, 1.37);
    else
      EXPECT_TRUE(m.scalars[i] >= 0.7 && r > 1.79) << i;
  }
}

TEST(Generators, SphereTrianglesFaceOutwards) {
  const Scene s = make("sphere", {{"subdiv", "2"}});
  EXPECT_EQ(s.soup().num_triangles(), 20u * 16);
  for (const auto& t : s.soup().tris) {
    const Vec3 a = s.soup().points[t[0]], b = s.soup().points[t[1]], c = s.soup().points[t[2]];
    EXPECT_GT(dot(cross(b - a, c - a), a + b + c), 0);
  }
}

TEST(Generators, VolumesHaveTheirDensity) {
  auto fraction = [](const Scene& s) { return double(s.num_primitives()) / s.grid().num_voxels(); };
  EXPECT_GT(fraction(make("block")), 0.3);
  const double shells = fraction(make("shells"));
  EXPECT_GT(shells, 0.05);
  EXPECT_LT(shells, 0.3);
  EXPECT_LT(fraction(make("sparse")), 0.05);
  EXPECT_GT(fraction(make("sparse")), 0.002);
}

TEST(Generators, SliversAreNearlyFlat) {
  const Scene s = make("slivers", {{"n", "3"}, {"flatness", "1e-9"}});
  const CellMesh& m = s.mesh();
  int flat = 0;
  for (size_t c = 0; c < m.num_cells(); ++c) {
    const int32_t* p = m.cell_points(c);
    const Vec3 a = m.points[p[0]];
    const double vol = dot(cross(m.points[p[1]] - a, m.points[p[2]] - a), m.points[p[3]] - a);
    if (vol < 1e-8) ++flat;
  }
  EXPECT_EQ(flat, 9);
}

TEST(Generators, OffsetMovesCoordinatesFarFromTheOrigin) {
  const Scene s = make("offset");
  EXPECT_GT(s.bounds().lo.x, 1e7 - 10);
  EXPECT_GT(make("offset", {{"shape", "gap"}}).bounds().lo.z, 1e7 - 1);
}

TEST(Generators, TinyCellsAreSmallerThanAPixel) {
  const Scene s = make("tiny");
  EXPECT_EQ(s.mesh().num_cells(), 2000u);
  const double pixel = 2 * s.bounds().radius() / 512;  // view set framing at 512x512
  for (size_t c = 0; c < s.mesh().num_cells(); c += 97) {
    Aabb b;
    for (int q = 0; q < 4; ++q) b.add(s.mesh().points[s.mesh().cell_points(c)[q]]);
    EXPECT_LT(length(b.hi - b.lo), 0.5 * pixel);
  }
}

TEST(Generators, UnknownOrOutOfRangeParametersAreInputErrors) {
  std::string e = input_error([] { make("gap", {{"nq", "3"}}); });
  EXPECT_TRUE(contains(e, "gap: parameter nq: is not a known parameter")) << e;
  e = input_error([] { make("gap", {{"gaps", "96"}}); });
  EXPECT_TRUE(contains(e, "gap: parameter gaps")) << e;
  e = input_error([] { make("gap", {{"nz", "5"}, {"gaps", "5"}}); });
  EXPECT_TRUE(contains(e, "gaps need nz > gaps")) << e;
  e = input_error([] { make("helix", {{"cells", "100"}}); });
  EXPECT_TRUE(contains(e, "helix: parameter cells")) << e;
  e = input_error([] { make("zoo", {{"scale", "0"}}); });
  EXPECT_TRUE(contains(e, "zoo: parameter scale: 0 is not in [1, 10]")) << e;
  e = input_error([] { make("sphere", {{"subdiv", "two"}}); });
  EXPECT_TRUE(contains(e, "is not an integer")) << e;
  e = input_error([] { make("cycle-sticks", {{"n", "2"}}); });
  EXPECT_TRUE(contains(e, "parameter n: is not a known parameter")) << e;
  e = input_error([] { make("tiny", {{"count", "1000"}, {"size", "0.05"}}); });
  EXPECT_TRUE(contains(e, "tiny: parameter size")) << e;
  e = input_error([] { find_dataset("nope"); });
  EXPECT_TRUE(contains(e, "nope: unknown dataset")) << e;
}

TEST(Generators, RegistryNamesAreUniqueAndDescribed) {
  std::vector<std::string> names;
  for (const auto& info : dataset_registry()) {
    names.push_back(info.name);
    EXPECT_FALSE(info.summary.empty()) << info.name;
    EXPECT_TRUE(info.make) << info.name;
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
  for (const char* hard : {"offset", "slivers", "edge-on", "eye-in-plane", "eye-inside", "cycle",
                           "cycle-sticks", "tiny"})
    EXPECT_TRUE(find_dataset(hard).hard_case) << hard;
  EXPECT_GE(std::count_if(names.begin(), names.end(), [](const std::string& n) { return n.rfind("tet-", 0) == 0; }), 5);
}
