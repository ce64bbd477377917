#include "algorithms/stencil/stencil_xmpvo.h"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>

#include "algorithms/mpvo/mpvo_core.h"
#include "algorithms/stencil/layer_extraction.h"
#include "algorithms/stencil/snapped_signs.h"
#include "harness/geometry/predicates.h"
#include "harness/raster/polygon_raster.h"

namespace vob {
namespace {

using namespace stencil;

class StencilXmpvo final : public Orderer {
 public:
  explicit StencilXmpvo(const ResolvedParams& p) : x_(p) {}

  // Image-exact for the backend's own rule: the harness rasterizer's (software) or the gl
  // sampling rule, what llvmpipe draws (gl; stencil_xmpvo.h says what the claim assumes).
  Claims claims() const override {
    Claims c = mpvo::core_claims(false, true);
    if (x_.backend_name == "gl") c.image_exact_under = RasterRule::gl;
    return c;
  }

  void prepare(const Scene& scene, PhaseClock& clock) override {
    core_.prepare(scene, clock);
    { auto p = clock.phase("exterior faces"); ext_ = &scene.exterior_faces(); }
    auto p = clock.phase("upload");
    x_.backend = make_layer_backend(x_.backend_name, "stencil-xmpvo");
    find_coincident();
    std::vector<Vec3> corners;
    std::vector<int8_t> sizes;
    for (int32_t i : prim_) {
      corners.insert(corners.end(), &ext_->corners[4 * size_t(i)], &ext_->corners[4 * size_t(i) + 4]);
      sizes.push_back(ext_->size[size_t(i)]);
    }
    x_.backend->set_primitives(corners, sizes);
    x_.backend->set_facing(&front_);  // touching volumes: coplanar ties by facing
    Aabb box;  // the GL backend's bounding sphere (gl_backend.cpp): the same 24-bit depths
    for (size_t i = 0; i < ext_->size.size(); ++i)
      for (int k = 0; k < ext_->size[i]; ++k) box.add(ext_->corners[4 * i + k]);
    gl_centre_ = ext_->size.empty() ? Vec3{} : (box.lo + box.hi) * 0.5;
    gl_radius_ = ext_->size.empty() ? 1.0 : std::max(0.5 * length(box.hi - box.lo), 1e-300);
  }

