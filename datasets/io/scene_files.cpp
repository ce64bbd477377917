// load_input and write_scene: dispatch on the file extension; loads are validated (DESIGN.md:
// finite coordinates, indices in range, non-degenerate positively oriented cells, no face
// shared by more than two cells). Nothing is repaired.
#include <cstdio>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "datasets/datasets.h"
#include "datasets/io/file_util.h"
#include "datasets/io/inr_reader.h"
#include "datasets/io/off_io.h"
#include "datasets/io/tetgen_bridge.h"
#include "datasets/io/tetgen_files.h"
#include "datasets/io/vtk_io.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
Scene validated(Scene s, const std::string& path) {
  switch (s.kind()) {
    case SceneKind::Cells:
      validate_cell_mesh(s.mesh(), path);
      build_mesh_faces(s.mesh(), path);  // throws on a face shared by 3 cells or overlaps
      break;
    case SceneKind::Triangles: validate_triangle_soup(s.soup(), path); break;
    case SceneKind::Voxels: validate_voxel_grid(s.grid(), path); break;
  }
  return s;
}
}  // namespace

namespace {
Scene load_unguarded(const std::string& path, const InputOptions& opt) {
  require_readable_file(path);
  const std::string ext = file_extension(path);
  const std::string name = std::filesystem::path(path).stem().string();
  nlohmann::json params{{"input", path}};
  if (opt.tetrahedralize && ext != ".off")
    throw InputError(path, "file", "--tetrahedralize applies to .off surfaces only");
  if (ext == ".vtu" || ext == ".vtk" || ext == ".vti") {
    std::string note;
    Scene s = validated(read_vtk_file(path, &note), path);
    // Told only now that the whole read succeeded, so a refused file still gets one line.
    if (!note.empty()) std::fprintf(stderr, "vobench: note: %s: %s\n", path.c_str(), note.c_str());
    return s;
  }
  if (ext == ".node" || ext == ".ele") {
    const std::string node = ext == ".node" ? path : tetgen_partner(path, ".node");
    const std::string ele = tetgen_partner(node, ".ele");
    require_readable_file(node);
    require_readable_file(ele);
    return validated(Scene::from_mesh(name, read_tetgen(node, ele), params), path);
  }
  if (ext == ".inr") return validated(Scene::from_grid(name, read_inr(path), params), path);
  if (ext == ".off") {
    TriangleSoup soup = read_off(path);
    validate_triangle_soup(soup, path);
    if (!opt.tetrahedralize) return Scene::from_soup(name, std::move(soup), params);
    check_closed_surface(soup, path);
    params["tetgen"] = opt.tetgen_switches.empty() ? kDefaultTetgenSwitches : opt.tetgen_switches;
    return validated(Scene::from_mesh(name, tetrahedralize_surface(soup, path, opt.tetgen_switches), params), path);
  }
  if (ext == ".gz")
    throw InputError(path, "file", "compressed input is not supported; decompress it first");
  throw InputError(path, "file", "unknown extension '" + ext +
                                     "' (expected .vtu .vtk .vti .node .ele .inr .off)");
}
}  // namespace

Scene load_input(const std::string& path, const InputOptions& opt) {
  try {
    return load_unguarded(path, opt);
  } catch (const std::bad_alloc&) {
    throw InputError(path, "file", "not enough memory to read it");
  } catch (const std::length_error&) {
    throw InputError(path, "file", "declares more data than can be held in memory");
  }
}

void write_scene(const Scene& scene, const std::string& path) {
  const std::string ext = file_extension(path);
  auto mismatch = [&](const char* expected) {
    throw InputError(path, "file", std::string("a ") + scene_kind_name(scene.kind()) +
                                       " scene is written as " + expected + ", not '" + ext + "'");
  };
  switch (scene.kind()) {
    case SceneKind::Cells:
      if (ext == ".vtu") return write_vtu(scene.mesh(), path);
      if (ext == ".vtk") return write_vtk_legacy(scene.mesh(), path);
      if (ext == ".node") return write_tetgen(scene.mesh(), path);
      mismatch(".vtu, .vtk or .node (+ .ele)");
      break;
    case SceneKind::Triangles:
      if (ext == ".off") return write_off(scene.soup(), path);
      mismatch(".off");
      break;
    case SceneKind::Voxels:
      if (ext == ".vti") return write_vti(scene.grid(), path);
      mismatch(".vti");
      break;
  }
}

}  // namespace vob
