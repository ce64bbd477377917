// vobVisibilitySort (vtk/vobench_visibility_sort.h): the cells it hands VTK are the
// orderer's own order for the same camera, in batches, both directions; it prepares on a
// new input and orders on a new camera only; a model transform is followed.
#include <gtest/gtest.h>

#include <functional>

#include <vtkCamera.h>
#include <vtkIdTypeArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkTransform.h>
#include <vtkUnstructuredGrid.h>

#include "datasets/datasets.h"
#include "harness/bench/external_orderer.h"
#include "harness/bench/registry.h"
#include "harness/view/view_set.h"
#include "vtk/vobench_visibility_sort.h"
#include "vtk/vtk_scene.h"

namespace vob {
namespace {

void set_camera(vtkCamera* vc, const Camera& c) {
  vc->SetPosition(c.eye.x, c.eye.y, c.eye.z);
  vc->SetFocalPoint(c.target.x, c.target.y, c.target.z);
  vc->SetViewUp(c.up.x, c.up.y, c.up.z);
  vc->SetViewAngle(c.fov_deg);
}

std::vector<int32_t> traverse(vobVisibilitySort* sort, size_t* largest_batch = nullptr) {
  std::vector<int32_t> out;
  sort->InitTraversal();
  while (vtkIdTypeArray* ids = sort->GetNextCells()) {
    if (largest_batch) *largest_batch = std::max(*largest_batch, size_t(ids->GetNumberOfTuples()));
    for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i) out.push_back(static_cast<int32_t>(ids->GetValue(i)));
  }
  return out;
}

std::vector<int32_t> own_order(const std::string& spec, const Scene& scene, const Camera& cam) {
  auto orderer = make_orderer(spec);
  PhaseClock clock;
  orderer->prepare(scene.fresh(), clock);
  return orderer->order(cam, clock).order;
}

Scene helix_2000() {
  Params p("helix");
  p.set("cells", "2000");
  return make_dataset("helix", p);
}

struct Helix {
  Scene scene = helix_2000();
  vtkSmartPointer<vtkUnstructuredGrid> grid = grid_from_scene(scene);
  std::vector<Camera> views = fibonacci_views(scene.bounds(), 14, {300, 200});
};

class AdapterOrder : public ::testing::TestWithParam<const char*> {};

TEST_P(AdapterOrder, EqualsTheOrderersOwnOrderInEveryViewAndDirection) {
  Helix h;
  vtkNew<vobVisibilitySort> sort;
  ASSERT_TRUE(sort->SetOrderer(GetParam())) << sort->GetLastError();
  vtkNew<vtkCamera> cam;
  sort->SetInput(h.grid);
  sort->SetCamera(cam);
  sort->SetImageSize(300, 200);
  sort->SetMaxCellsReturned(333);
  for (const Camera& view : h.views) {
    set_camera(cam, view);
    sort->SetDirectionToBackToFront();
    size_t batch = 0;
    const auto got = traverse(sort, &batch);
    ASSERT_TRUE(sort->GetLastError().empty()) << sort->GetLastError();
    EXPECT_EQ(got, own_order(GetParam(), h.scene, view));
    EXPECT_EQ(batch, 333u);
    sort->SetDirectionToFrontToBack();
    auto reversed = traverse(sort);
    std::reverse(reversed.begin(), reversed.end());
    EXPECT_EQ(reversed, got);
  }
  EXPECT_EQ(sort->GetNumberOfPrepares(), 1);
  EXPECT_EQ(sort->GetNumberOfOrders(), 14);  // the direction alone is no new camera
}
INSTANTIATE_TEST_SUITE_P(Orderers, AdapterOrder, ::testing::Values("xmpvo", "sxmpvo", "centroid"));

TEST(Adapter, RunsAnExternalSorterAsTheOrderersProtocolDoes) {
  Helix h;
  vtkNew<vobVisibilitySort> sort;
  ASSERT_TRUE(sort->SetExternalCommand(VOB_TEST_EXTERNAL_SORTER, 60));
  vtkNew<vtkCamera> cam;
  sort->SetInput(h.grid);
  sort->SetCamera(cam);
  sort->SetImageSize(300, 200);
  auto direct = make_external_orderer(VOB_TEST_EXTERNAL_SORTER, 60);
  PhaseClock clock;
  direct->prepare(h.scene, clock);
  std::vector<std::vector<int32_t>> orders;
  for (int v : {0, 7}) {
    set_camera(cam, h.views[v]);
    sort->SetViewIndex(v);
    set_external_view_index(*direct, v);
    const auto got = traverse(sort);
    ASSERT_TRUE(sort->GetLastError().empty()) << sort->GetLastError();
    EXPECT_EQ(got, direct->order(h.views[v], clock).order) << "view " << v;
    orders.push_back(got);
  }
  EXPECT_NE(orders[0], orders[1]);  // the camera reached the sorter
}

TEST(Adapter, PreparesOnANewInputAndOrdersOnANewCameraOnly) {
  Helix h;
  vtkNew<vobVisibilitySort> sort;
  ASSERT_TRUE(sort->SetOrderer("mpvo"));
  vtkNew<vtkCamera> cam;
  set_camera(cam, h.views[0]);
  sort->SetInput(h.grid);
  sort->SetCamera(cam);
  sort->SetImageSize(300, 200);
  traverse(sort);
  traverse(sort);
  EXPECT_EQ(sort->GetNumberOfOrders(), 1);
  set_camera(cam, h.views[1]);
  traverse(sort);
  EXPECT_EQ(sort->GetNumberOfOrders(), 2);
  sort->SetImageSize(301, 200);  // another resolution is another camera
  traverse(sort);
  EXPECT_EQ(sort->GetNumberOfOrders(), 3);
  EXPECT_EQ(sort->GetNumberOfPrepares(), 1);
  h.grid->Modified();
  traverse(sort);
  EXPECT_EQ(sort->GetNumberOfPrepares(), 2);
  sort->SetAlwaysOrder(true);
  traverse(sort);
  EXPECT_EQ(sort->GetNumberOfOrders(), 5);
}

TEST(Adapter, FollowsAModelTransform) {
  Helix h;
  // x' = 2 R x + t with R a quarter turn about z: exact in binary, so the camera comes back
  // to the data's frame bit for bit.
  vtkNew<vtkMatrix4x4> m;
  const double e[16] = {0, -2, 0, 8, 2, 0, 0, -4, 0, 0, 2, 0.5, 0, 0, 0, 1};
  m->DeepCopy(e);
  const auto to_world = [&](Vec3 p, double w) {
    return Vec3{-2 * p.y + 8 * w, 2 * p.x - 4 * w, 2 * p.z + 0.5 * w};
  };
  for (const char* spec : {"xmpvo", "bsp-xmpvo"}) {
    vtkNew<vobVisibilitySort> sort;
    ASSERT_TRUE(sort->SetOrderer(spec));
    vtkNew<vtkCamera> cam;
    sort->SetInput(h.grid);
    sort->SetCamera(cam);
    sort->SetModelTransform(m);
    sort->SetImageSize(300, 200);
    for (int v : {0, 5, 9}) {
      Camera world = h.views[v];
      world.eye = to_world(world.eye, 1);
      world.target = to_world(world.target, 1);
      world.up = to_world(world.up, 0) * 0.5;
      set_camera(cam, world);
      EXPECT_EQ(traverse(sort), own_order(spec, h.scene, h.views[v])) << spec << " view " << v;
      EXPECT_EQ(sort->GetLastCamera().eye, h.views[v].eye);
    }
    EXPECT_EQ(sort->GetNumberOfPrepares(), 1);  // a similarity moves the camera, not the data
  }
}

TEST(Adapter, MovesTheDataForAnAffineModelTransform) {
  Helix h;
  vtkNew<vtkMatrix4x4> m;  // x' = (x, 2y, z/2) + (1, 0, 0): no similarity, exact in binary
  const double e[16] = {1, 0, 0, 1, 0, 2, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1};
  m->DeepCopy(e);
  CellMesh world_mesh = h.scene.mesh();
  for (Vec3& p : world_mesh.points) p = {p.x + 1, 2 * p.y, 0.5 * p.z};
  const Scene world = Scene::from_mesh("world", world_mesh);
  const std::vector<Camera> views = fibonacci_views(world.bounds(), 14, {300, 200});
  vtkNew<vobVisibilitySort> sort;
  ASSERT_TRUE(sort->SetOrderer("xmpvo"));
  vtkNew<vtkCamera> cam;
  sort->SetInput(h.grid);
  sort->SetCamera(cam);
  sort->SetModelTransform(m);
  sort->SetImageSize(300, 200);
  for (int v : {2, 11}) {
    set_camera(cam, views[v]);
    EXPECT_EQ(traverse(sort), own_order("xmpvo", world, views[v])) << "view " << v;
  }
  EXPECT_EQ(sort->GetNumberOfPrepares(), 1);
  vtkNew<vtkMatrix4x4> identity;  // back to the data as they are: a new prepare
  sort->SetModelTransform(identity);
  traverse(sort);
  EXPECT_EQ(sort->GetNumberOfPrepares(), 2);
}

// VTK camera settings vobench's camera cannot express are refused by name, never ordered
// for the wrong rays; back at their defaults the order is the orderer's own again.
TEST(Adapter, RefusesCameraSettingsItCannotMap) {
  Helix h;
  const std::vector<std::pair<std::string, std::function<void(vtkCamera*, bool)>>> settings = {
      {"WindowCenter", [](vtkCamera* c, bool on) { c->SetWindowCenter(on ? 0.25 : 0, 0); }},
      {"ViewShear", [](vtkCamera* c, bool on) { c->SetViewShear(0, on ? 0.1 : 0, 1); }},
      {"ViewShear", [](vtkCamera* c, bool on) { on ? c->SetObliqueAngles(30, 63.4) : c->SetViewShear(0, 0, 1); }},
      {"UseOffAxisProjection", [](vtkCamera* c, bool on) { c->SetUseOffAxisProjection(on); }},
      {"UseExplicitProjectionTransformMatrix",
       [](vtkCamera* c, bool on) { c->SetUseExplicitProjectionTransformMatrix(on); }},
      {"UseExplicitAspectRatio", [](vtkCamera* c, bool on) { c->SetUseExplicitAspectRatio(on); }},
      {"UserTransform", [](vtkCamera* c, bool on) {
         vtkNew<vtkTransform> t;
         c->SetUserTransform(on ? t.Get() : nullptr);
       }}};
  vtkNew<vobVisibilitySort> sort;
  ASSERT_TRUE(sort->SetOrderer("xmpvo"));
  vtkNew<vtkCamera> cam;
  sort->SetInput(h.grid);
  sort->SetCamera(cam);
  sort->SetImageSize(300, 200);
  set_camera(cam, h.views[4]);
  for (const auto& [name, set] : settings) {
    set(cam, true);
    EXPECT_TRUE(traverse(sort).empty()) << name;
    EXPECT_NE(sort->GetLastError().find(name), std::string::npos) << sort->GetLastError();
    set(cam, false);
    EXPECT_EQ(traverse(sort), own_order("xmpvo", h.scene, h.views[4])) << name;
  }
}

TEST(Adapter, MapsParallelProjectionAndTheCamerasModelTransform) {
  Helix h;
  vtkNew<vobVisibilitySort> sort;
  ASSERT_TRUE(sort->SetOrderer("sxmpvo"));
  vtkNew<vtkCamera> cam;
  sort->SetInput(h.grid);
  sort->SetCamera(cam);
  sort->SetImageSize(300, 200);
  for (int v : {1, 6}) {
    Camera ortho = h.views[v];
    ortho.ortho = true;
    ortho.ortho_height = 0.6 * length(h.scene.bounds().hi - h.scene.bounds().lo);
    set_camera(cam, ortho);
    cam->ParallelProjectionOn();
    cam->SetParallelScale(0.5 * ortho.ortho_height);
    EXPECT_EQ(traverse(sort), own_order("sxmpvo", h.scene, ortho)) << "view " << v;
    EXPECT_NE(traverse(sort), own_order("sxmpvo", h.scene, h.views[v])) << "perspective is another order";
  }
  cam->ParallelProjectionOff();
  // The camera's model matrix moves every prop: x' = R x + t, a quarter turn about z.
  const double e[16] = {0, -1, 0, 3, 1, 0, 0, -1, 0, 0, 1, 0.5, 0, 0, 0, 1};
  cam->SetModelTransformMatrix(e);
  const auto to_world = [](Vec3 p, double w) { return Vec3{-p.y + 3 * w, p.x - w, p.z + 0.5 * w}; };
  Camera world = h.views[3];
  world.eye = to_world(world.eye, 1);
  world.target = to_world(world.target, 1);
  world.up = to_world(world.up, 0);
  set_camera(cam, world);
  EXPECT_EQ(traverse(sort), own_order("sxmpvo", h.scene, h.views[3]));
  EXPECT_EQ(sort->GetLastCamera().eye, h.views[3].eye);
}

TEST(Adapter, RefusesClearly) {
  vtkNew<vobVisibilitySort> sort;
  EXPECT_FALSE(sort->SetOrderer("no-such-orderer"));
  EXPECT_NE(sort->GetLastError().find("no-such-orderer"), std::string::npos);
  EXPECT_FALSE(sort->SetOrderer("btf"));  // voxels
  Helix h;
  ASSERT_TRUE(sort->SetOrderer("xmpvo"));
  vtkNew<vtkCamera> cam;
  sort->SetInput(h.grid);
  sort->SetCamera(cam);
  sort->InitTraversal();  // no image size
  EXPECT_EQ(sort->GetNextCells(), nullptr);
  EXPECT_NE(sort->GetLastError().find("image size"), std::string::npos);
}

}  // namespace
}  // namespace vob
