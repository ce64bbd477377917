// Scene: one primitive kind (cells, triangles or voxels) with a name, the parameters that
// made it, and derived structures built on first request, each timed and counted in bytes.
// Copies share the data and the cache; fresh() shares the data with an empty cache, so that
// every orderer pays for the structures it asks for.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/scene/cell_mesh.h"
#include "harness/scene/exterior_faces.h"
#include "harness/scene/mesh_faces.h"
#include "harness/scene/triangle_soup.h"
#include "harness/scene/voxel_grid.h"

namespace vob {

enum class SceneKind { Cells, Triangles, Voxels };
const char* scene_kind_name(SceneKind k);     // "cells", "triangles", "voxels"
SceneKind parse_scene_kind(const std::string& s);

struct DerivedStat {
  std::string name;
  double seconds = 0;
  size_t bytes = 0;
};

class Scene {
 public:
  Scene() = default;
  static Scene from_mesh(std::string name, CellMesh mesh, nlohmann::json params = {});
  static Scene from_soup(std::string name, TriangleSoup soup, nlohmann::json params = {});
  static Scene from_grid(std::string name, VoxelGrid grid, nlohmann::json params = {});

  const std::string& name() const { return name_; }
  const nlohmann::json& params() const { return params_; }
  SceneKind kind() const { return kind_; }
  const CellMesh& mesh() const;
  const TriangleSoup& soup() const;
  const VoxelGrid& grid() const;
  size_t num_primitives() const;  // cells, triangles or significant voxels
  Aabb bounds() const;
  size_t bytes() const;           // the primitive data itself

  // Derived structures (cells). The first call builds and records a DerivedStat.
  const MeshFaces& faces() const;
  const FacePlanes& face_planes() const;
  const Centroids& cell_centroids() const;
  const Centroids& face_centroids() const;
  const ExteriorFaces& exterior_faces() const;  // the boundary faces, oriented outward
  // Derived structures (voxels).
  const std::vector<int32_t>& significant_voxels() const;
  const std::vector<VoxelRun>& significant_runs() const;

  std::vector<DerivedStat> derived_stats() const;
  size_t derived_bytes() const;
  Scene fresh() const;

 private:
  struct Cache;
  Scene(std::string name, nlohmann::json params, SceneKind kind);
  std::string name_;
  nlohmann::json params_;
  SceneKind kind_ = SceneKind::Cells;
  std::shared_ptr<const CellMesh> mesh_;
  std::shared_ptr<const TriangleSoup> soup_;
  std::shared_ptr<const VoxelGrid> grid_;
  std::shared_ptr<Cache> cache_;
};

}  // namespace vob
