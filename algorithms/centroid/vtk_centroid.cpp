#include "algorithms/centroid/vtk_centroid.h"

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellCenterDepthSort.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <cstring>

namespace vob {
namespace {

vtkSmartPointer<vtkUnstructuredGrid> to_vtk_grid(const CellMesh& mesh) {
  vtkNew<vtkDoubleArray> coords;
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(static_cast<vtkIdType>(mesh.num_points()));
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  std::memcpy(coords->GetPointer(0), mesh.points.data(), mesh.num_points() * sizeof(Vec3));
  vtkNew<vtkPoints> points;
  points->SetData(coords);

  vtkNew<vtkTypeInt32Array> offsets, conn;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(mesh.offsets.size()));
  std::memcpy(offsets->GetPointer(0), mesh.offsets.data(), mesh.offsets.size() * 4);
  conn->SetNumberOfTuples(static_cast<vtkIdType>(mesh.conn.size()));
  std::memcpy(conn->GetPointer(0), mesh.conn.data(), mesh.conn.size() * 4);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, conn);

  vtkNew<vtkUnsignedCharArray> types;  // our CellType values are VTK's codes
  types->SetNumberOfTuples(static_cast<vtkIdType>(mesh.num_cells()));
  for (size_t c = 0; c < mesh.num_cells(); ++c)
    types->SetValue(static_cast<vtkIdType>(c), static_cast<unsigned char>(mesh.types[c]));

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(types, cells);
  return grid;
}

class VtkCentroidOrderer final : public Orderer {
 public:
  explicit VtkCentroidOrderer(int chunk) : chunk_(chunk) {}
  Claims claims() const override { return {}; }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    {
      auto p = clock.phase("vtk unstructured grid");
      grid_ = to_vtk_grid(scene.mesh());
    }
    auto p = clock.phase("vtk cell centres");
    // Set everything that touches the sorter's MTime now: a later change would make VTK
    // recompute the cell centres inside order().
    sorter_ = vtkSmartPointer<vtkCellCenterDepthSort>::New();
    camera_ = vtkSmartPointer<vtkCamera>::New();
    sorter_->SetInput(grid_);
    sorter_->SetCamera(camera_);
    sorter_->SetDirectionToBackToFront();
    sorter_->SetMaxCellsReturned(chunk_);
    const Aabb box = scene.mesh().bounds();
    const Vec3 c = box.empty() ? Vec3{} : box.center();
    camera_->SetFocalPoint(c.x, c.y, c.z);
    camera_->SetPosition(c.x, c.y, c.z + 1.0);
    sorter_->InitTraversal();  // computes the cell centres once
    while (sorter_->GetNextCells()) {
    }
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    {
      auto p = clock.phase("vtk camera");
      camera_->SetPosition(view.eye.x, view.eye.y, view.eye.z);
      camera_->SetFocalPoint(view.target.x, view.target.y, view.target.z);
      camera_->SetViewUp(view.up.x, view.up.y, view.up.z);
      camera_->SetParallelProjection(view.ortho);
      if (view.ortho)
        camera_->SetParallelScale(0.5 * view.ortho_height);
      else
        camera_->SetViewAngle(view.fov_deg);
    }
    // GetNextCells' quicksort takes its pivots from vtkMath's generator, so cells of equal
    // depth came out in an order that depended on the frames before: seeded here, the
    // order is a function of the view (outside the timed phase).
    vtkMath::RandomSeed(1);
    auto p = clock.phase("vtk depth sort");
    out.order.reserve(static_cast<size_t>(grid_->GetNumberOfCells()));
    sorter_->InitTraversal();
    while (vtkIdTypeArray* ids = sorter_->GetNextCells()) {
      const vtkIdType n = ids->GetNumberOfTuples();
      const vtkIdType* v = ids->GetPointer(0);
      for (vtkIdType i = 0; i < n; ++i) out.order.push_back(static_cast<int32_t>(v[i]));
    }
    return out;
  }

  size_t bytes() const override {
    // VTK's copy of the mesh and the sorter's centres, depths and ids.
    const vtkIdType n = grid_ ? grid_->GetNumberOfCells() : 0;
    const size_t grid_bytes = grid_ ? grid_->GetActualMemorySize() * 1024ull : 0;
    return grid_bytes + static_cast<size_t>(n) * (3 * sizeof(float) + sizeof(float) +
                                                  sizeof(vtkIdType));
  }

 private:
  int chunk_;
  vtkSmartPointer<vtkUnstructuredGrid> grid_;
  vtkSmartPointer<vtkCellCenterDepthSort> sorter_;
  vtkSmartPointer<vtkCamera> camera_;
};

}  // namespace

OrdererInfo vtk_centroid_orderer_info() {
  return {"vtk-centroid", SceneKind::Cells,
          "VTK's vtkCellCenterDepthSort: cell centres by depth along the view direction "
          "(heuristic peer)",
          {ParamSpec::integer("chunk", 1000, 1, 2147483647,
                              "cells per GetNextCells call (1000: what vtkProjectedTetrahedraMapper "
                              "asks for; 2147483647: one piece)")},
          [](const ResolvedParams& p) -> std::unique_ptr<Orderer> {
            return std::make_unique<VtkCentroidOrderer>(p.get_int("chunk"));
          }};
}

}  // namespace vob
