#include "harness/scene/scene.h"

#include <chrono>
#include <optional>
#include <stdexcept>

#include "harness/scene/input_error.h"

namespace vob {

const char* scene_kind_name(SceneKind k) {
  switch (k) {
    case SceneKind::Cells: return "cells";
    case SceneKind::Triangles: return "triangles";
    case SceneKind::Voxels: return "voxels";
  }
  return "?";
}

SceneKind parse_scene_kind(const std::string& s) {
  if (s == "cells") return SceneKind::Cells;
  if (s == "triangles") return SceneKind::Triangles;
  if (s == "voxels") return SceneKind::Voxels;
  throw InputError("scene kind '" + s + "' is not one of cells, triangles, voxels");
}

struct Scene::Cache {
  std::optional<MeshFaces> faces;
  std::optional<FacePlanes> planes;
  std::optional<Centroids> cell_centroids, face_centroids;
  std::optional<ExteriorFaces> exterior;
  std::optional<std::vector<int32_t>> voxels;
  std::optional<std::vector<VoxelRun>> runs;
  std::vector<DerivedStat> stats;
};

namespace {
template <class T, class F>
const T& build_once(std::optional<T>& slot, std::vector<DerivedStat>& stats, const char* name,
                    F&& make, size_t (*bytes)(const T&)) {
  if (!slot) {
    const auto t0 = std::chrono::steady_clock::now();
    slot.emplace(make());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    stats.push_back({name, s, bytes(*slot)});
  }
  return *slot;
}
template <class T>
size_t vec_bytes(const std::vector<T>& v) { return v.capacity() * sizeof(T); }
}  // namespace

// The from_* factories differ only in which primitives the scene holds.
Scene::Scene(std::string name, nlohmann::json params, SceneKind kind)
    : name_(std::move(name)), params_(std::move(params)), kind_(kind), cache_(std::make_shared<Cache>()) {}

Scene Scene::from_mesh(std::string name, CellMesh mesh, nlohmann::json params) {
  Scene s(std::move(name), std::move(params), SceneKind::Cells);
  s.mesh_ = std::make_shared<const CellMesh>(std::move(mesh));
  return s;
}
Scene Scene::from_soup(std::string name, TriangleSoup soup, nlohmann::json params) {
  Scene s(std::move(name), std::move(params), SceneKind::Triangles);
  s.soup_ = std::make_shared<const TriangleSoup>(std::move(soup));
  return s;
}
Scene Scene::from_grid(std::string name, VoxelGrid grid, nlohmann::json params) {
  Scene s(std::move(name), std::move(params), SceneKind::Voxels);
  s.grid_ = std::make_shared<const VoxelGrid>(std::move(grid));
  return s;
}

const CellMesh& Scene::mesh() const {
  if (!mesh_) throw std::logic_error("scene '" + name_ + "' has no cell mesh");
  return *mesh_;
}
const TriangleSoup& Scene::soup() const {
  if (!soup_) throw std::logic_error("scene '" + name_ + "' has no triangle soup");
  return *soup_;
}
const VoxelGrid& Scene::grid() const {
  if (!grid_) throw std::logic_error("scene '" + name_ + "' has no voxel grid");
  return *grid_;
}

size_t Scene::num_primitives() const {
  switch (kind_) {
    case SceneKind::Cells: return mesh().num_cells();
    case SceneKind::Triangles: return soup().num_triangles();
    case SceneKind::Voxels: return significant_voxels().size();
  }
  return 0;
}

namespace {
// f applied to the scene's primitives, whichever kind they are (R{} for no kind).
template <class R, class F>
R on_primitives(const Scene& s, F&& f) {
  switch (s.kind()) {
    case SceneKind::Cells: return f(s.mesh());
    case SceneKind::Triangles: return f(s.soup());
    case SceneKind::Voxels: return f(s.grid());
  }
  return R{};
}
}  // namespace

Aabb Scene::bounds() const {
  return on_primitives<Aabb>(*this, [](const auto& p) { return p.bounds(); });
}

size_t Scene::bytes() const {
  return on_primitives<size_t>(*this, [](const auto& p) { return p.bytes(); });
}

const MeshFaces& Scene::faces() const {
  return build_once<MeshFaces>(
      cache_->faces, cache_->stats, "unique faces", [&] { return build_mesh_faces(mesh(), name_); },
      +[](const MeshFaces& f) { return f.bytes(); });
}
const FacePlanes& Scene::face_planes() const {
  const MeshFaces& f = faces();
  return build_once<FacePlanes>(
      cache_->planes, cache_->stats, "face planes", [&] { return build_face_planes(mesh(), f); },
      +[](const FacePlanes& p) { return p.bytes(); });
}
const Centroids& Scene::cell_centroids() const {
  return build_once<Centroids>(
      cache_->cell_centroids, cache_->stats, "cell centroids",
      [&] { return build_cell_centroids(mesh()); }, +[](const Centroids& c) { return c.bytes(); });
}
const Centroids& Scene::face_centroids() const {
  const MeshFaces& f = faces();
  return build_once<Centroids>(
      cache_->face_centroids, cache_->stats, "face centroids",
      [&] { return build_face_centroids(mesh(), f); }, +[](const Centroids& c) { return c.bytes(); });
}
const ExteriorFaces& Scene::exterior_faces() const {
  const MeshFaces& f = faces();
  return build_once<ExteriorFaces>(
      cache_->exterior, cache_->stats, "exterior faces",
      [&] { return build_exterior_faces(mesh(), f); }, +[](const ExteriorFaces& e) { return e.bytes(); });
}
const std::vector<int32_t>& Scene::significant_voxels() const {
  return build_once<std::vector<int32_t>>(
      cache_->voxels, cache_->stats, "significant voxels",
      [&] { return vob::significant_voxels(grid()); },
      +[](const std::vector<int32_t>& v) { return vec_bytes(v); });
}
const std::vector<VoxelRun>& Scene::significant_runs() const {
  return build_once<std::vector<VoxelRun>>(
      cache_->runs, cache_->stats, "significant runs", [&] { return vob::significant_runs(grid()); },
      +[](const std::vector<VoxelRun>& v) { return vec_bytes(v); });
}

std::vector<DerivedStat> Scene::derived_stats() const { return cache_->stats; }
size_t Scene::derived_bytes() const {
  size_t b = 0;
  for (const auto& s : cache_->stats) b += s.bytes;
  return b;
}

Scene Scene::fresh() const {
  Scene s = *this;
  s.cache_ = std::make_shared<Cache>();
  return s;
}

}  // namespace vob
