#include <algorithm>
#include <filesystem>

#include "harness/bench/reporters.h"
#include "harness/render/compositor.h"

namespace vob {

namespace {
std::string file_safe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
  return s;
}
}  // namespace

ImageReporter::ImageReporter(const SuiteSpec& suite, std::string image_dir, std::string results_dir)
    : suite_(suite), dir_(std::move(image_dir)), results_dir_(std::move(results_dir)) {}

bool ImageReporter::writes_files() const { return !suite_.image_views.empty() || suite_.images_of_violations; }

void ImageReporter::report(Measurement& m, const Scene& scene, const Camera& cam) const {
  namespace fs = std::filesystem;
  Record& rec = m.record;
  const bool want_images =
      std::count(suite_.image_views.begin(), suite_.image_views.end(), rec.view_index) > 0 ||
      (suite_.images_of_violations && m.violated);
  if (!suite_.image_error && !want_images) return;
  // The image error shares the two renders with the files: both are made here. A
  // compositing orderer is shown by what it composited against its own exact composite.
  const Image ordered = m.composited ? m.composited->ordered : render_in_order(scene, cam, m.ordering.order);
  const Image exact = m.composited ? m.composited->exact : render_exact(scene, cam);
  rec.image_error = image_error(ordered, exact).to_json();
  if (!want_images) return;
  const std::string stem =
      (fs::path(dir_) / file_safe(rec.dataset + "-" + rec.algorithm + "-v" + std::to_string(rec.view_index) +
                                  "-" + std::to_string(rec.w) + "x" + std::to_string(rec.h)))
          .string();
  fs::create_directories(dir_);
  write_png(ordered, stem + "-order.png");
  write_png(exact, stem + "-exact.png");
  write_png(difference_image(ordered, exact), stem + "-diff.png");
  // Paths relative to the folder of results.jsonl, so the folder can move (probes' too).
  const fs::path base = fs::absolute(results_dir_.empty() ? "." : results_dir_);
  const auto rel = [&](const std::string& path) {
    return fs::absolute(path).lexically_normal().lexically_relative(base.lexically_normal()).generic_string();
  };
  rec.images = {{"order", rel(stem + "-order.png")}, {"exact", rel(stem + "-exact.png")},
                {"diff", rel(stem + "-diff.png")}};
  // The violation map from the verdict's mask (the composited one for compositing orderers).
  if (m.verdict && !m.verdict->result.violation_mask.empty()) {
    write_png(violation_image(exact, m.verdict->result.violation_mask), stem + "-violations.png");
    rec.images["violations"] = rel(stem + "-violations.png");
  }
}

}  // namespace vob
