#include "vtk/vobench_visibility_sort.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include <vtkCamera.h>
#include <vtkDataSet.h>
#include <vtkHomogeneousTransform.h>
#include <vtkIdTypeArray.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>

#include "harness/bench/external_orderer.h"
#include "harness/bench/registry.h"
#include "harness/scene/input_error.h"
#include "vtk/vtk_scene.h"

vtkStandardNewMacro(vobVisibilitySort);

using Matrix = std::array<double, 16>;  // row-major 4x4, VTK's element order

struct vobVisibilitySort::State {
  std::unique_ptr<vob::Orderer> orderer;
  vob::Claims claims;
  vob::Scene scene;
  bool prepared = false, failed = false;
  vtkDataSet* input = nullptr;  // the input the scene was made from, and its time then
  vtkMTimeType input_time = 0;
  Matrix data_to_world{};       // applied to the points of `scene` (identity or general)
  vob::Camera camera;
  bool has_camera = false;
};

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Matrix identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Matrix to_matrix(vtkMatrix4x4* v) {
  Matrix m;
  std::copy(&v->Element[0][0], &v->Element[0][0] + 16, m.begin());
  return m;
}

Matrix times(const Matrix& a, const Matrix& b) {
  Matrix c{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) c[4 * i + j] += a[4 * i + k] * b[4 * k + j];
  return c;
}

// A vtkCamera setting that moves or shears the image window away from the centred one
// vobench's camera describes ("" when there is none): sampling those rays with vobench's
// camera would give an order for other rays, so they are refused, not ignored.
std::string unmapped_camera_setting(vtkCamera* c) {
  const double* wc = c->GetWindowCenter();
  const double* shear = c->GetViewShear();
  const auto num = [](double v) { return std::to_string(v); };
  if (wc[0] != 0 || wc[1] != 0) return "WindowCenter (" + num(wc[0]) + ", " + num(wc[1]) + ") is not (0, 0)";
  if (shear[0] != 0 || shear[1] != 0)
    return "ViewShear (" + num(shear[0]) + ", " + num(shear[1]) + ") is not (0, 0) (oblique angles)";
  if (c->GetUseOffAxisProjection()) return "UseOffAxisProjection is on";
  if (c->GetUseExplicitProjectionTransformMatrix()) return "UseExplicitProjectionTransformMatrix is on";
  if (c->GetUserTransform()) return "a UserTransform (projection side) is set";
  if (c->GetUseExplicitAspectRatio()) return "UseExplicitAspectRatio is on";
  if (c->GetStereo()) return "stereo rendering is on (each eye sees a sheared frustum)";
  return "";
}

vob::Vec3 apply(const Matrix& m, vob::Vec3 p, double w) {
  return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3] * w, m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7] * w,
          m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11] * w};
}

// s > 0 when the linear part is s times a rotation (no reflection), else 0.
double similarity_scale(const Matrix& m) {
  const vob::Vec3 c0{m[0], m[4], m[8]}, c1{m[1], m[5], m[9]}, c2{m[2], m[6], m[10]};
  const double s2 = dot(c0, c0), tol = 1e-12 * s2;
  if (!(s2 > 0) || std::abs(dot(c1, c1) - s2) > tol || std::abs(dot(c2, c2) - s2) > tol ||
      std::abs(dot(c0, c1)) > tol || std::abs(dot(c0, c2)) > tol || std::abs(dot(c1, c2)) > tol ||
      dot(cross(c0, c1), c2) <= 0)
    return 0;
  return std::sqrt(s2);
}
}  // namespace

vobVisibilitySort::vobVisibilitySort() : S(std::make_unique<State>()) { this->Batch->SetNumberOfComponents(1); }
vobVisibilitySort::~vobVisibilitySort() = default;

void vobVisibilitySort::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Prepares: " << this->Prepares << ", Orders: " << this->Orders << "\n";
}

bool vobVisibilitySort::SetOrderer(const std::string& spec) {
  try {
    if (vob::spec_orderer(spec).kind != vob::SceneKind::Cells)
      throw vob::InputError(spec, "orderer", "orders no cells (vtkVisibilitySort sorts cells)");
    this->S->orderer = vob::make_orderer(spec);
  } catch (const std::exception& e) {
    this->Fail(e.what());
    return false;
  }
  return this->Adopted();
}

