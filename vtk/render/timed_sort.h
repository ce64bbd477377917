// A vtkVisibilitySort that times another one (VTK's vtkCellCenterDepthSort): the wrapped
// sort gets this one's input, camera, transform, direction and batch size on every
// InitTraversal, and the seconds spent in its InitTraversal and GetNextCells are summed.
#pragma once
#include <vtkSmartPointer.h>
#include <vtkVisibilitySort.h>

class vobTimedSort : public vtkVisibilitySort {
 public:
  static vobTimedSort* New();
  vtkTypeMacro(vobTimedSort, vtkVisibilitySort);
  void SetSort(vtkVisibilitySort* inner) { this->Inner = inner; }
  void InitTraversal() override;
  vtkIdTypeArray* GetNextCells() override;
  double GetLastSortSeconds() const { return this->Seconds; }

 protected:
  vobTimedSort() = default;
  ~vobTimedSort() override = default;

 private:
  vobTimedSort(const vobTimedSort&) = delete;
  void operator=(const vobTimedSort&) = delete;
  vtkSmartPointer<vtkVisibilitySort> Inner;
  double Seconds = 0;
};
