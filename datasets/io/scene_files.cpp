// load_input and write_scene: dispatch on the file extension; loads are validated (DESIGN.md:
// finite coordinates, indices in range, non-degenerate positively oriented cells, no face
// shared by more than two cells). Nothing is repaired.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "datasets/datasets.h"
#include "datasets/io/exodus_reader.h"
#include "datasets/io/file_util.h"
#include "datasets/io/gmsh_reader.h"
#include "datasets/io/inr_reader.h"
#include "datasets/io/off_io.h"
#include "datasets/io/surface_reader.h"
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
    case SceneKind::Voxels:
      validate_voxel_grid(s.grid(), path);
      // Only voxels above the threshold are ordered and judged: a file without one would
      // pass every check on nothing, as a mesh without cells would.
      if (std::none_of(s.grid().values.begin(), s.grid().values.end(),
                       [t = s.grid().threshold](float v) { return v > t; }))
        throw InputError(path, "values", "no voxel is above the threshold " + short_number(s.grid().threshold) +
                                             " (nothing to order or draw)");
      break;
  }
  return s;
}

// A reader's note ("skipped ...") is told only once the whole read and validation
// succeeded, so a refused file still gets exactly one line.
Scene told(Scene s, const std::string& path, const std::string& note) {
  if (!note.empty()) std::fprintf(stderr, "vobench: note: %s: %s\n", path.c_str(), note.c_str());
  return s;
}

bool is_surface(const std::string& ext) {
  return ext == ".off" || ext == ".stl" || ext == ".ply" || ext == ".obj";
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() &&
         std::equal(tail.rbegin(), tail.rend(), s.rbegin(),
                    [](char a, char b) { return std::tolower((unsigned char)a) == b; });
}
}  // namespace

namespace {
Scene load_unguarded(const std::string& path, const InputOptions& opt) {
  require_readable_file(path);
  const std::string ext = file_extension(path);
  const std::string name = std::filesystem::path(path).stem().string();
  nlohmann::json params{{"input", path}};
  if (opt.tetrahedralize && !is_surface(ext))
    throw InputError(path, "file", "--tetrahedralize applies to surfaces (.off .stl .ply .obj) only");
  if (!opt.variable.empty() && ext != ".exo" && ext != ".e")
    throw InputError(path, "file", "an input variable applies to Exodus II files (.exo .e) only");
  std::string note;
  if (ext == ".vtu" || ext == ".pvtu" || ext == ".vtk" || ext == ".vti")
    return told(validated(read_vtk_file(path, &note), path), path, note);
  if (ext == ".msh")
    return told(validated(Scene::from_mesh(name, read_gmsh(path, &note), params), path), path, note);
  if (ext == ".exo" || ext == ".e") {
    if (!opt.variable.empty()) params["variable"] = opt.variable;
    return told(validated(Scene::from_mesh(name, read_exodus(path, opt.variable, &note), params), path), path, note);
  }
  if (ends_with(path, ".inr.gz"))
    return validated(Scene::from_grid(std::filesystem::path(name).stem().string(), read_inr_gz(path), params), path);
  if (ext == ".node" || ext == ".ele") {
    const std::string node = ext == ".node" ? path : tetgen_partner(path, ".node");
    const std::string ele = tetgen_partner(node, ".ele");
    require_readable_file(node);
    require_readable_file(ele);
    return validated(Scene::from_mesh(name, read_tetgen(node, ele), params), path);
  }
  if (ext == ".inr") return validated(Scene::from_grid(name, read_inr(path), params), path);
  if (is_surface(ext)) {
    TriangleSoup soup = ext == ".off" ? read_off(path) : read_surface(path, &note);
    validate_triangle_soup(soup, path);
    if (soup.warped_polygons > 0) {
      char text[200];
      std::snprintf(text, sizeof text, "%zu polygons are not planar (the worst %.2g of its size off its plane): each split as a fan from its first corner",
                    soup.warped_polygons, soup.worst_warp);
      note += (note.empty() ? "" : "; ") + std::string(text);
    }
    if (!opt.tetrahedralize) return told(Scene::from_soup(name, std::move(soup), params), path, note);
    check_closed_surface(soup, path);
    params["tetgen"] = opt.tetgen_switches.empty() ? kDefaultTetgenSwitches : opt.tetgen_switches;
    return told(validated(Scene::from_mesh(name, tetrahedralize_surface(soup, path, opt.tetgen_switches), params), path), path, note);
  }
  if (ext == ".gz")
    throw InputError(path, "file", "of gzipped files only .inr.gz is read; decompress it first");
  throw InputError(path, "file", "unknown extension '" + ext +
                                     "' (expected .vtu .pvtu .vtk .vti .node .ele .inr .inr.gz .off .stl .ply .obj .msh .exo .e)");
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
