// Whether the exterior surface meets itself away from shared vertices and edges: an
// exterior edge whose open segment meets an exterior face that does not have it (volumes
// touching along a face, an edge or a point, without sharing vertices). Where no edge is
// so touched, every point of an exterior edge's relative interior lies on its own faces
// only, which is what lets XMPVO's edge sweep give an entering face the leaving face's
// place in the depth order without comparing depths (edge_sweep.cpp, swap).
#pragma once
#include <cstdint>

#include "harness/scene/exterior_faces.h"

namespace vob::xmpvo {

struct EdgeContacts {
  int64_t edges = 0;          // unique exterior edges
  int64_t candidates = 0;     // (edge, face) pairs whose closed boxes meet
  int64_t touched_edges = 0;  // edges some face not having them meets (conservative: a
                              // face coplanar with the edge, or meeting it at an
                              // endpoint it does not have, counts)
  bool triangles_only = true; // every exterior face a triangle (the test's premise)
};

// Exact (orient3d); candidates by CGAL's box intersection.
EdgeContacts find_edge_contacts(const ExteriorFaces& ext);

}  // namespace vob::xmpvo
