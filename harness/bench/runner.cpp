#include "harness/bench/runner.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "datasets/datasets.h"
#include "harness/bench/atomic_file.h"
#include "harness/bench/context.h"
#include "harness/bench/registry.h"
#include "harness/bench/results.h"
#include "harness/raster/polygon_raster.h"
#include "harness/render/compositor.h"
#include "harness/scene/cell_overlap.h"
#include "harness/scene/input_error.h"
#include "harness/view/view_set.h"

namespace vob {

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }
std::string file_safe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
  return s;
}
}  // namespace

PreparedOrderer prepare_orderer(const std::string& spec, const Scene& scene) {
  PreparedOrderer p;
  p.spec = spec;
  p.orderer = make_orderer(spec);
  p.info = &spec_orderer(spec);
  if (p.info->kind != scene.kind())
    throw InputError("--algorithm", spec,
                     std::string("orders ") + scene_kind_name(p.info->kind) +
                         ", but scene '" + scene.name() + "' has " + scene_kind_name(scene.kind()));
  p.scene = scene.fresh();
  const auto t0 = std::chrono::steady_clock::now();
  p.orderer->prepare(p.scene, p.prepare_clock);
  p.prepare_seconds = seconds_since(t0);
  return p;
}

nlohmann::json FrameMeasurement::phases_json() const {
  nlohmann::json j = nlohmann::json::object();
  if (repeats.empty()) return j;
  for (const auto& [name, _] : repeats.back()) {
    std::vector<double> v;
    for (const auto& r : repeats)
      for (const auto& [n, s] : r)
        if (n == name) v.push_back(s);
    j[name] = {{"min", *std::min_element(v.begin(), v.end())}, {"median", median(v)}};
  }
  return j;
}

nlohmann::json FrameMeasurement::total_json() const {
  std::vector<double> v;
  for (const auto& r : repeats) {
    double t = 0;
    for (const auto& [n, s] : r) t += s;
    v.push_back(t);
  }
  if (v.empty()) return {{"min", 0.0}, {"median", 0.0}};
  return {{"min", *std::min_element(v.begin(), v.end())}, {"median", median(v)}};
}

double FrameMeasurement::total_median() const { return total_json()["median"].get<double>(); }

FrameMeasurement measure_frame(PreparedOrderer& p, const Camera& view, int warmup, int repeats) {
  FrameMeasurement m;
  for (int i = 0; i < warmup; ++i) {
    PhaseClock c;
    p.orderer->order(view, c);
  }
  for (int i = 0; i < repeats; ++i) {
    PhaseClock c;
    m.ordering = p.orderer->order(view, c);
    m.repeats.push_back(c.phases());
  }
  return m;
}

void check_complete(const Scene& scene, const Ordering& o, const std::string& who) {
  const std::vector<int32_t>* ids = nullptr;
  size_t n = scene.num_primitives();
  if (scene.kind() == SceneKind::Voxels) ids = &scene.significant_voxels();
  if (o.order.size() != n)
    throw std::logic_error(who + ": ordering has " + std::to_string(o.order.size()) +
                           " entries for " + std::to_string(n) + " primitives");
  if (ids) {
    std::vector<int32_t> sorted = o.order;
    std::sort(sorted.begin(), sorted.end());
    if (sorted != *ids) throw std::logic_error(who + ": ordering is not a permutation of the significant voxels");
    return;
  }
  std::vector<char> seen(n, 0);
  for (int32_t id : o.order) {
    if (id < 0 || static_cast<size_t>(id) >= n || seen[id])
      throw std::logic_error(who + ": ordering repeats or invents primitive " + std::to_string(id));
    seen[id] = 1;
  }
}

std::vector<std::pair<int, Camera>> dataset_views(const DatasetSpec& spec, const Scene& scene,
                                                  int count, const std::vector<int>& indices,
                                                  int width, int height, bool ortho, double zoom) {
  std::vector<std::pair<int, Camera>> out;
  if (spec.input.empty()) {
    const DatasetInfo& info = find_dataset(spec.name);
    if (info.views) {
      const auto cams = info.views(scene, width, height);
      for (size_t i = 0; i < cams.size(); ++i)
        if (indices.empty() || std::count(indices.begin(), indices.end(), int(i)))
          out.emplace_back(int(i), cams[i]);
      return out;
    }
  }
  ViewOptions vo;
  vo.width = width;
  vo.height = height;
  vo.ortho = ortho;
  vo.zoom = zoom;
  const Aabb box = scene.bounds();
  if (indices.empty())
    for (int i = 0; i < count; ++i) out.emplace_back(i, fibonacci_view(box, count, i, vo));
  else
    for (int i : indices) out.emplace_back(i, fibonacci_view(box, count, i, vo));
  return out;
}

