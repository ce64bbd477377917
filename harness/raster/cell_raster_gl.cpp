#include "harness/raster/cell_raster_gl.h"

#include <algorithm>
#include <limits>

#include "harness/raster/polygon_raster.h"
#include "harness/scene/cell_types.h"

namespace vob {

namespace {
// Face f of cell c: its points and their window positions as the collector projected them.
int face_vertices(const SampleFrame& frame, const CellMesh& mesh, const ProjectedPoints& proj,
                  int32_t c, const LocalFaces& lf, int f, Vec3* v, ProjectedVertex* pv) {
  const int32_t* p = mesh.cell_points(c);
  for (int i = 0; i < lf.size[f]; ++i) {
    const int32_t id = p[lf.v[f][i]];
    v[i] = mesh.points[size_t(id)];
    pv[i].x = proj.x[size_t(id)];
    pv[i].y = proj.y[size_t(id)];
    pv[i].in_front = frame.ortho() || proj.zc[size_t(id)] > 0;
  }
  return lf.size[f];
}
}  // namespace

template <class Fn>
void GlCellRaster::each_face(int32_t c, Fn&& fn) const {
  const LocalFaces& lf = cell_local_faces(mesh_.types[size_t(c)]);
  for (int f = 0; f < lf.count; ++f) {
    Vec3 v[4];
    ProjectedVertex pv[4];
    const int n = face_vertices(frame_, mesh_, proj_, c, lf, f, v, pv);
    PolygonRaster pr;
    if (pr.setup(frame_, v, n, pv)) fn(pr);
  }
}

SampleRect GlCellRaster::bounds(int32_t c) const {
  SampleRect r;
  each_face(c, [&](const PolygonRaster& pr) { r = r.unite(pr.bounds()); });
  return r;
}

void GlCellRaster::accumulate(int32_t c, const SampleRect& r) {
  const int w = r.x1 - r.x0 + 1;
  const size_t size = size_t(w) * size_t(r.y1 - r.y0 + 1);
  lo_.assign(size, std::numeric_limits<double>::infinity());
  hi_.assign(size, -std::numeric_limits<double>::infinity());
  n_.assign(size, 0);
  each_face(c, [&](PolygonRaster& pr) {
    pr.scan(r, [&](int sx, int sy, double t) {
      const size_t i = size_t(sy - r.y0) * w + (sx - r.x0);
      lo_[i] = std::min(lo_[i], t);
      hi_[i] = std::max(hi_[i], t);
      if (n_[i] < 255) ++n_[i];
    });
  });
}

}  // namespace vob
