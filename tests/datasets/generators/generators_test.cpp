// Every generator gives a valid, conforming, deterministic scene; counts match the papers.
#include <algorithm>
#include <map>

#include "datasets/generators/gap.h"
#include "datasets/generators/helix.h"
#include "harness/geometry/predicates.h"
#include "harness/oracle/sequences.h"
#include "harness/scene/mesh_faces.h"
#include "harness/view/view_set.h"
#include "tests/support/test_util.h"

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
    {"touching-conforming", {{"n", "4"}}},
    {"touching-shifted", {{"n", "4"}}},
    {"touching-rotated", {{"n", "4"}}},
    {"touching-overhang", {{"n", "4"}}},
    {"touching-edge", {{"n", "4"}}},
    {"touching-hex", {{"n", "4"}}},
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
      {"helix", {{"turns", "20"}, {"cells", "3240"}}},  // the smallest helix of 20 turns
      {"helix", {{"turns", "1"}, {"cells", "162"}}},
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
      {"touching-conforming", {{"n", "1"}}},
      {"touching-shifted", {{"n", "1"}}},
      {"touching-rotated", {{"n", "1"}, {"angle", "-180"}}},
      {"touching-rotated", {{"n", "7"}, {"angle", "180"}}},
      {"touching-overhang", {{"n", "1"}}},
      {"touching-edge", {{"n", "1"}}},
      {"touching-hex", {{"n", "1"}}},
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
  EXPECT_EQ(helix_min_cells(1), 162);
  EXPECT_EQ(helix_min_cells(20), 3240);
  for (int target : {486, 600, 1000, 5000, 20000, 123456}) {
    const HelixResolution r = helix_resolution(target, 3);
    EXPECT_NEAR(double(r.cells()), target, 0.1 * target) << target;
  }
  // The paper's sizes (helix450k .. helix4.5), without building them.
  for (int target : {450000, 1050000, 1485000, 2370000, 3570000, 4500000}) {
    const HelixResolution r = helix_resolution(target, 3);
    EXPECT_NEAR(double(r.cells()), target, 0.01 * target) << target;
  }
  const Scene s = make("helix", {{"cells", "5000"}});
  EXPECT_NEAR(double(s.mesh().num_cells()), 5000, 500);
  expect_valid(make("helix", {{"cells", "486"}}));  // the smallest helix is still valid
  expect_valid(make("helix", {{"cells", "700"}, {"turns", "1"}}));
}

namespace {
// Distance from p to the helix centre line of `turns` turns: a coarse scan, then a
// ternary search around the best sample (the distance is unimodal there).
double centre_line_distance(Vec3 p, int turns) {
  const double span = 2 * 3.14159265358979323846 * turns;
  const int n = 400 * turns;
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (length(p - helix_centre(span * i / n)) < length(p - helix_centre(span * best / n))) best = i;
  double lo = span * std::max(0, best - 1) / n, hi = span * std::min(n, best + 1) / n;
  for (int it = 0; it < 100; ++it) {
    const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
    if (length(p - helix_centre(a)) < length(p - helix_centre(b)))
      hi = b;
    else
      lo = a;
  }
  return length(p - helix_centre(0.5 * (lo + hi)));
}
}  // namespace

TEST(Generators, HelixInnerTubeRunsInsideTheHollowOuterOne) {
  const Scene s = make("helix", {{"cells", "2000"}});
  const CellMesh& m = s.mesh();
  const HelixShape shape;
  // Inner tube: scalars 0.2..0.3 within inner_radius of the centre line; outer: 0.7..0.8
  // between the bore and outer_radius.
  for (size_t i = 0; i < m.num_points(); ++i) {
    const double d = centre_line_distance(m.points[i], 3);
    if (m.scalars[i] <= 0.3 + 1e-12) {
      EXPECT_GE(m.scalars[i], 0.2 - 1e-12) << i;
      EXPECT_LT(d, shape.inner_radius + 1e-9) << i;
    } else {
      EXPECT_TRUE(m.scalars[i] >= 0.7 - 1e-12 && m.scalars[i] <= 0.8 + 1e-12) << i;
      EXPECT_GT(d, shape.hole_radius - 1e-9) << i;
      EXPECT_LT(d, shape.outer_radius + 1e-9) << i;
    }
  }
}

TEST(Generators, HelixTubesAreSeparatedByAThinFilmOfEmptySpace) {
  // Along every pixel ray of 14 views, an inner (green) cell and an outer (pink) cell met
  // in turn are apart: the tubes never touch. And the film is thin somewhere in every view:
  // ray-gaps between the tubes far shorter than the cells (why MPVONC fails, helix.h).
  const HelixShape shape;
  const double film = shape.hole_radius - shape.inner_radius;
  for (const char* cells : {"486", "3000"}) {
    const Scene s = make("helix", {{"cells", cells}});
    const CellMesh& m = s.mesh();
    for (int v = 0; v < 14; ++v) {
      const Camera cam = fibonacci_view(s.bounds(), 14, v, {.width = 128, .height = 128});
      const CellSequences seq = raster_cell_sequences(s, cam, 1);
      double min_gap = 1e9;
      for (int64_t i = 0; i < seq.num_samples(); ++i) {
        const auto sp = seq.at(i);
        for (size_t k = 0; k + 1 < sp.size(); ++k)
          if ((m.cell_scalar(sp[k].cell) < 0.5) != (m.cell_scalar(sp[k + 1].cell) < 0.5))
            min_gap = std::min(min_gap, sp[k + 1].t_in - sp[k].t_out);
      }
      // A triangle bore (the coarsest) is a chord polygon: the film is half as thick there.
      EXPECT_GT(min_gap, 0.25 * film) << cells << " cells, view " << v;
      EXPECT_LT(min_gap, 10 * film) << cells << " cells, view " << v;
    }
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
