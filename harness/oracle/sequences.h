// Exact per-sample cell sequences (every cell a sample's ray passes through, sorted by
// depth) and their comparison. Two independent sources produce them: the rasterizer's
// fragments (raster_cell_sequences, here) and the Embree ray caster (embree_caster.h); a
// test holds the two together, so the oracle's fragments are checked against real rays.
//
// Tie handling. A ray that passes within a hair of an edge or vertex meets some cells in
// segments of almost zero length; whether such a cell is listed depends on rounding (the
// rasterizer works in doubles, Embree in floats). compare_sequences(a, b, tol) therefore:
//  - compares the sequences of cells whose segments are at least `tol` long: equal -> equal;
//  - otherwise calls the sample grazing when every difference is explained by short
//    segments: no cell is at least 4*tol long in one source and absent or shorter than
//    tol/4 in the other, and the cells at least tol long in both come in the same order;
//  - anything else is a mismatch (a wrong, missing or misordered cell).
// With Embree's float precision, tol = 1e-5 of the scene radius leaves a wide margin over
// the float error of t (about 1e-7 of the eye distance).
#pragma once
#include <functional>
#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct RaySegment {
  int32_t cell = 0;
  double t_in = 0, t_out = 0;
  double length() const { return t_out - t_in; }
  double mid() const { return 0.5 * (t_in + t_out); }
};

struct CellSequences {
  int cols = 0, rows = 0, supersample = 1;  // the sample grid (W*S x H*S)
  std::vector<int64_t> offsets;              // size samples + 1, index sy * cols + sx
  std::vector<RaySegment> segments;          // per sample, by increasing midpoint

  int64_t num_samples() const { return int64_t(cols) * rows; }
  std::span<const RaySegment> at(int64_t sample) const {
    return {segments.data() + offsets[sample], segments.data() + offsets[sample + 1]};
  }
};

// Orders each sample's segments by midpoint (ties by cell id) and builds the CSR.
CellSequences make_cell_sequences(int cols, int rows, int supersample,
                                  std::vector<std::vector<RaySegment>>&& per_row_segments,
                                  std::vector<std::vector<int32_t>>&& per_row_counts);

// From the rasterizer: every cell drawn, segments longer than min_length (and than the
// collector's own kMinSegmentRelative floor).
CellSequences raster_cell_sequences(const Scene& scene, const Camera& view, int supersample,
                                    double min_length = 0);

// Rays lying in a face plane. A ray that runs inside the plane of one of a cell's faces
// (an orthographic view exactly along an axis, an eye in a face plane) travels along the
// cell's boundary: whether that counts as passing through the cell is a convention, and the
// two sources settle it differently (doubles with the top-left rule here, floats in Embree).
// in_face_plane(sample, cell) says whether the sample's ray lies within `tol` of the plane of
// one of the cell's faces, direction included.
using InFacePlane = std::function<bool(int64_t sample, int32_t cell)>;
InFacePlane ray_in_face_plane_test(const Scene& scene, const Camera& view, int supersample,
                                   double tol);

struct SequenceComparison {
  int64_t samples = 0;     // compared
  int64_t equal = 0;       // identical sequences of cells at least tol long
  int64_t grazing = 0;     // different only through short segments (see above)
  int64_t in_plane = 0;    // different only through cells whose face plane holds the ray
  int64_t mismatched = 0;  // real disagreements
  nlohmann::json examples = nlohmann::json::array();  // first few mismatches
  bool ok() const { return mismatched == 0; }
  nlohmann::json to_json() const;
};

// InputError when the grids differ. With `in_plane`, samples whose differences all come
// from cells whose face plane holds the ray count as in_plane, not mismatched.
SequenceComparison compare_sequences(const CellSequences& a, const CellSequences& b, double tol,
                                     int max_examples = 5, const InFacePlane& in_plane = {});

}  // namespace vob