  Ordering order(const Camera& view, PhaseClock& clock) override {
    Ordering out;
    const size_t b = prim_.size();
    {
      auto p = clock.phase("I create partial order");
      core_.create_partial_order(view);
      // GL: arrows and facing as llvmpipe's snapped faces wind (snapped_signs.h).
      if (x_.backend_name == "gl") snapped_flips_ = apply_snapped_signs(core_, view, snapped_);
      front_.resize(b);
      for (size_t i = 0; i < b; ++i) front_[i] = core_.face_sign(ext_->face[size_t(prim_[i])]) > 0;
    }
    {
      auto p = clock.phase("render");
      x_.backend->begin_frame(view);
      last_.assign(size_t(view.width) * view.height, 0);
      pairs_.clear();
      // Coincident faces (touching volumes with duplicated nodes): a shared face, crossed
      // from the cell it faces away from (the ray leaves it there) into the other one, as
      // MPVO's arrow; edge-on (no sign) they cover nothing and give nothing.
      for (const auto& [i, j] : coincident_) {
        const int si = core_.face_sign(ext_->face[size_t(i)]), sj = core_.face_sign(ext_->face[size_t(j)]);
        if (si < 0 && sj > 0) pairs_.push_back((uint64_t(uint32_t(ext_->cell[size_t(i)])) << 32) | uint32_t(ext_->cell[size_t(j)]));
        if (sj < 0 && si > 0) pairs_.push_back((uint64_t(uint32_t(ext_->cell[size_t(j)])) << 32) | uint32_t(ext_->cell[size_t(i)]));
      }
    }
    int64_t pixel_pairs = 0, dropped_pairs = 0, swapped_pairs = 0;
    const bool gl = x_.backend_name == "gl";
    if (gl) {
      gl_frame_ = std::make_unique<SampleFrame>(view, 1, RasterRule::gl);
      gl_range_ = gl_depth_range(view, gl_centre_, gl_radius_);
    }
    const PixelSink sink = [&](int64_t pixel, int32_t prim, int) {
      const int32_t prev = last_[size_t(pixel)], face = prim_[size_t(prim)];
      last_[size_t(pixel)] = face + 1;
      if (gl && prev && ext_front(prev - 1) && !ext_front(face) && coplanar(prev - 1, face)) {
        // Touching volumes: the depth test broke a tie between coplanar faces the other
        // way than the facing rule (the back face is nearer): the pair as it should be.
        ++swapped_pairs;
        pairs_.push_back((uint64_t(uint32_t(ext_->cell[size_t(face)])) << 32) | uint32_t(ext_->cell[size_t(prev - 1)]));
        return;
      }
      if (prev && !ext_front(prev - 1) && ext_front(face)) {
        if (gl && !ordered_by_rule(prev - 1, face, pixel)) {
          ++dropped_pairs;
          return;
        }
        ++pixel_pairs;
        pairs_.push_back((uint64_t(uint32_t(ext_->cell[size_t(prev - 1)])) << 32) | uint32_t(ext_->cell[size_t(face)]));
      }
    };
    x_.extractor.run(*x_.backend, int32_t(b), view, x_.opt, clock, x_.result, &sink);
    const LayerResult& result = x_.result;
    {
      auto p = clock.phase("relations");
      std::sort(pairs_.begin(), pairs_.end());
      pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
      rel_.clear();
      rel_.reserve(pairs_.size());
      for (uint64_t k : pairs_) {
        const int32_t front = int32_t(k >> 32), behind = int32_t(k & 0xffffffffu);
        if (front != behind) rel_.push_back({front, behind});
      }
      extra_.build_from_pairs(core_.num_cells(), rel_);
    }
    {
      auto p = clock.phase("DFS");
      core_.dfs_all(out, &extra_);
    }
    // Faces the layer extraction had to force out of a visibility cycle: a cycle it met and
    // broke, reported by the cells they bound (as stencil-layers reports its triangles).
    for (int32_t f : result.forced) out.cycles.add({ext_->cell[size_t(prim_[size_t(f)])]});
    core_.add_counters(out);
    add_layer_counters(result, out);
    auto& k = out.counters;
    k["exterior_faces"] = double(ext_->face.size());
    k["coincident_face_pairs"] = double(coincident_.size());
    if (x_.backend_name == "gl") k["snapped_sign_flips"] = double(snapped_flips_);
    k["pixel_pairs"] = double(pixel_pairs);
    if (gl) k["dropped_pairs"] = double(dropped_pairs);  // ordered otherwise by the gl rule
    if (gl) k["swapped_pairs"] = double(swapped_pairs);  // coplanar ties the depth test misordered
    k["relations"] = double(rel_.size());
    k["unclassified_faces"] = double(result.unclassified_visible);
    k["unclassified_no_pixel"] = double(result.unclassified_no_pixel);
    k["bytes_pixels"] = double(last_.capacity() * 4 + x_.extractor.bytes() + x_.backend->bytes());
    return out;
  }

  size_t bytes() const override {
    return core_.bytes() + last_.capacity() * 4 + front_.capacity() + pairs_.capacity() * 8 +
           rel_.capacity() * 8 + extra_.bytes() + x_.bytes();
  }

