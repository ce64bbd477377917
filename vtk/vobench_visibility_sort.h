// vobVisibilitySort: any vobench orderer (a registered one, "name:k=v,...", or another
// program through the external-orderer protocol) behind VTK's vtkVisibilitySort, so that
// vtkProjectedTetrahedraMapper::SetVisibilitySort draws cells in vobench's order.
//
// - Input (a vtkUnstructuredGrid of linear volume cells) becomes a vobench scene and the
//   orderer is prepared again whenever the input or its modified time changes.
// - Camera, ModelTransform and the image size become a vobench camera (harness/view/
//   camera.h): position, focal point, view up, view angle or parallel scale, and the size of
//   the renderer given with SetRenderer (else SetImageSize), so an image-exact orderer is
//   exact at the rendered resolution. A rigid or uniformly scaled model transform moves the
//   camera into the data's frame; any other affine one moves the data (a new prepare). The
//   camera's own ModelTransformMatrix and UserViewTransform join the model transform.
//   Settings vobench's centred camera cannot express (WindowCenter, ViewShear / oblique
//   angles, off-axis, explicit projection or aspect, a UserTransform, stereo) are refused
//   by name: an order for other rays would be silently wrong.
// - The orderer runs when that camera differs from the last one (or on every
//   InitTraversal with SetAlwaysOrder(true), for timing); GetNextCells hands the order out
//   MaxCellsReturned cells at a time, back to front or front to back.
// A failure (bad input, a broken external sorter) is a vtkErrorMacro, GetLastError() says
// it and GetNextCells returns nullptr at once: the mapper draws nothing rather than a
// wrong order.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkVisibilitySort.h>
#include <vtkWeakPointer.h>

class vtkIdTypeArray;
class vtkRenderer;

namespace vob {
struct Camera;
}

class vobVisibilitySort : public vtkVisibilitySort {
 public:
  static vobVisibilitySort* New();
  vtkTypeMacro(vobVisibilitySort, vtkVisibilitySort);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The orderer: "xmpvo", "sxmpvo", "centroid:key=view", ... (vobench list). False, with
  // GetLastError(), for an unknown name, bad parameters or an orderer of other scenes.
  bool SetOrderer(const std::string& spec);
  // Another program as the orderer (README "Judging your own sorter"): started through
  // /bin/sh on the first prepare, `timeout` seconds per answer.
  bool SetExternalCommand(const std::string& command, double timeout = 60.0);
  // The view index sent to an external sorter with the next orders (default -1).
  void SetViewIndex(int index) { this->ViewIndex = index; }

  // Where the image size comes from: the renderer's size in pixels when a renderer is set
  // (held weakly), else the size given here.
  void SetRenderer(vtkRenderer* renderer);
  void SetImageSize(int width, int height);
  // Order on every InitTraversal even for an unchanged camera (frame timing).
  void SetAlwaysOrder(bool on) { this->AlwaysOrder = on; }

  void InitTraversal() override;
  vtkIdTypeArray* GetNextCells() override;

  // What the last traversal used and cost.
  const std::string& GetLastError() const { return this->LastError; }
  const std::vector<int32_t>& GetBackToFrontOrder() const { return this->Order; }
  const vob::Camera& GetLastCamera() const;
  double GetLastPrepareSeconds() const { return this->PrepareSeconds; }
  // Seconds in the orderer and in handing out cells since the last InitTraversal.
  double GetLastSortSeconds() const { return this->SortSeconds; }
  int64_t GetLastCycles() const { return this->Cycles; }
  int GetNumberOfPrepares() const { return this->Prepares; }
  int GetNumberOfOrders() const { return this->Orders; }
  bool GetObjectExact() const;
  bool GetImageExact() const;

 protected:
  vobVisibilitySort();
  ~vobVisibilitySort() override;

 private:
  vobVisibilitySort(const vobVisibilitySort&) = delete;
  void operator=(const vobVisibilitySort&) = delete;
  bool Prepare(const double* data_to_world);
  bool CurrentCamera(vob::Camera& out, double* data_to_world);
  void Fail(const std::string& message);
  // After S->orderer was replaced: its claims, nothing prepared, no error. Returns true.
  bool Adopted();

  struct State;
  std::unique_ptr<State> S;
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkNew<vtkIdTypeArray> Batch;
  std::vector<int32_t> Order;
  std::string LastError;
  size_t Next = 0;
  int ViewIndex = -1;
  int Width = 0, Height = 0;
  bool AlwaysOrder = false;
  double PrepareSeconds = 0, SortSeconds = 0;
  int64_t Cycles = 0;
  int Prepares = 0, Orders = 0;
};
