// Voxel orderers (btf, wbtf, pbtf, ip-pbtf, distance-sort): complete permutations for any
// eye, the interleaving and permutation rules, and the property each order provably has:
// face-adjacent significant voxels drawn farther first (in the oracle's depth) wherever the
// theory says so.
#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/voxel/grid_traversal.h"
#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/bench/runner.h"
#include "harness/oracle/oracle.h"

namespace vob {
namespace {

// Every registered voxel orderer, plus the non-default forms.
std::vector<std::string> voxel_specs() {
  std::vector<std::string> v = {"pbtf:permute=wbtf", "ip-pbtf:interleave=explicit"};
  for (const auto& info : orderer_registry())
    if (info.kind == SceneKind::Voxels) v.push_back(info.name);
  return v;
}

Scene volume(const std::string& name, int nx, int ny, int nz) {
  Params p(name);
  p.set("nx", std::to_string(nx));
  p.set("ny", std::to_string(ny));
  p.set("nz", std::to_string(nz));
  return make_dataset(name, p);
}

// Anisotropic, off-origin, uneven dims: catches mixed-up axes and strides.
Scene odd_grid(bool empty) {
  VoxelGrid g;
  g.dims = {13, 9, 7};
  g.spacing = {1.0, 1.5, 0.75};
  g.origin = {-3, 2, 5};
  g.values.assign(g.num_voxels(), 0.0f);
  if (!empty)
    for (size_t v = 0; v < g.values.size(); ++v) g.values[v] = (v * 7919 % 5 < 3) ? 1.0f : 0.0f;
  return Scene::from_grid(empty ? "empty" : "odd", std::move(g));
}

Camera look(Vec3 eye, Vec3 target, bool ortho = false) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = std::fabs(normalize(target - eye).z) > 0.99 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  c.ortho = ortho;
  c.width = c.height = 64;
  return c;
}

// Eyes inside, on a face plane (of the box and of a voxel-centre plane), on an edge, far
// outside, and orthographic views along axes and diagonals.
std::vector<Camera> hard_eyes(const Scene& s) {
  const Aabb b = s.bounds();
  const Vec3 c = b.center(), lo = b.lo, hi = b.hi;
  const Vec3 v0 = s.grid().centre(0, 0, 0);
  return {look(c, c + Vec3{1, 0.3, 0.2}),
          look(c + Vec3{0.37, -0.21, 0.11}, c - Vec3{1, 1, 1}),
          look({lo.x, c.y, c.z}, c),                    // on the x = lo face plane
          look({v0.x, c.y + 0.1, c.z}, c),              // in the plane of the first voxel centres
          look({lo.x, lo.y, c.z}, c),                   // on an edge of the box
          look({hi.x, hi.y, hi.z}, c),                  // on a corner
          look(c + Vec3{1e9, 3e8, -2e8}, c),            // far outside
          look(c + Vec3{-20, 0.5, 0.5}, c),
          look(c + Vec3{0, 0, 30}, c, true),            // ortho straight down
          look(c + Vec3{10, -7, 5}, c, true)};
}

TEST(VoxelOrderers, RegistryHasTheVoxelOrderers) {
  for (const char* name : {"btf", "wbtf", "pbtf", "ip-pbtf", "distance-sort"})
    EXPECT_EQ(find_orderer(name).kind, SceneKind::Voxels) << name;
}

TEST(VoxelOrderers, CompletePermutationForAnyEyeAndEmptyVolume) {
  for (bool empty : {false, true}) {
    const Scene scene = odd_grid(empty);
    for (const std::string& spec : voxel_specs()) {
      PreparedOrderer p = prepare_orderer(spec, scene);
      for (const Camera& cam : hard_eyes(scene)) {
        PhaseClock clock;
        const Ordering o = p.orderer->order(cam, clock);
        EXPECT_NO_THROW(check_complete(scene, o, spec)) << spec << " eye " << cam.eye.x;
        EXPECT_EQ(o.order.size(), empty ? 0u : scene.num_primitives());
      }
    }
  }
}

TEST(VoxelOrderers, SplitCasesFollowTheEye) {
  const Scene s = odd_grid(false);
  const Aabb b = s.bounds();
  const Vec3 c = b.center();
  auto splits = [&](Vec3 eye) { return voxel::split_axes(voxel::eye_splits(s.grid(), look(eye, c + Vec3{0.1, 0, 0}))); };
  EXPECT_EQ(splits(c), 3);                                     // volume-on
  EXPECT_EQ(splits({b.hi.x + 5, c.y, c.z}), 2);                // face-on
  EXPECT_EQ(splits({b.hi.x + 5, b.hi.y + 5, c.z}), 1);         // edge-on
  EXPECT_EQ(splits({b.hi.x + 5, b.hi.y + 5, b.hi.z + 5}), 0);  // corner-on
  EXPECT_EQ(splits({1e300, -1e300, 1e300}), 0);
}

TEST(VoxelOrderers, InterleavedSequenceMergesByDistance) {
  voxel::AxisSplit a{10, 3, 2.8, 5};  // parts {0,1,2} up and {9..3} down; m2 = floor(5.6)
  const std::vector<int32_t> want = {9, 8, 7, 6, 0, 5, 1, 4, 2, 3};
  EXPECT_EQ(voxel::interleaved_sequence(a), want);
  voxel::AxisSplit whole{4, 0, -7};
  EXPECT_EQ(voxel::interleaved_sequence(whole), (std::vector<int32_t>{3, 2, 1, 0}));
}

TEST(VoxelOrderers, PermutationRuleKeepsSplitAxesInside) {
  const Scene s = odd_grid(false);
  const Vec3 c = s.bounds().center();
  // Face-on along x (x unsplit), looking mostly along y: WBTF would put y outermost, but y
  // is split, so x (the only unsplit axis) goes out.
  const Camera cam = look({s.bounds().hi.x + 1, c.y, c.z}, c + Vec3{0, 10, 0});
  const auto sp = voxel::eye_splits(s.grid(), cam);
  ASSERT_FALSE(sp[0].split());
  ASSERT_TRUE(sp[1].split());
  EXPECT_EQ(voxel::wbtf_permutation(cam)[0], 1);
  EXPECT_EQ(voxel::ip_permutation(cam, sp)[0], 0);
}

TEST(VoxelOrderers, ExplicitAndImplicitInterleavingEmitTheSameOrder) {
  for (const Scene& scene : {odd_grid(false), volume("sparse", 24, 20, 18)}) {
    PreparedOrderer ex = prepare_orderer("ip-pbtf:interleave=explicit", scene);
    PreparedOrderer im = prepare_orderer("ip-pbtf", scene);
    for (const Camera& cam : hard_eyes(scene)) {
      PhaseClock c1, c2;
      const Ordering a = ex.orderer->order(cam, c1), b = im.orderer->order(cam, c2);
      EXPECT_EQ(a.order, b.order);
      EXPECT_EQ(a.counters.at("visited"), double(scene.grid().num_voxels()));
      EXPECT_EQ(b.counters.at("visited"), double(scene.num_primitives()));
    }
  }
}

// Face-adjacent significant pairs drawn nearer first (beyond the oracle's tie tolerance).
int64_t adjacent_pairs_out_of_order(const Scene& s, const Camera& cam, const std::vector<int32_t>& order) {
  const VoxelGrid& g = s.grid();
  std::vector<int64_t> pos(g.num_voxels(), -1);
  for (size_t i = 0; i < order.size(); ++i) pos[order[i]] = int64_t(i);
  const double tol = kDepthTieRelative * (s.bounds().radius() + length(cam.eye - s.bounds().center()));
  int64_t bad = 0;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const int64_t a = g.id(i, j, k);
        if (pos[a] < 0) continue;
        const int nb[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
        for (const auto& q : nb) {
          if (q[0] >= g.dims[0] || q[1] >= g.dims[1] || q[2] >= g.dims[2]) continue;
          const int64_t b = g.id(q[0], q[1], q[2]);
          if (pos[b] < 0) continue;
          const double da = cam.depth(g.centre_of(a)), db = cam.depth(g.centre_of(b));
          const int64_t first = pos[a] < pos[b] ? a : b;
          const double df = first == a ? da : db, ds = first == a ? db : da;
          bad += ds > df + tol;  // the later one is farther
        }
      }
  return bad;
}

// Orthographic: every grid order with per-axis directions from the view direction draws
// face-adjacent voxels farther first (Frieder et al.); perspective: the PBTF traversal
// towards the eye does so inside each subvolume, and IP-PBTF's interleaving also across
// the dividing planes, so ip-pbtf holds for every eye. (pbtf holds too, since the voxel
// nearest the eye ends its part; its errors are between splats farther apart.)
TEST(VoxelOrderers, FaceAdjacentPairsInDepthOrder) {
  const Scene s = odd_grid(false);
  for (const std::string spec : {"btf", "wbtf", "pbtf", "ip-pbtf"}) {
    PreparedOrderer p = prepare_orderer(spec, s);
    for (const Camera& cam : hard_eyes(s)) {
      PhaseClock clock;
      const Ordering o = p.orderer->order(cam, clock);
      const int64_t bad = adjacent_pairs_out_of_order(s, cam, o.order);
      if (cam.ortho || spec.find("pbtf") != std::string::npos) {
        EXPECT_EQ(bad, 0) << spec << " eye (" << cam.eye.x << "," << cam.eye.y << "," << cam.eye.z << ")";
      }
    }
  }
}

}  // namespace
}  // namespace vob
