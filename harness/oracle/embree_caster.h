// An independent check of the oracle's cell fragments: Embree 3 casts the ray of every
// sample through all cell faces and reports every hit, giving per-sample cell sequences
// that share no code with the rasterizer (float geometry, Embree's watertight triangle test,
// Camera::ray for the rays).
//
// The scene holds each unique face once (quads as the two triangles (0,1,2), (0,2,3)); a
// triangle knows the one or two cells that own its face. An intersection filter records
// each hit and rejects it, so traversal continues and reports all of them; a primitive
// reported twice (spatial splits) is counted once. A cell's segment is [first hit, last
// hit]; a cell hit on a single face is entered only if the ray starts inside it (eye inside
// a cell, or an orthographic ray starting in a cell that straddles the eye plane), giving
// [0, hit]; otherwise it was grazed and is dropped, as are segments not longer than
// min_length. Coordinates are shifted to the scene centre before the conversion to float.
#pragma once
#include <memory>

#include "harness/oracle/sequences.h"

namespace vob {

class EmbreeCaster {
 public:
  explicit EmbreeCaster(const Scene& scene);  // cells only; InputError otherwise
  ~EmbreeCaster();
  EmbreeCaster(const EmbreeCaster&) = delete;
  EmbreeCaster& operator=(const EmbreeCaster&) = delete;

  // The sequences of the view at S x S samples per pixel.
  CellSequences cast(const Camera& view, int supersample, double min_length = 0) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vob