bool vobVisibilitySort::SetExternalCommand(const std::string& command, double timeout) {
  try {
    this->S->orderer = vob::make_external_orderer(command, timeout);
  } catch (const std::exception& e) {
    this->Fail(e.what());
    return false;
  }
  return this->Adopted();
}

bool vobVisibilitySort::Adopted() {
  this->S->claims = this->S->orderer->claims();
  this->S->prepared = this->S->has_camera = this->S->failed = false;
  this->LastError.clear();
  this->Modified();
  return true;
}

void vobVisibilitySort::SetRenderer(vtkRenderer* renderer) { this->Renderer = renderer; }
void vobVisibilitySort::SetImageSize(int width, int height) {
  this->Width = width;
  this->Height = height;
}

const vob::Camera& vobVisibilitySort::GetLastCamera() const { return this->S->camera; }
bool vobVisibilitySort::GetObjectExact() const { return this->S->claims.object_exact; }
bool vobVisibilitySort::GetImageExact() const { return this->S->claims.image_exact; }

void vobVisibilitySort::Fail(const std::string& message) {
  this->LastError = message;
  this->Order.clear();
  this->S->has_camera = false;  // no order for any camera until the next one succeeds
  vtkErrorMacro(<< message);
}

bool vobVisibilitySort::Prepare(const double* data_to_world) {
  State& s = *this->S;
  const auto t0 = std::chrono::steady_clock::now();
  s.input = this->Input;
  s.input_time = this->Input->GetMTime();
  std::copy(data_to_world, data_to_world + 16, s.data_to_world.begin());
  s.prepared = s.has_camera = false;
  try {
    vob::Scene scene = vob::scene_from_vtk(this->Input, "vtkVisibilitySort input");
    if (s.data_to_world != identity()) {
      vob::CellMesh mesh = scene.mesh();
      for (vob::Vec3& p : mesh.points) p = apply(s.data_to_world, p, 1);
      scene = vob::scene_from_vtk(vob::grid_from_scene(vob::Scene::from_mesh("", mesh)),
                                  "vtkVisibilitySort input (model transform applied)");
    }
    s.scene = scene;
    vob::PhaseClock clock;
    s.orderer->prepare(s.scene, clock);
  } catch (const std::exception& e) {
    s.failed = true;
    this->Fail(e.what());
    return false;
  }
  s.prepared = true;
  s.failed = false;
  ++this->Prepares;
  this->PrepareSeconds = seconds_since(t0);
  return true;
}

// The camera in the frame of the prepared scene, and the matrix the scene needs.
bool vobVisibilitySort::CurrentCamera(vob::Camera& c, double* data_to_world) {
  Matrix m = this->ModelTransform ? to_matrix(this->ModelTransform) : identity();
  int w = this->Width, h = this->Height;
  if (this->Renderer) {
    const int* size = this->Renderer->GetSize();
    w = size[0];
    h = size[1];
  }
  if (w <= 0 || h <= 0) {
    this->Fail("the image size is unknown: call SetRenderer or SetImageSize");
    return false;
  }
  vtkCamera* cam = this->Camera;
  if (const std::string why = unmapped_camera_setting(cam); !why.empty()) {
    this->Fail("camera: " + why + ": vobench's camera has no such projection (the order would be for other rays)");
    return false;
  }
  // The camera's own model transform and user view transform act on every prop before
  // the view transform (ModelView = Setup * UserView * CameraModel): data to world as well.
  if (vtkMatrix4x4* cm = cam->GetModelTransformMatrix()) m = times(to_matrix(cm), m);
  if (vtkHomogeneousTransform* uv = cam->GetUserViewTransform()) m = times(to_matrix(uv->GetMatrix()), m);
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1) {
    this->Fail("the model transform is projective (last row not 0 0 0 1)");
    return false;
  }
  double p[3], f[3], u[3];
  cam->GetPosition(p);
  cam->GetFocalPoint(f);
  cam->GetViewUp(u);
  c.eye = {p[0], p[1], p[2]};
  c.target = {f[0], f[1], f[2]};
  c.up = {u[0], u[1], u[2]};
  c.width = w;
  c.height = h;
  c.ortho = cam->GetParallelProjection() != 0;
  c.ortho_height = 2 * cam->GetParallelScale();
  c.fov_deg = cam->GetViewAngle();
  if (cam->GetUseHorizontalViewAngle())  // vobench's angle is vertical
    c.fov_deg = 2 * std::atan(std::tan(c.fov_deg * M_PI / 360) * h / w) * 180 / M_PI;
  const double s = similarity_scale(m);
  if (s > 0) {  // the camera into the data's frame: the data stay as they are
    vtkNew<vtkMatrix4x4> inv;
    inv->DeepCopy(m.data());
    inv->Invert();
    const Matrix im = to_matrix(inv);
    c.eye = apply(im, c.eye, 1);
    c.target = apply(im, c.target, 1);
    c.up = apply(im, c.up, 0);
    c.ortho_height /= s;
    m = identity();
  }
  std::copy(m.begin(), m.end(), data_to_world);
  try {
    c.validate();
  } catch (const std::exception& e) {
    this->Fail(std::string("camera: ") + e.what());
    return false;
  }
  return true;
}

