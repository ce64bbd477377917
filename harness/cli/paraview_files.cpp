#include "harness/cli/paraview_files.h"

#include <cstdio>

#include "datasets/io/vtk_io.h"
#include "harness/bench/atomic_file.h"
#include "harness/scene/input_error.h"

namespace vob {

void write_order_vtu(const Scene& scene, const Ordering& ordering, const OracleResult& judged,
                     const std::string& path) {
  if (scene.kind() != SceneKind::Cells)
    throw InputError("--vtu", path, std::string("writes cell meshes; this scene has ") + scene_kind_name(scene.kind()));
  const size_t n = scene.mesh().num_cells();
  std::vector<int64_t> rank(n, -1), in_cycle(n, 0);
  for (size_t i = 0; i < ordering.order.size(); ++i) rank[size_t(ordering.order[i])] = int64_t(i);
  for (const int32_t c : ordering.cycles.primitives)
    if (c >= 0 && size_t(c) < n) in_cycle[size_t(c)] = 1;
  std::vector<int64_t> violating = judged.violating_fragments_per_primitive;
  violating.resize(n, 0);
  write_vtu(scene.mesh(), path,
            {{"order_rank", rank}, {"violating_fragments", violating}, {"in_cycle", in_cycle}});
}

void write_violation_vti(const OracleResult& r, const std::string& path) {
  write_mask_vti(r.violation_mask, r.mask_width, r.mask_height, "violating", path);
}

void write_camera_pvcc(const Camera& cam, const std::string& path) {
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<PVCameraConfiguration description=\"ParaView camera configuration\" version=\"1.0\">\n"
                    "  <Proxy group=\"views\" type=\"RenderView\" id=\"1\" servers=\"21\">\n";
  auto property = [&](const char* name, std::initializer_list<double> values, bool boolean = false) {
    xml += std::string("    <Property name=\"") + name + "\" id=\"1." + name + "\" number_of_elements=\"" +
           std::to_string(values.size()) + "\">\n";
    int i = 0;
    for (const double v : values) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", v);
      xml += "      <Element index=\"" + std::to_string(i++) + "\" value=\"" + buf + "\"/>\n";
    }
    if (boolean) xml += std::string("      <Domain name=\"bool\" id=\"1.") + name + ".bool\"/>\n";
    xml += "    </Property>\n";
  };
  property("CameraPosition", {cam.eye.x, cam.eye.y, cam.eye.z});
  property("CameraFocalPoint", {cam.target.x, cam.target.y, cam.target.z});
  const Vec3 up = cam.true_up();  // ParaView keeps view-up orthogonal to the view direction
  property("CameraViewUp", {up.x, up.y, up.z});
  property("CenterOfRotation", {cam.target.x, cam.target.y, cam.target.z});
  property("CameraViewAngle", {cam.fov_deg});
  property("CameraParallelScale", {0.5 * cam.ortho_height});
  property("CameraParallelProjection", {cam.ortho ? 1.0 : 0.0}, true);
  xml += "  </Proxy>\n</PVCameraConfiguration>\n";
  write_file_atomically(path, xml);
}

}  // namespace vob
