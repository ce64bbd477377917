#include "vtk/render/render_report.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "harness/bench/atomic_file.h"
#include "harness/scene/input_error.h"

namespace vob {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

nlohmann::json summary(const RenderRun& run) {
  nlohmann::json out = nlohmann::json::array();
  for (size_t s = 0; s < run.sorters.size(); ++s) {
    std::vector<double> frame, sort, ratio;
    int64_t views_off = 0, pixels = 0;
    int max = 0;
    for (const ViewFrames& v : run.views) {
      const SorterFrame& f = v.sorters[s];
      frame.push_back(median(f.frame_seconds));
      sort.push_back(median(f.sort_seconds));
      ratio.push_back(frame.back() / median(v.sorters[0].frame_seconds));
      views_off += f.diff.pixels > 0;
      pixels += f.diff.pixels;
      max = std::max(max, f.diff.max);
    }
    nlohmann::json j = {{"sorter", run.sorters[s].label},
                        {"median_frame_seconds", median(frame)},
                        {"median_sort_seconds", median(sort)},
                        {"median_frame_ratio_to_vtk_default", median(ratio)}};
    if (run.reference >= 0)
      j["difference_from_reference"] = {{"views_differing", views_off}, {"pixels", pixels}, {"max", max}};
    out.push_back(j);
  }
  return out;
}

namespace {
nlohmann::json seconds_json(const std::vector<double>& v) {
  return {{"median", median(v)}, {"samples", v}};
}

void write_text(const std::string& path, const std::string& text) {
  write_file_atomically(path, text);
}
}  // namespace

void write_render_json(const RenderRun& run, const std::string& dir) {
  nlohmann::json j = run.context;
  j["sorters"] = nlohmann::json::array();
  for (const SorterInfo& s : run.sorters)
    j["sorters"].push_back({{"label", s.label},
                            {"algorithm", s.algorithm},
                            {"claims", {{"object_exact", s.object_exact}, {"image_exact", s.image_exact}}},
                            {"prepare_seconds", s.prepare_seconds >= 0 ? nlohmann::json(s.prepare_seconds)
                                                                       : nlohmann::json()}});
  j["reference"] = run.reference >= 0 ? nlohmann::json(run.sorters[run.reference].label) : nlohmann::json();
  j["views"] = nlohmann::json::array();
  for (const ViewFrames& v : run.views) {
    nlohmann::json jv = {{"view_index", v.view_index}, {"camera", v.camera.to_json()}};
    for (size_t s = 0; s < v.sorters.size(); ++s) {
      const SorterFrame& f = v.sorters[s];
      nlohmann::json jf = {{"sorter", run.sorters[s].label},
                           {"frame_seconds", seconds_json(f.frame_seconds)},
                           {"sort_seconds", seconds_json(f.sort_seconds)},
                           {"image", f.image},
                           {"covered_pixels", f.covered}};
      if (f.compared)
        jf["difference"] = {{"pixels", f.diff.pixels}, {"max", f.diff.max}, {"image", f.diff_image}};
      jv["results"].push_back(jf);
    }
    j["views"].push_back(jv);
  }
  j["summary"] = summary(run);
  write_text(dir + "/render.json", j.dump(1) + "\n");
}

void write_render_html(const RenderRun& run, const std::string& dir) {
  std::ostringstream h;
  h << std::setprecision(3);
  h << "<!doctype html><meta charset=utf-8><title>vobench-vtk render</title>\n"
       "<style>body{font-family:sans-serif}td,th{padding:4px;vertical-align:top;text-align:center}"
       "img{width:256px;image-rendering:pixelated}</style>\n";
  h << "<h1>What VTK shows: vtkOpenGLProjectedTetrahedraMapper</h1>\n<p>"
    << run.context.value("scene", nlohmann::json()).dump() << "; " << run.context.value("tetrahedra", 0)
    << " tetrahedra; " << run.context.value("gl_renderer", std::string()) << "; machine state: "
    << run.context.value("load", std::string()) << ".</p>\n";
  h << "<p>Reference: "
    << (run.reference >= 0 ? run.sorters[run.reference].label : std::string("none (no exact orderer given)"))
    << ". A pixel differs when any 8-bit channel does.</p>\n<table border=1><tr><th>sorter</th>"
       "<th>views differing</th><th>pixels</th><th>max</th><th>frame ms (median)</th>"
       "<th>sort ms</th><th>frame / VTK's</th></tr>\n";
  for (const auto& s : summary(run)) {
    const auto d = s.value("difference_from_reference", nlohmann::json::object());
    h << "<tr><td>" << s["sorter"].get<std::string>() << "</td><td>" << d.value("views_differing", 0)
      << "</td><td>" << d.value("pixels", 0) << "</td><td>" << d.value("max", 0) << "</td><td>"
      << 1e3 * s["median_frame_seconds"].get<double>() << "</td><td>"
      << 1e3 * s["median_sort_seconds"].get<double>() << "</td><td>"
      << s["median_frame_ratio_to_vtk_default"].get<double>() << "</td></tr>\n";
  }
  h << "</table>\n<table><tr><th>view</th>";
  for (const SorterInfo& s : run.sorters) h << "<th>" << s.label << "</th>";
  h << "</tr>\n";
  for (const ViewFrames& v : run.views) {
    h << "<tr><td>" << v.view_index << "</td>";
    for (const SorterFrame& f : v.sorters) {
      h << "<td><img src=\"" << f.image << "\"><br>" << 1e3 * median(f.frame_seconds) << " ms";
      if (f.compared)
        h << "<br><a href=\"" << f.diff_image << "\">" << f.diff.pixels << " px differ (max " << f.diff.max
          << ")</a>";
      h << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table>\n";
  write_text(dir + "/render.html", h.str());
}

}  // namespace vob