std::vector<std::string> algorithms_for(const std::vector<std::string>& listed, SceneKind kind) {
  std::vector<std::string> out;
  for (const auto& a : listed) {
    if (a == "all") {
      for (const auto& info : orderer_registry())
        if (info.kind == kind && std::find(out.begin(), out.end(), info.name) == out.end())
          out.push_back(info.name);
      continue;
    }
    const auto name = Params::parse_spec(a).first;
    if (find_orderer(name).kind == kind && std::find(out.begin(), out.end(), a) == out.end())
      out.push_back(a);
  }
  return out;
}

nlohmann::json scene_facts(const Scene& scene) {
  nlohmann::json j{{"kind", scene_kind_name(scene.kind())}, {"n", scene.num_primitives()}};
  if (scene.kind() == SceneKind::Cells) {
    const CellMesh& m = scene.mesh();
    j["points"] = m.num_points();
    j["b"] = scene.faces().boundary.size();
    nlohmann::json types = nlohmann::json::object();
    for (CellType t : m.types) {
      const std::string name = cell_type_name(t);
      types[name] = types.value(name, 0) + 1;
    }
    j["cell_types"] = types;
  } else if (scene.kind() == SceneKind::Triangles) {
    j["points"] = scene.soup().points.size();
  } else {
    const VoxelGrid& g = scene.grid();
    j["dims"] = {g.dims[0], g.dims[1], g.dims[2]};
    j["voxels"] = g.num_voxels();
  }
  return j;
}

int64_t exterior_area_pixels(const Scene& scene, const Camera& view) {
  const SampleFrame frame(view, 1);
  const MeshFaces& faces = scene.faces();
  const CellMesh& mesh = scene.mesh();
  int64_t covered = 0;
  for (int32_t f : faces.boundary) {
    Vec3 v[4];
    const int n = faces.face_size(f);
    for (int i = 0; i < n; ++i) v[i] = mesh.points[faces.face_points(f)[i]];
    rasterize_polygon(frame, v, n, frame.bounds(), [&](int, int, double) { ++covered; });
  }
  return covered;
}