void vobVisibilitySort::InitTraversal() {
  State& s = *this->S;
  this->Next = 0;
  this->SortSeconds = 0;
  if (!s.orderer) return this->Fail("no orderer: call SetOrderer or SetExternalCommand");
  if (!this->Input || !this->Camera) return this->Fail("no input or no camera");
  vob::Camera cam;
  Matrix m;
  if (!this->CurrentCamera(cam, m.data())) return;
  const bool new_input = s.input != this->Input || s.input_time != this->Input->GetMTime() || s.data_to_world != m;
  if (new_input && !this->Prepare(m.data())) return;
  if (!new_input && (s.failed || !s.prepared)) return this->Fail(this->LastError.empty() ? "not prepared" : this->LastError);
  const auto same = [](const vob::Camera& a, const vob::Camera& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.ortho == b.ortho &&
           a.fov_deg == b.fov_deg && a.ortho_height == b.ortho_height && a.width == b.width &&
           a.height == b.height;
  };
  if (s.has_camera && same(cam, s.camera) && !this->AlwaysOrder) return;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    vob::set_external_view_index(*s.orderer, this->ViewIndex);
    vob::PhaseClock clock;
    vob::Ordering o = s.orderer->order(cam, clock);
    if (o.order.size() != s.scene.num_primitives())
      throw std::runtime_error("the orderer returned " + std::to_string(o.order.size()) + " ids for " +
                               std::to_string(s.scene.num_primitives()) + " cells");
    this->Order = std::move(o.order);
    this->Cycles = o.cycles.cycles;
  } catch (const std::exception& e) {
    s.has_camera = false;
    return this->Fail(e.what());
  }
  s.camera = cam;
  s.has_camera = true;
  this->LastError.clear();
  ++this->Orders;
  this->SortSeconds = seconds_since(t0);
  this->LastSortTime.Modified();
}

vtkIdTypeArray* vobVisibilitySort::GetNextCells() {
  if (!this->S->has_camera || this->Next >= this->Order.size()) return nullptr;
  const auto t0 = std::chrono::steady_clock::now();
  const size_t n = std::min(this->Order.size() - this->Next, static_cast<size_t>(this->MaxCellsReturned));
  this->Batch->SetNumberOfTuples(static_cast<vtkIdType>(n));
  vtkIdType* out = this->Batch->GetPointer(0);
  const size_t total = this->Order.size();
  if (this->Direction == FRONT_TO_BACK)
    for (size_t i = 0; i < n; ++i) out[i] = this->Order[total - 1 - (this->Next + i)];
  else
    for (size_t i = 0; i < n; ++i) out[i] = this->Order[this->Next + i];
  this->Next += n;
  this->SortSeconds += seconds_since(t0);
  return this->Batch;
}