 private:
  Extraction x_;
  mpvo::MpvoCore core_;
  const ExteriorFaces* ext_ = nullptr;  // the scene's exterior faces
  std::vector<uint8_t> front_;  // per primitive (layered exterior face): facing the eye
  std::vector<int32_t> prim_;   // primitive -> exterior face: all but coincident pairs
  std::vector<std::pair<int32_t, int32_t>> coincident_;  // exterior faces with the same points
  std::vector<int32_t> prim_of_;  // exterior face -> primitive, -1 for coincident ones
  bool ext_front(int32_t f) const { return front_[size_t(prim_of_[size_t(f)])]; }
  // Exterior faces with exactly the same points (two volumes meshed with duplicated nodes
  // that touch face to face): a ray meets both at one depth, and their depth-buffer ties
  // (llvmpipe's float planes differ with the vertex order: 1 step either way, or equal and
  // then taken as an order by the layering's G != C test) made layering cycles that the
  // gl rule does not have. They are a shared face: related as MPVO relates one, not layered.
  void find_coincident() {
    const size_t n = ext_->face.size();
    std::vector<std::pair<std::array<Vec3, 4>, int32_t>> keys(n);
    for (size_t i = 0; i < n; ++i) {
      std::array<Vec3, 4> k{};
      const int m = ext_->size[i];
      const double inf = std::numeric_limits<double>::infinity();  // after any point
      for (int j = 0; j < 4; ++j) k[size_t(j)] = j < m ? ext_->corners[4 * i + size_t(j)] : Vec3{inf, inf, inf};
      std::sort(k.begin(), k.end(), [](const Vec3& a, const Vec3& b) { return lex_less(a, b); });
      keys[i] = {k, int32_t(i)};
    }
    auto less = [](const std::array<Vec3, 4>& a, const std::array<Vec3, 4>& b) {
      for (int j = 0; j < 4; ++j) {
        if (lex_less(a[size_t(j)], b[size_t(j)])) return true;
        if (lex_less(b[size_t(j)], a[size_t(j)])) return false;
      }
      return false;
    };
    std::sort(keys.begin(), keys.end(), [&](const auto& a, const auto& b) {
      return less(a.first, b.first) || (!less(b.first, a.first) && a.second < b.second);
    });
    coincident_.clear();
    prim_of_.assign(n, 0);
    for (size_t i = 0; i + 1 < n; ++i) {
      const int32_t a = keys[i].second, c = keys[i + 1].second;
      if (ext_->size[size_t(a)] == ext_->size[size_t(c)] && !less(keys[i].first, keys[i + 1].first) &&
          (i + 2 >= n || less(keys[i + 1].first, keys[i + 2].first)) && (i == 0 || less(keys[i - 1].first, keys[i].first))) {
        coincident_.push_back({a, c});
        prim_of_[size_t(a)] = prim_of_[size_t(c)] = -1;
        ++i;
      }
    }
    prim_.clear();
    for (size_t i = 0; i < n; ++i)
      if (prim_of_[i] == 0) prim_of_[i] = int32_t(prim_.size()), prim_.push_back(int32_t(i));
  }
  std::vector<int64_t> snapped_;  // gl: snapped window positions of the mesh points
  int64_t snapped_flips_ = 0;
  // GL backend: llvmpipe interpolates depth in floats from the framebuffer origin, which
  // can put two faces that meet at a pixel centre (a snapped vertex on it: equal depths)
  // a few 24-bit steps apart, and the depth test then orders them. A back/front pair is
  // kept when the gl rule orders it the same way: the back face strictly nearer in 24 bits,
  // or the faces coplanar (touching volumes: equal true depths, the back face nearer).
  bool ordered_by_rule(int32_t back, int32_t front, int64_t pixel) {
    const int sx = int(pixel % gl_frame_->cols()), sy = int(pixel / gl_frame_->cols());
    const int64_t db = rule_depth24(back, sx, sy), df = rule_depth24(front, sx, sy);
    if (db < 0 || df < 0) return true;  // not covered under the rule: nothing to compare
    return db < df || coplanar(back, front);  // coplanar: equal true depths, back face first
  }
  int64_t rule_depth24(int32_t f, int sx, int sy) const {
    PolygonRaster pr;
    int64_t d = -1;
    if (pr.setup(*gl_frame_, &ext_->corners[4 * size_t(f)], ext_->size[size_t(f)]))
      pr.scan(SampleRect{sx, sy, sx, sy}, [&](int, int, double t) {
        d = gl_depth24(gl_window_depth(gl_frame_->camera(), gl_range_, t / gl_frame_->dir_length(sx, sy)));
      });
    return d;
  }
  // Exterior faces a and b exactly coplanar (orient3d; the first point off the plane
  // usually ends it at the predicate's float filter).
  bool coplanar(int32_t a, int32_t b) const {
    const Vec3* pa = &ext_->corners[4 * size_t(a)];
    const Vec3* pb = &ext_->corners[4 * size_t(b)];
    bool on = true;
    for (int j = 0; j < ext_->size[size_t(b)] && on; ++j) on = orient3d(pa[0], pa[1], pa[2], pb[j]) == 0;
    for (int j = 3; j < ext_->size[size_t(a)] && on; ++j) on = orient3d(pb[0], pb[1], pb[2], pa[j]) == 0;
    return on;
  }

  std::unique_ptr<SampleFrame> gl_frame_;
  GlDepthRange gl_range_;
  Vec3 gl_centre_{};
  double gl_radius_ = 1;
  std::vector<int32_t> last_;  // per pixel: exterior face seen in the latest layer + 1
  std::vector<uint64_t> pairs_;
  std::vector<std::pair<int32_t, int32_t>> rel_;
  mpvo::ExtraRelations extra_;
};

}  // namespace

OrdererInfo stencil_xmpvo_orderer_info() {
  return extraction_orderer_info<StencilXmpvo>(
      "stencil-xmpvo", SceneKind::Cells,
      "Krishnan et al.'s discretized XMPVO: exterior faces layered with the stencil buffer, "
      "relations between faces met at a pixel in consecutive layers, MPVO DFS");
}

}  // namespace vob
