#include "algorithms/havs/havs_probes.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <filesystem>
#include <random>

#include "algorithms/havs/havs_frame.h"
#include "algorithms/havs/reference_sorts.h"
#include "harness/render/compositor.h"
#include "harness/sort/radix_sort.h"

namespace vob {
namespace {

using Clock = std::chrono::steady_clock;

nlohmann::json run_sorts(Params& p, const ProbeContext& ctx) {
  const size_t n = size_t(p.get_int("n", 1000000, 1, 100000000));
  const int seed = p.get_int("seed", 1, 0, INT_MAX);
  const std::string sort = p.get_choice("sort", "radix", {"shell", "heap", "quick", "stable", "radix"});
  if (p.dry_run()) return nlohmann::json::object();
  std::mt19937 rng(static_cast<uint32_t>(seed));
  std::uniform_real_distribution<float> u(-1000.f, 1000.f);
  std::vector<float> src(n);
  for (float& k : src) k = u(rng);
  std::vector<havs::KeyId> pairs(n);
  std::vector<float> keys;
  std::vector<int32_t> ids(n);
  std::vector<uint64_t> scratch;
  // Each run sorts a fresh copy of the same keys; the copy is not timed.
  const auto once = [&] {
    if (sort == "radix") {
      keys = src;
      for (size_t q = 0; q < n; ++q) ids[q] = int32_t(q);
    } else {
      for (size_t q = 0; q < n; ++q) pairs[q] = {src[q], int32_t(q)};
    }
    const auto t0 = Clock::now();
    if (sort == "shell") havs::shellsort(pairs);
    else if (sort == "heap") havs::heapsort(pairs);
    else if (sort == "quick") havs::quicksort(pairs);
    else if (sort == "stable") havs::stable_sort(pairs);
    else radix_sort_by_key(keys, ids, scratch);
    return std::chrono::duration<double>(Clock::now() - t0).count();
  };
  if (ctx.progress) ctx.progress("sorting " + std::to_string(n) + " keys with " + sort);
  for (int i = 0; i < ctx.warmup; ++i) once();
  std::vector<double> samples;
  for (int i = 0; i < std::max(ctx.repeats, 1); ++i) samples.push_back(once());
  // A sort that does not sort would time nothing useful: check the output once.
  bool sorted = true;
  if (sort == "radix") sorted = std::is_sorted(keys.begin(), keys.end());
  else sorted = std::is_sorted(pairs.begin(), pairs.end(), havs::key_less);
  std::vector<double> s = samples;
  std::sort(s.begin(), s.end());
  return {{"sort", sort}, {"n", n}, {"seed", seed}, {"samples_s", samples}, {"min_s", s.front()},
          {"median_s", s[s.size() / 2]}, {"sorted", sorted}};
}

nlohmann::json run_analysis(Params& p, const ProbeContext& ctx) {
  // The analysis needs a face order; k only decides the k-buffer rerun, not the columns.
  const int k = p.get_int("k", 2, 1, havs::kMaxK);
  if (p.dry_run()) return nlohmann::json::object();
  const havs::FaceData fd = havs::build_face_data(*ctx.scene);
  std::filesystem::create_directories(ctx.image_dir);
  nlohmann::json views = nlohmann::json::array();
  int64_t worst_score = -1;
  int worst = -1;
  havs::SortBuffers sb;
  std::vector<int32_t> order;
  for (const auto& [index, cam] : ctx.views) {
    havs::sort_faces(fd, cam, sb, order);
    const havs::Analysis a = havs::analyze(fd, cam, order, k);
    views.push_back({{"view", index}, {"fragments", a.fragments}, {"covered_pixels", a.covered_pixels},
                     {"max_list", a.max_list}, {"max_k", a.max_k_needed},
                     {"k_gt_2", a.pixels_k_above(2)}, {"k_gt_6", a.pixels_k_above(6)}});
    // Fig. 6 shows the view with the most pixels needing k > 2 (ties: the larger max k).
    const int64_t score = a.pixels_k_above(2) * 1000000 + a.max_k_needed;
    if (score > worst_score) {
      worst_score = score;
      worst = index;
      write_png(havs::k_needed_image(a, cam.width, cam.height),
                (std::filesystem::path(ctx.image_dir) / (ctx.image_prefix + "-kmap.png")).string());
    }
    if (ctx.progress)
      ctx.progress("view " + std::to_string(index) + ": " + std::to_string(a.fragments) +
                   " fragments, max k " + std::to_string(a.max_k_needed));
  }
  nlohmann::json out{{"k", k}, {"faces", fd.faces->num_faces()}, {"views", views}, {"worst_view", worst}};
  if (!ctx.views.empty()) out["size"] = {ctx.views[0].second.width, ctx.views[0].second.height};
  if (worst >= 0) {
    const std::string dir = std::filesystem::path(ctx.image_dir).filename().string();
    out["images"] = {{"kmap", dir + "/" + ctx.image_prefix + "-kmap.png"}};
  }
  return out;
}

}  // namespace

ProbeInfo havs_sorts_probe_info() {
  return {"havs-sorts",
          "HAVS Table 1: one sort (sort=shell|heap|quick|stable|radix) of n=1000000 uniform "
          "(float, int32 id) pairs (seed=1); per-run seconds, median and min",
          false, run_sorts};
}

ProbeInfo havs_analysis_probe_info() {
  return {"havs-analysis",
          "HAVS Table 2 / Fig. 6: per view, face fragments, longest A-buffer list, largest k "
          "needed and pixels needing k > 2 and > 6 (face order of the centroid radix sort); "
          "the k map of the view with most k > 2 pixels as a PNG",
          true, run_analysis};
}

}  // namespace vob
