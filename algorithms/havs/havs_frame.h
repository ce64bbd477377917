// The two phases of HAVS on the CPU (Callahan et al., sections 3.3 and 4), and the analysis
// that measures them against the exact per-pixel order.
//
// - FaceData (view independent, built once): the unique faces of the mesh, their boundary
//   tags (a face with one cell is a boundary face; the paper tags boundary vertices, which
//   marks the same faces on a tetrahedral mesh) and a linear function giving the normalised
//   scalar at any point of the face (quads: one per half, split along the 0-2 diagonal).
// - sort_faces ("cpu sort"): face centroid distances to the eye as float keys, sorted front to
//   back by the LSD radix argsort (stable: ties in face id order).
// - render_kbuffer ("k-buffer"): the faces are rasterized in sorted order at pixel centres by
//   the harness rasterizer (top-left rule, so every face crossing a ray gives one fragment);
//   each fragment goes through its pixel's k-buffer (kbuffer.h); a final flush. The image is
//   cut into bands of rows processed in parallel, the faces binned per band first
//   (face_bins.h): a pixel's result depends only on the fragments reaching it, in face order,
//   so bands are independent and the result does not depend on threads.
// - analyze: per pixel, the fragment stream in arrival order, its A-buffer (sorted) order,
//   k_needed (kbuffer.h), and the k-buffer rerun on the stream, segment by segment against
//   the A-buffer's; both images. Untimed.
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/havs/kbuffer.h"
#include "harness/sort/radix_argsort.h"
#include "harness/raster/raster_rule.h"
#include "harness/render/compositor.h"
#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob::havs {

inline float clamp01(double s) { return float(s < 0 ? 0 : (s > 1 ? 1 : s)); }

struct FaceData {
  Scene scene;                        // shares the mesh and its derived faces
  const MeshFaces* faces = nullptr;
  const Centroids* centroids = nullptr;
  std::vector<uint8_t> boundary;      // per face
  struct Points {
    int32_t id[4];                    // the face's points; id[3] = -1 for a triangle
  };
  std::vector<Points> points;         // per face: one load where MeshFaces takes two dependent
  struct Linear {
    Vec3 g;
    double c = 0;
    double at(const Vec3& p) const { return dot(g, p) + c; }
  };
  std::vector<Linear> scalar;         // per face (quads: the half 0-1-2)
  std::vector<int32_t> quad_slot;     // per face: -1, or index into quad_half2 / quad_split
  std::vector<Linear> quad_half2;     // quads: the half 0-2-3
  std::vector<Linear> quad_split;     // quads: > 0 on the 0-2-3 side of the diagonal
  double tau0 = 1;                    // extinction scale, as the harness compositor
  size_t bytes() const;
  float scalar_at(int32_t f, const Vec3& p) const {
    const int32_t q = quad_slot[f];
    const double s = (q >= 0 && quad_split[q].at(p) > 0) ? quad_half2[q].at(p) : scalar[f].at(p);
    return clamp01(s);
  }
};
FaceData build_face_data(const Scene& scene);

struct SortBuffers {
  RadixArgsort sort;  // fused key pass + range-limited LSD passes, parallel under the TBB limit
  size_t bytes() const { return sort.bytes(); }
};
// Face ids front to back by centroid distance to the eye (view depth in ortho).
void sort_faces(const FaceData& fd, const Camera& view, SortBuffers& buf, std::vector<int32_t>& order);

// A complete back-to-front permutation of the cells for the harness: each cell is placed at
// the sorted position of the last of its faces to arrive (that is when the k-buffer can
// composite its segment), farthest first; ties keep cell id order.
std::vector<int32_t> cell_order_from_faces(const FaceData& fd, const std::vector<int32_t>& face_order);

struct RenderStats {
  int64_t fragments = 0;
  int64_t segments = 0;     // composited (inside) segments
};
// The k-buffer pass; `image` is resized to the view. k in [1, kMaxK].
constexpr int kMaxK = 16;
struct FaceBins;  // face_bins.h
// `scratch` (optional): the binning buffers, kept by a caller that renders frame after frame.
// `rule` gl: the faces cover the pixels llvmpipe's rule gives them (raster_rule.h), with
// the depth and scalar of their own planes, as the GL k-buffer's shader computes them: the
// software image the GL one is compared with under that rule.
RenderStats render_kbuffer(const FaceData& fd, const Camera& view,
                           const std::vector<int32_t>& face_order, int k, Image& image,
                           FaceBins* scratch = nullptr, RasterRule rule = RasterRule::exact);

struct Segment {
  float d1 = 0, d2 = 0;
  int32_t face1 = 0, face2 = 0;
};

struct AnalysisOptions {
  bool record_segments = false;  // keep the k-buffer's composited segments per pixel (tests)
};

struct Analysis {
  int k = 0;
  int64_t fragments = 0;          // face fragments at pixel centres
  int64_t covered_pixels = 0;
  int max_list = 0;               // longest per-pixel list (Table 2 "Max A")
  int max_k_needed = 0;           // max over pixels of k_needed (Table 2 "Max k")
  std::vector<int64_t> k_histogram;  // covered pixels by k_needed
  int64_t pixels_k_above(int k) const;
  std::vector<uint8_t> k_needed;  // per pixel (clamped to 255), index y * w + x
  int64_t violating_pixels = 0;   // pixels whose segment sequence differs from the A-buffer's
  std::vector<uint8_t> violating; // per pixel, 1 where it differs
  int64_t violating_segments = 0; // positions where it differs
  Image kbuffer_image, exact_image;
  ImageError image_error;         // k-buffer image against the A-buffer (exact order) image
  // With record_segments: composited segments per pixel, front to back (CSR).
  std::vector<int64_t> seg_offsets;
  std::vector<Segment> segments;
};
Analysis analyze(const FaceData& fd, const Camera& view, const std::vector<int32_t>& face_order,
                 int k, const AnalysisOptions& opt = {});

// Fig. 6 colours: k_needed <= 2 green, 2 < k <= 6 yellow, > 6 red, uncovered black.
Image k_needed_image(const Analysis& a, int width, int height);

}  // namespace vob::havs
