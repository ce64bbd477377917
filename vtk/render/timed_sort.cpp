#include "vtk/render/timed_sort.h"

#include <chrono>

#include <vtkObjectFactory.h>

vtkStandardNewMacro(vobTimedSort);

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
}  // namespace

void vobTimedSort::InitTraversal() {
  const auto t0 = Clock::now();
  this->Inner->SetInput(this->Input);
  this->Inner->SetCamera(this->Camera);
  this->Inner->SetModelTransform(this->ModelTransform);
  this->Inner->SetDirection(this->Direction);
  this->Inner->SetMaxCellsReturned(this->MaxCellsReturned);
  this->Inner->InitTraversal();
  this->Seconds = since(t0);
}

vtkIdTypeArray* vobTimedSort::GetNextCells() {
  const auto t0 = Clock::now();
  vtkIdTypeArray* ids = this->Inner->GetNextCells();
  this->Seconds += since(t0);
  return ids;
}
