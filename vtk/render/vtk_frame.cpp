#include "vtk/render/vtk_frame.h"

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <vtkCamera.h>
#include <vtkColorTransferFunction.h>
#include <vtkOpenGLProjectedTetrahedraMapper.h>
#include <vtkPiecewiseFunction.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVisibilitySort.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

namespace vob {

VtkStage::VtkStage(vtkUnstructuredGrid* tets, double lo, double hi, double radius, int width, int height)
    : window_(vtkSmartPointer<vtkRenderWindow>::New()), tets_(tets), width_(width), height_(height) {
  window_->SetOffScreenRendering(1);
  window_->SetMultiSamples(0);  // one sample at each pixel centre, as vobench's oracle
  window_->SetSize(width, height);
  window_->AddRenderer(renderer_);
  renderer_->SetBackground(0, 0, 0);
  // vobench's compositor's transfer function (harness/render/compositor.cpp): green to pink,
  // extinction (2.4 / radius) (0.25 + 0.75 s), here as opacity per bounding radius.
  vtkNew<vtkColorTransferFunction> colour;
  vtkNew<vtkPiecewiseFunction> opacity;
  const double span = hi > lo ? hi - lo : 1.0;
  for (int k = 0; k <= 4; ++k) {
    const double s = k / 4.0, v = lo + s * span;
    colour->AddRGBPoint(v, 0.15 + s * 0.85, 0.80 - s * 0.45, 0.30 + s * 0.40);
    opacity->AddPoint(v, 1 - std::exp(-2.4 * (0.25 + 0.75 * s)));
  }
  property_->SetColor(colour);
  property_->SetScalarOpacity(opacity);
  property_->SetScalarOpacityUnitDistance(radius > 0 ? radius : 1.0);
  property_->SetInterpolationTypeToLinear();
  property_->ShadeOff();
}

VtkStage::~VtkStage() = default;

int VtkStage::add_sorter(vtkVisibilitySort* sort) {
  vtkNew<vtkOpenGLProjectedTetrahedraMapper> mapper;
  mapper->SetInputData(tets_);
  mapper->SetVisibilitySort(sort);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->SetProperty(property_);
  volume->VisibilityOff();
  renderer_->AddVolume(volume);
  volumes_.push_back(volume);
  return static_cast<int>(volumes_.size()) - 1;
}

double VtkStage::render(int i, const Camera& c) {
  if (c.width != width_ || c.height != height_) {  // fitted views have sizes of their own
    width_ = c.width;
    height_ = c.height;
    window_->SetSize(width_, height_);
  }
  for (size_t k = 0; k < volumes_.size(); ++k) volumes_[k]->SetVisibility(static_cast<int>(k) == i);
  vtkCamera* vc = renderer_->GetActiveCamera();
  vc->SetPosition(c.eye.x, c.eye.y, c.eye.z);
  vc->SetFocalPoint(c.target.x, c.target.y, c.target.z);
  vc->SetViewUp(c.up.x, c.up.y, c.up.z);
  vc->SetParallelProjection(c.ortho);
  if (c.ortho)
    vc->SetParallelScale(0.5 * c.ortho_height);
  else
    vc->SetViewAngle(c.fov_deg);
  renderer_->ResetCameraClippingRange();
  const auto t0 = std::chrono::steady_clock::now();
  window_->Render();
  window_->WaitForCompletion();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

RgbImage VtkStage::capture() {
  vtkNew<vtkUnsignedCharArray> px;
  window_->GetPixelData(0, 0, width_ - 1, height_ - 1, 0, px, 0);
  RgbImage img;
  img.width = width_;
  img.height = height_;
  const auto* p = px->GetPointer(0);
  img.rgb.assign(p, p + 3 * static_cast<size_t>(width_) * height_);
  return img;
}

std::string VtkStage::gl_renderer() {
  std::istringstream in(window_->ReportCapabilities() ? window_->ReportCapabilities() : "");
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("OpenGL renderer string:", 0) == 0 || line.rfind("OpenGL version string:", 0) == 0)
      out += (out.empty() ? "" : "; ") + line.substr(line.find_first_not_of(' ', line.find(':') + 1));
  return out;
}

}  // namespace vob
