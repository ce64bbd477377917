#include "harness/oracle/embree_caster.h"

#include <algorithm>
#include <limits>
#include <string>

#include <embree3/rtcore.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "harness/geometry/predicates.h"
#include "harness/scene/cell_types.h"
#include "harness/scene/input_error.h"
#include "harness/scene/mesh_faces.h"

namespace vob {

namespace {

struct Hit {
  unsigned prim;
  float t;
};
struct CellHit {
  int32_t cell, face;
  float t;
};

// Embree hands the context pointer back to the filter; the hit list rides behind it.
struct HitContext {
  RTCIntersectContext ctx;
  std::vector<Hit>* hits;
};

void record_and_reject(const RTCFilterFunctionNArguments* args) {
  auto* hc = reinterpret_cast<HitContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    hc->hits->push_back({RTCHitN_primID(args->hit, args->N, i), RTCRayN_tfar(args->ray, args->N, i)});
    args->valid[i] = 0;  // rejected: traversal goes on and reports the next hit
  }
}

void check_device(RTCDevice dev, const char* what) {
  const RTCError e = rtcGetDeviceError(dev);
  if (e != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("embree: ") + what + " failed (error " + std::to_string(e) + ")");
}

}  // namespace

struct EmbreeCaster::Impl {
  Scene scene;
  MeshFaces faces;
  std::vector<int32_t> tri_face;
  Vec3 shift;
  RTCDevice device = nullptr;
  RTCScene rtc = nullptr;

  ~Impl() {
    if (rtc) rtcReleaseScene(rtc);
    if (device) rtcReleaseDevice(device);
  }

  // Exact: p strictly inside cell c (every face sees it on its inner side).
  bool contains(int32_t c, Vec3 p) const {
    const CellMesh& m = scene.mesh();
    const int32_t* v = m.cell_points(c);
    const LocalFaces& lf = cell_local_faces(m.types[c]);
    for (int f = 0; f < lf.count; ++f)
      if (orient3d(m.points[v[lf.v[f][0]]], m.points[v[lf.v[f][1]]], m.points[v[lf.v[f][2]]], p) >= 0)
        return false;
    return true;
  }
};

EmbreeCaster::EmbreeCaster(const Scene& scene) : impl_(std::make_unique<Impl>()) {
  if (scene.kind() != SceneKind::Cells)
    throw InputError("embree caster", "scene '" + scene.name() + "'", "has no cells");
  Impl& im = *impl_;
  im.scene = scene;
  const CellMesh& m = scene.mesh();
  im.faces = build_mesh_faces(m, scene.name());
  im.shift = scene.bounds().center();
  std::vector<unsigned> idx;
  for (size_t f = 0; f < im.faces.num_faces(); ++f) {
    const int32_t* v = im.faces.face_points(f);
    const int n = im.faces.face_size(f);
    for (int k = 1; k + 1 < n; ++k) {
      idx.insert(idx.end(), {unsigned(v[0]), unsigned(v[k]), unsigned(v[k + 1])});
      im.tri_face.push_back(int32_t(f));
    }
  }
  im.device = rtcNewDevice(nullptr);
  if (!im.device) throw std::runtime_error("embree: cannot create a device");
  im.rtc = rtcNewScene(im.device);
  rtcSetSceneFlags(im.rtc, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(im.rtc, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry g = rtcNewGeometry(im.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                         3 * sizeof(float), m.num_points()));
  for (size_t i = 0; i < m.num_points(); ++i) {
    const Vec3 p = m.points[i] - im.shift;
    vb[3 * i] = float(p.x), vb[3 * i + 1] = float(p.y), vb[3 * i + 2] = float(p.z);
  }
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                            3 * sizeof(unsigned), im.tri_face.size()));
  std::copy(idx.begin(), idx.end(), ib);
  rtcSetGeometryIntersectFilterFunction(g, record_and_reject);
  rtcCommitGeometry(g);
  rtcAttachGeometry(im.rtc, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(im.rtc);
  check_device(im.device, "building the scene");
}

EmbreeCaster::~EmbreeCaster() = default;

CellSequences EmbreeCaster::cast(const Camera& view, int supersample, double min_length) const {
  view.validate();
  if (supersample < 1 || supersample > 16)
    throw InputError("embree caster", "supersample", std::to_string(supersample) + " is not in [1, 16]");
  const Impl& im = *impl_;
  const int S = supersample, cols = view.width * S, rows = view.height * S;
  std::vector<std::vector<RaySegment>> seg(rows);
  std::vector<std::vector<int32_t>> counts(rows, std::vector<int32_t>(cols, 0));
  struct Work {
    std::vector<Hit> hits;
    std::vector<CellHit> ch;  // (cell, face, t): two per shared face
  };
  tbb::enumerable_thread_specific<Work> work;
  tbb::parallel_for(0, rows, [&](int sy) {
    Work& w = work.local();
    for (int sx = 0; sx < cols; ++sx) {
      const Ray ray = view.ray((sx + 0.5) / S, (sy + 0.5) / S);
      const Vec3 o = ray.origin - im.shift;
      HitContext hc;
      rtcInitIntersectContext(&hc.ctx);
      w.hits.clear();
      hc.hits = &w.hits;
      RTCRayHit rh{};
      rh.ray.org_x = float(o.x), rh.ray.org_y = float(o.y), rh.ray.org_z = float(o.z);
      rh.ray.dir_x = float(ray.dir.x), rh.ray.dir_y = float(ray.dir.y), rh.ray.dir_z = float(ray.dir.z);
      rh.ray.tnear = 0.0f;
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = 0xFFFFFFFFu;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(im.rtc, &hc.ctx, &rh);
      // One hit per triangle, then per (cell, face).
      std::sort(w.hits.begin(), w.hits.end(), [](const Hit& a, const Hit& b) { return a.prim < b.prim; });
      w.hits.erase(std::unique(w.hits.begin(), w.hits.end(),
                               [](const Hit& a, const Hit& b) { return a.prim == b.prim; }),
                   w.hits.end());
      std::vector<CellHit>& ch = w.ch;
      ch.clear();
      for (const Hit& h : w.hits) {
        const int32_t f = im.tri_face[h.prim];
        ch.push_back({im.faces.cell0[f], f, h.t});
        if (im.faces.cell1[f] >= 0) ch.push_back({im.faces.cell1[f], f, h.t});
      }
      std::sort(ch.begin(), ch.end(), [](const CellHit& a, const CellHit& b) {
        return a.cell != b.cell ? a.cell < b.cell : a.t < b.t;
      });
      for (size_t i = 0; i < ch.size();) {
        size_t j = i;
        bool two_faces = false;
        while (j < ch.size() && ch[j].cell == ch[i].cell) two_faces |= ch[j].face != ch[i].face, ++j;
        double t0 = ch[i].t, t1 = ch[j - 1].t;
        bool keep = two_faces;
        if (!two_faces && im.contains(ch[i].cell, ray.origin)) t0 = 0, keep = true;
        if (keep && t1 - t0 > min_length) {
          seg[sy].push_back({ch[i].cell, t0, t1});
          ++counts[sy][sx];
        }
        i = j;
      }
    }
  });
  check_device(im.device, "casting rays");
  return make_cell_sequences(cols, rows, S, std::move(seg), std::move(counts));
}

}  // namespace vob
