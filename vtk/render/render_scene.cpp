#include "vtk/render/render_scene.h"

#include <fstream>

#include <vtkCellCenterDepthSort.h>
#include <vtkCellData.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVersion.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "harness/scene/input_error.h"
#include "vtk/render/render_report.h"
#include "vtk/render/timed_sort.h"
#include "vtk/render/vtk_frame.h"
#include "vtk/vobench_visibility_sort.h"
#include "vtk/vtk_scene.h"

namespace vob {

std::string file_label(const std::string& s) {
  std::string o;
  for (char c : s) o += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.') ? c : '_';
  return o;
}

namespace {
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return "load average " + a + " " + b + " " + c;
}

// The grid the mappers draw: the scene's cells, tetrahedralized by VTK when they are not
// all tetrahedra (cell array vobench_cell_id: each tetrahedron's cell in the scene).
vtkSmartPointer<vtkUnstructuredGrid> tetrahedra(const Scene& scene, bool& split) {
  auto grid = grid_from_scene(scene);
  const CellMesh& m = scene.mesh();
  split = false;
  for (CellType t : m.types) split = split || t != CellType::Tetra;
  if (!split) return grid;
  vtkNew<vtkDataSetTriangleFilter> filter;
  filter->SetInputData(grid);
  filter->TetrahedraOnlyOn();
  filter->Update();
  vtkSmartPointer<vtkUnstructuredGrid> out = filter->GetOutput();
  return out;
}
}  // namespace

nlohmann::json render_scene(const Scene& scene, const std::vector<std::pair<int, Camera>>& cameras,
                            const RenderSettings& s, const std::string& out, nlohmann::json context) {
  const int w = cameras.at(0).second.width, h = cameras.at(0).second.height;
  const std::string load_at_start = load_average();
  bool split = false;
  auto tets = tetrahedra(scene, split);
  double range[2];
  tets->GetPointData()->GetScalars()->GetRange(range);
  std::string scalar_source = "the scene's point scalars";
  const Aabb box = scene.bounds();
  const double radius = 0.5 * length(box.hi - box.lo);
  if (!(range[1] > range[0])) {  // one colour everywhere would make every order look alike
    auto* values = vtkDoubleArray::SafeDownCast(tets->GetPointData()->GetScalars());
    for (vtkIdType i = 0; i < tets->GetNumberOfPoints(); ++i) {
      double p[3];
      tets->GetPoint(i, p);
      values->SetValue(i, 1.0 - length(Vec3{p[0], p[1], p[2]} - box.center()) / radius);
    }
    values->Modified();
    values->GetRange(range);
    scalar_source = "synthetic: 1 - distance from the box centre / bounding radius (the scene's are constant)";
  }
  if (split) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(tets);
    writer->SetFileName((out + "/tetrahedra.vtu").c_str());
    writer->Write();
  }

  VtkStage stage(tets, range[0], range[1], radius / s.extinction, w, h);
  RenderRun run;
  vtkNew<vtkCellCenterDepthSort> vtk_sort;
  vtkNew<vobTimedSort> timed;
  timed->SetSort(vtk_sort);
  stage.add_sorter(timed);
  run.sorters.push_back({"vtk-default", "vtkCellCenterDepthSort"});
  std::vector<vtkSmartPointer<vobVisibilitySort>> ours;
  for (const std::string& alg : s.algorithms) {
    auto sort = vtkSmartPointer<vobVisibilitySort>::New();
    if (!sort->SetOrderer(alg)) throw InputError("--algorithm " + alg, "orderer", sort->GetLastError());
    sort->SetRenderer(stage.renderer());
    sort->SetAlwaysOrder(true);  // every timed frame sorts, as VTK's sort does
    stage.add_sorter(sort);
    ours.push_back(sort);
    run.sorters.push_back({alg, alg, sort->GetObjectExact(), sort->GetImageExact()});
    if (run.reference < 0 && (sort->GetObjectExact() || sort->GetImageExact()))
      run.reference = static_cast<int>(run.sorters.size()) - 1;
  }
  const auto check = [&](size_t i, int view) {
    if (i > 0 && !ours[i - 1]->GetLastError().empty())
      throw InputError("--algorithm " + s.algorithms[i - 1], "view " + std::to_string(view),
                       ours[i - 1]->GetLastError());
  };
  // Warm-up: prepares, shader compilation, buffers; the prepare is the adapter's.
  for (size_t i = 0; i < run.sorters.size(); ++i) {
    if (i > 0) ours[i - 1]->SetViewIndex(cameras[0].first);
    stage.render(static_cast<int>(i), cameras[0].second);
    check(i, cameras[0].first);
    if (i > 0) run.sorters[i].prepare_seconds = ours[i - 1]->GetLastPrepareSeconds();
  }
  for (const auto& [index, cam] : cameras) {
    ViewFrames v;
    v.view_index = index;
    v.camera = cam;
    v.sorters.resize(run.sorters.size());
    std::vector<RgbImage> images(run.sorters.size());
    for (int r = 0; r < s.repeats; ++r)
      for (size_t i = 0; i < run.sorters.size(); ++i) {  // interleaved: one load for all
        if (const int sig = s.stop ? s.stop() : 0) throw RenderStopped{sig};
        if (i > 0) ours[i - 1]->SetViewIndex(index);
        const double t = stage.render(static_cast<int>(i), cam);
        check(i, index);
        v.sorters[i].frame_seconds.push_back(t);
        v.sorters[i].sort_seconds.push_back(i == 0 ? timed->GetLastSortSeconds() : ours[i - 1]->GetLastSortSeconds());
        if (r == s.repeats - 1) images[i] = stage.capture();
      }
    for (size_t i = 0; i < run.sorters.size(); ++i) {
      SorterFrame& f = v.sorters[i];
      const std::string base = "view" + std::to_string(index) + "-" + file_label(run.sorters[i].label);
      f.image = base + ".png";
      f.covered = covered_pixels(images[i]);
      write_rgb_png(images[i], out + "/" + f.image);
      if (run.reference >= 0) {
        f.compared = true;
        f.diff = compare_images(images[i], images[run.reference]);
        f.diff_image = base + "-diff.png";
        write_difference_png(images[i], images[run.reference], out + "/" + f.diff_image);
      }
    }
    run.views.push_back(std::move(v));
  }
  run.context = std::move(context);
  run.context.update(nlohmann::json{
      {"cells", scene.num_primitives()},
      {"tetrahedra", tets->GetNumberOfCells()},
      {"tetrahedralized", split},
      {"id_map", split ? "tetrahedra.vtu, cell array vobench_cell_id: each tetrahedron's scene cell"
                       : "identity (the scene is tetrahedra)"},
      {"scalars", scalar_source},
      {"size", {w, h}},
      {"repeats", s.repeats},
      {"extinction", s.extinction},
      {"warmup", 1},
      {"vtk_version", vtkVersion::GetVTKVersion()},
      {"gl_renderer", stage.gl_renderer()},
      {"load", load_at_start + " at the start, " + load_average() + " at the end (other jobs share the machine)"},
      {"timing", "frame: Render() to glFinish, interleaved over sorters per view and repeat; "
                 "sort: the sort's InitTraversal and GetNextCells inside that frame"}});
  write_render_json(run, out);
  write_render_html(run, out);
  return summary(run);
}

}  // namespace vob
