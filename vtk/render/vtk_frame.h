// The VTK side of `vobench-vtk render`: one offscreen render window (X, through Xvfb in
// tests) with one vtkOpenGLProjectedTetrahedraMapper and volume per sorter, all on the same
// tetrahedra and transfer function; a frame draws one sorter's volume for one camera.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "harness/view/camera.h"

class vtkRenderWindow;
class vtkRenderer;
class vtkUnstructuredGrid;
class vtkVisibilitySort;
class vtkVolume;
class vtkVolumeProperty;

namespace vob {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // row 0 at the bottom, as GL reads it
};

class VtkStage {
 public:
  // `tets`: the grid the mappers draw, point scalars in [lo, hi]; `radius`: the opacity's
  // unit distance (the bounding radius gives vobench's compositor's extinction).
  VtkStage(vtkUnstructuredGrid* tets, double lo, double hi, double radius, int width, int height);
  ~VtkStage();
  int add_sorter(vtkVisibilitySort* sort);  // its index
  // Draws sorter `i` alone for `camera` (the window takes the camera's size); returns the
  // seconds from Render() to the GL's completion.
  double render(int i, const Camera& camera);
  RgbImage capture();
  vtkRenderer* renderer() { return renderer_; }
  std::string gl_renderer();  // GL_RENDERER and GL_VERSION, as VTK reports them

 private:
  vtkSmartPointer<vtkRenderWindow> window_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<vtkVolumeProperty> property_;
  vtkUnstructuredGrid* tets_;
  std::vector<vtkSmartPointer<vtkVolume>> volumes_;
  int width_, height_;
};

}  // namespace vob