RunSummary run_suite(const SuiteSpec& suite, const RunOptions& opt) {
  namespace fs = std::filesystem;
  RunSummary summary;
  ResultsFile results(opt.results_path);
  const std::string image_dir =
      !opt.image_dir.empty() ? opt.image_dir
                             : (fs::path(opt.results_path).parent_path() / "images").string();
  if (!suite.image_views.empty() || suite.images_of_violations) require_writable_folder(image_dir);
  const nlohmann::json context = run_context();
  auto say = [&](const std::string& s) {
    if (opt.progress) opt.progress(s);
  };
  auto stop = [&] { return summary.stopped = opt.stop_requested && opt.stop_requested(); };
  for (size_t di = 0; di < suite.datasets.size(); ++di) {
    const DatasetSpec& ds = suite.datasets[di];
    if (stop()) return summary;
    const auto t0 = std::chrono::steady_clock::now();
    const Scene scene = make_scene(ds);
    if (opt.validate_full && scene.kind() == SceneKind::Cells) {
      const CellOverlapReport overlaps = check_overlapping_cells(scene.mesh(), scene.faces());
      if (!overlaps.pairs.empty())
        throw InputError(describe_overlap(ds.input.empty() ? ds.label() : ds.input, overlaps));
    }
    const nlohmann::json facts = scene_facts(scene);
    say("dataset " + std::to_string(di + 1) + "/" + std::to_string(suite.datasets.size()) + " " +
        ds.label() + ": " + std::to_string(scene.num_primitives()) + " " +
        scene_kind_name(scene.kind()) + " (" + std::to_string(seconds_since(t0)).substr(0, 5) + " s)");
    const auto algorithms = algorithms_for(suite.algorithms, scene.kind());
    for (const auto& spec : algorithms) {
      std::unique_ptr<PreparedOrderer> prepared;  // only when some record is missing
      for (const auto& [w, h] : suite.sizes) {
        const auto views = dataset_views(ds, scene, suite.views, suite.view_indices, w, h,
                                         suite.ortho, suite.zoom);
        for (const auto& [vi, cam] : views) {
          const std::string key = suite.name + "|" + spec + "|" + ds.label() + "|v" +
                                  std::to_string(vi) + "/" + std::to_string(suite.views) + "|" +
                                  size_text(w, h) + "|s" + std::to_string(suite.supersample) +
                                  (suite.ortho ? "|ortho" : "") +
                                  (suite.zoom != 1.0 ? "|zoom" + std::to_string(suite.zoom) : "");
          if (stop()) return summary;
          if (results.has(key)) {
            ++summary.skipped;
            continue;
          }
          if (!prepared) prepared = std::make_unique<PreparedOrderer>(prepare_orderer(spec, scene));
          PreparedOrderer& p = *prepared;
          FrameMeasurement m = measure_frame(p, cam, suite.warmup, suite.repeats);
          check_complete(scene, m.ordering, spec);
          nlohmann::json rec;
          rec["key"] = key;
          rec["suite"] = suite.name;
          rec["algorithm"] = spec;
          rec["orderer"] = p.info->name;
          rec["parameters"] = resolved_parameters(spec);
          const Claims cl = p.orderer->claims();
          rec["claims"] = {{"object_exact", cl.object_exact}, {"image_exact", cl.image_exact}};
          rec["dataset"] = ds.label();
          rec["dataset_spec"] = ds.to_json();
          for (const auto& [k, v] : facts.items()) rec[k] = v;
          rec["w"] = w;
          rec["h"] = h;
          rec["pixels"] = int64_t(w) * h;
          rec["view_index"] = vi;
          rec["views"] = suite.views;
          rec["camera"] = cam.to_json();
          rec["repeats"] = suite.repeats;
          rec["warmup"] = suite.warmup;
          rec["phases"] = m.phases_json();
          rec["total"] = m.total_json();
          nlohmann::json prep_phases = nlohmann::json::object();
          for (const auto& [n, s] : p.prepare_clock.phases()) prep_phases[n] = s;
          nlohmann::json derived = nlohmann::json::array();
          for (const auto& d : p.scene.derived_stats())
            derived.push_back({{"name", d.name}, {"seconds", d.seconds}, {"bytes", d.bytes}});
          rec["prepare"] = {{"seconds", p.prepare_seconds}, {"phases", prep_phases}, {"derived", derived}};
          rec["bytes"] = {{"orderer", p.orderer->bytes()},
                          {"scene", scene.bytes()},
                          {"derived", p.scene.derived_bytes()}};
          rec["cycles"] = {{"count", m.ordering.cycles.cycles},
                           {"primitives", m.ordering.cycles.primitives.size() > 20
                                              ? std::vector<int32_t>(m.ordering.cycles.primitives.begin(),
                                                                     m.ordering.cycles.primitives.begin() + 20)
                                              : m.ordering.cycles.primitives}};
          rec["counters"] = m.ordering.counters;
          if (scene.kind() == SceneKind::Cells) rec["a"] = exterior_area_pixels(scene, cam);
          std::string verdict;
          bool violated = false;
          if (suite.oracle) {
            OracleOptions oo;
            oo.supersample = suite.supersample;
            const OracleResult r = check_ordering(scene, cam, m.ordering.order, oo);
            rec["oracle"] = r.to_json();
            // Overlapping cells: the input has no visibility order; not the orderer's fault.
            if (r.input_fault())
              rec["input_fault"] = {{"overlapping_pairs", r.overlapping_pairs},
                                    {"examples", r.overlap_examples}};
            violated = !r.ok() && !r.input_fault();
            if (violated) ++summary.violations;
            verdict = r.input_fault() ? ", input fault: " + std::to_string(r.overlapping_pairs) +
                                            " overlapping cell pairs"
                                      : ", " + std::to_string(r.violating_pixels) + " violating pixels";
          }
          const bool want_images =
              std::count(suite.image_views.begin(), suite.image_views.end(), vi) > 0 ||
              (suite.images_of_violations && violated);
          if (suite.image_error || want_images) {
            const Image ordered = render_in_order(scene, cam, m.ordering.order);
            const Image exact = render_exact(scene, cam);
            rec["image_error"] = image_error(ordered, exact).to_json();
            if (want_images) {
              const std::string stem = (fs::path(image_dir) /
                                        file_safe(ds.label() + "-" + spec + "-v" +
                                                  std::to_string(vi) + "-" + size_text(w, h)))
                                           .string();
              fs::create_directories(image_dir);
              write_png(ordered, stem + "-order.png");
              write_png(exact, stem + "-exact.png");
              write_png(difference_image(ordered, exact), stem + "-diff.png");
              rec["images"] = {{"order", stem + "-order.png"},
                               {"exact", stem + "-exact.png"},
                               {"diff", stem + "-diff.png"}};
            }
          }
          rec["context"] = context;
          std::ostringstream line;
          line << "  " << spec << " on " << ds.label() << " view " << vi << " " << size_text(w, h) << ": ";
          if (results.append(rec)) {
            ++summary.written;
            line << m.total_median() * 1e3 << " ms/frame" << verdict;
          } else {
            ++summary.written_elsewhere;
            line << "another run wrote this record meanwhile; kept theirs";
          }
          say(line.str());
        }
      }
    }
  }
  return summary;
}

}  // namespace vob
