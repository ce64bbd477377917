// build_mesh_faces against a plain map-based reference: the same faces, numbered in order of
// first appearance (cell by cell, local faces in order), the same vertex loops, cells and
// per-cell face ids, and the same error lines, on generated meshes of every cell type, as
// generated and with cells and points shuffled.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <string>

#include "harness/bench/suite.h"
#include "harness/scene/input_error.h"
#include "harness/scene/mesh_faces.h"

using namespace vob;

namespace {

// The reference: one map from sorted point ids to face id. Errors as build_mesh_faces words
// them, thrown as InputError.
MeshFaces reference_faces(const CellMesh& mesh, const std::string& source) {
  MeshFaces out;
  const size_t nc = mesh.num_cells();
  out.cell_face_offsets.assign(1, 0);
  std::map<std::array<int32_t, 4>, int32_t> index;
  std::vector<int> parity;
  for (size_t c = 0; c < nc; ++c) {
    const LocalFaces& lf = cell_local_faces(mesh.types[c]);
    const int32_t* p = mesh.cell_points(c);
    for (int f = 0; f < lf.count; ++f) {
      const int n = lf.size[f];
      std::vector<int32_t> loop(n);
      for (int i = 0; i < n; ++i) loop[i] = p[lf.v[f][i]];
      std::array<int32_t, 4> key{-1, -1, -1, -1};
      std::vector<int32_t> sorted = loop;
      std::sort(sorted.begin(), sorted.end());
      std::copy(sorted.begin(), sorted.end(), key.begin());
      // Parity: is the loop, rotated to start at its smallest id, increasing at its second?
      const size_t m = std::min_element(loop.begin(), loop.end()) - loop.begin();
      const int par = loop[(m + 1) % n] < loop[(m + n - 1) % n] ? 1 : -1;
      const auto it = index.find(key);
      if (it == index.end()) {
        index.emplace(key, static_cast<int32_t>(out.cell0.size()));
        out.cell_faces.push_back(static_cast<int32_t>(out.cell0.size()));
        out.verts.insert(out.verts.end(), loop.begin(), loop.end());
        out.offsets.push_back(static_cast<int32_t>(out.verts.size()));
        out.cell0.push_back(static_cast<int32_t>(c));
        out.cell1.push_back(-1);
        parity.push_back(par);
        continue;
      }
      const int32_t id = it->second;
      std::string face = "face (";
      for (int i = 0; i < n; ++i) face += (i ? "," : "") + std::to_string(key[i]);
      face += ")";
      if (out.cell1[id] != -1)
        throw InputError(source, face,
                         "shared by more than two cells (" + std::to_string(out.cell0[id]) + ", " +
                             std::to_string(out.cell1[id]) + ", " + std::to_string(c) + ")");
      if (parity[id] == par)
        throw InputError(source, face,
                         "cells " + std::to_string(out.cell0[id]) + " and " + std::to_string(c) +
                             " lie on the same side of it (overlapping cells)");
      out.cell1[id] = static_cast<int32_t>(c);
      out.cell_faces.push_back(id);
    }
    out.cell_face_offsets.push_back(static_cast<int32_t>(out.cell_faces.size()));
  }
  for (size_t f = 0; f < out.cell0.size(); ++f)
    if (out.cell1[f] < 0) out.boundary.push_back(static_cast<int32_t>(f));
  return out;
}

void expect_same(const MeshFaces& a, const MeshFaces& b, const std::string& what) {
  EXPECT_EQ(a.offsets, b.offsets) << what;
  EXPECT_EQ(a.verts, b.verts) << what;
  EXPECT_EQ(a.cell0, b.cell0) << what;
  EXPECT_EQ(a.cell1, b.cell1) << what;
  EXPECT_EQ(a.cell_face_offsets, b.cell_face_offsets) << what;
  EXPECT_EQ(a.cell_faces, b.cell_faces) << what;
  EXPECT_EQ(a.boundary, b.boundary) << what;
}

CellMesh dataset(const std::string& name, std::map<std::string, std::string> set = {}) {
  DatasetSpec spec;
  spec.name = name;
  spec.set = std::move(set);
  return make_scene(spec).mesh();
}

std::string error_of(const std::function<MeshFaces()>& build) {
  try {
    build();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MeshFaces, MatchesTheMapReferenceOnGeneratedMeshes) {
  const std::vector<std::pair<std::string, CellMesh>> meshes{
      {"zoo (hexahedra, wedges, pyramids, tetrahedra)", dataset("zoo")},
      {"helix 20k", dataset("helix", {{"cells", "20000"}})},
      {"helix 20k shuffled", dataset("helix", {{"cells", "20000"}, {"shuffle", "7"}})},
      {"gap shuffled", dataset("gap", {{"nx", "10"}, {"ny", "10"}, {"nz", "20"}, {"shuffle", "3"}})},
  };
  for (const auto& [what, mesh] : meshes) {
    const MeshFaces got = build_mesh_faces(mesh, what);
    EXPECT_GT(got.num_faces(), 1000u) << what;
    EXPECT_LT(got.boundary.size(), got.num_faces()) << what;
    expect_same(got, reference_faces(mesh, what), what);
  }
}

// A face of three cells and a pair of overlapping cells, each appended to a shuffled helix:
// the same line as the reference's, naming the same face and cells.
TEST(MeshFaces, ErrorsNameTheFaceAndCellsOfTheReference) {
  const CellMesh helix = dataset("helix", {{"cells", "2000"}, {"shuffle", "5"}});
  const MeshFaces faces = build_mesh_faces(helix, "h");
  const size_t shared = faces.cell1.size() - 1 - std::distance(faces.cell1.rbegin(),
      std::find_if(faces.cell1.rbegin(), faces.cell1.rend(), [](int32_t c) { return c >= 0; }));
  ASSERT_GE(faces.cell1[shared], 0);
  const int32_t* v = faces.face_points(shared);
  ASSERT_EQ(faces.face_size(shared), 3);
  // A third cell on the shared face, on cell1's side (its apex at cell1's centroid).
  CellMesh three = helix;
  three.points.push_back(helix.cell_centroid(faces.cell1[shared]));
  const int32_t apex = static_cast<int32_t>(three.points.size() - 1);
  three.add_cell(CellType::Tetra, {v[0], v[2], v[1], apex});
  // A cell on the same side of a boundary face as its own cell.
  const size_t b = faces.boundary[faces.boundary.size() / 2];
  const int32_t* w = faces.face_points(b);
  CellMesh overlap = helix;
  overlap.points.push_back(helix.cell_centroid(faces.cell0[b]));
  const int32_t inner = static_cast<int32_t>(overlap.points.size() - 1);
  overlap.add_cell(CellType::Tetra, {w[0], w[2], w[1], inner});
  for (const CellMesh* m : {&three, &overlap}) {
    const std::string got = error_of([&] { return build_mesh_faces(*m, "bad.vtu"); });
    EXPECT_NE(got, "");
    EXPECT_EQ(got, error_of([&] { return reference_faces(*m, "bad.vtu"); }));
  }
  EXPECT_NE(error_of([&] { return build_mesh_faces(three, "bad.vtu"); }).find("shared by more than two cells"),
            std::string::npos);
  EXPECT_NE(error_of([&] { return build_mesh_faces(overlap, "bad.vtu"); }).find("overlapping cells"),
            std::string::npos);
}

// A point id past the points (validate_cell_mesh refuses it first; this is the backstop):
// one error naming the cell, no out-of-bounds write.
TEST(MeshFaces, PointIdOutOfRangeIsAnError) {
  CellMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  m.add_cell(CellType::Tetra, {1, 2, 3, 9});
  EXPECT_NE(error_of([&] { return build_mesh_faces(m, "m.vtu"); }).find("m.vtu: cell 1: point id out of range"),
            std::string::npos);
}
