#include "algorithms/havs/gl/gl_race_probe.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>

#include "algorithms/havs/gl/gl_kbuffer.h"
#include "algorithms/havs/havs_frame.h"
#include "harness/raster/polygon_raster.h"
#include "harness/raster/sample_frame.h"
#include "harness/render/compositor.h"

namespace vob {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

template <class F>
double median_seconds(int repeats, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < std::max(repeats, 1); ++i) {
    const auto t0 = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// Fragments per pixel as the harness rasterizer sees them under `rule`: exact is what the
// software k-buffer rasterizes; gl is llvmpipe's rule (raster_rule.h) on the harness' own
// projection, which the GL k-buffer's float vertex transform reaches up to rounding.
std::vector<uint32_t> pixel_fragment_counts(const havs::FaceData& fd, const Camera& cam,
                                            RasterRule rule = RasterRule::exact) {
  const SampleFrame frame(cam, 1, rule);
  std::vector<uint32_t> n(size_t(frame.num_samples()), 0);
  const MeshFaces& mf = *fd.faces;
  Vec3 v[4];
  for (size_t f = 0; f < mf.num_faces(); ++f) {
    const int m = mf.face_size(f);
    for (int i = 0; i < m; ++i) v[i] = fd.scene.mesh().points[mf.face_points(f)[i]];
    rasterize_polygon(frame, v, m, frame.bounds(), [&](int sx, int sy, double) { ++n[frame.index(sx, sy)]; });
  }
  for (uint32_t& c : n) c = std::min<uint32_t>(c, 0xffff);
  return n;
}

nlohmann::json run_gl(Params& p, const ProbeContext& ctx) {
  const int k = p.get_int("k", 2, 1, havs::kMaxK);
  if (p.dry_run()) return nlohmann::json::object();
  const havs::FaceData fd = havs::build_face_data(*ctx.scene);
  nlohmann::json out{{"k", k}, {"cells", ctx.scene->num_primitives()}, {"faces", fd.faces->num_faces()}};
  const char* lp_threads = std::getenv("LP_NUM_THREADS");
  out["lp_num_threads"] = lp_threads ? nlohmann::json(lp_threads) : nlohmann::json();
  std::unique_ptr<havs::GlKBuffer> gl;
  try {
    gl = std::make_unique<havs::GlKBuffer>(fd);
  } catch (const havs::GlUnavailable& e) {
    // No context on this machine: a record that says so, which the table shows.
    out["available"] = false;
    out["reason"] = e.what();
    return out;
  }
  out["available"] = true;
  out["gl_version"] = gl->version();
  out["gl_renderer"] = gl->renderer();
  fs::create_directories(ctx.image_dir);
  const std::string img_dir = fs::path(ctx.image_dir).filename().string();
  nlohmann::json views = nlohmann::json::array(), images = nlohmann::json::object();
  for (size_t vi = 0; vi < ctx.views.size(); ++vi) {
    const auto& [index, cam] = ctx.views[vi];
    havs::SortBuffers sb;
    std::vector<int32_t> order;
    havs::sort_faces(fd, cam, sb, order);
    Image sw, glb, gls;
    havs::RenderStats rs;
    havs::GlFrameStats gb, gsr;
    // Warm-ups (at least one: it also gives GL's per-pixel fragment counts): the software
    // bands' first touch, the GL programs and images for this k.
    std::vector<uint32_t> gl_pixel_frags;
    for (int w = 0; w < std::max(ctx.warmup, 1); ++w) {
      havs::render_kbuffer(fd, cam, order, k, sw);
      gl->render(cam, order, k, havs::GlDrawMode::Batched, glb, &gl_pixel_frags);
    }
    // Pixels where GL's coverage differs from the harness rasterizer's (fragment counts).
    std::vector<uint8_t> cov_diff(gl_pixel_frags.size(), 0), rule_diff(gl_pixel_frags.size(), 0);
    {
      const std::vector<uint32_t> sw_frags = pixel_fragment_counts(fd, cam);
      const std::vector<uint32_t> rule_frags = pixel_fragment_counts(fd, cam, RasterRule::gl);
      for (size_t q = 0; q < cov_diff.size(); ++q) {
        cov_diff[q] = sw_frags[q] != gl_pixel_frags[q];
        rule_diff[q] = rule_frags[q] != gl_pixel_frags[q];
      }
    }
    const double t_sw = median_seconds(ctx.repeats, [&] { rs = havs::render_kbuffer(fd, cam, order, k, sw); });
    // Every batched frame is compared with the serialized image: a race shows up in any.
    std::vector<Image> batched;
    const double t_gl = median_seconds(ctx.repeats, [&] {
      gb = gl->render(cam, order, k, havs::GlDrawMode::Batched, glb);
      batched.push_back(glb);
    });
    const double t_ser =
        median_seconds(ctx.repeats, [&] { gsr = gl->render(cam, order, k, havs::GlDrawMode::Serialized, gls); });
    const havs::ImageCompare8 c_gl = havs::compare_8bit(glb, sw), c_ser = havs::compare_8bit(gls, sw);
    // The software k-buffer under the gl sampling rule (llvmpipe's coverage, the planes'
    // own depths, as the shader): what is left differs where llvmpipe's float vertex
    // transform snaps otherwise than the rule, or by rounding.
    Image sw_rule;
    havs::render_kbuffer(fd, cam, order, k, sw_rule, nullptr, RasterRule::gl);
    const havs::ImageCompare8 c_rule = havs::compare_8bit(gls, sw_rule);
    int64_t rule_at_cov = 0;
    for (size_t q = 0; q < c_rule.mask.size(); ++q) rule_at_cov += c_rule.mask[q] && rule_diff[q];
    std::vector<uint8_t> race_mask(c_gl.mask.size(), 0);
    for (const Image& b : batched) {
      const havs::ImageCompare8 c = havs::compare_8bit(b, gls);
      for (size_t q = 0; q < c.mask.size(); ++q) race_mask[q] |= c.mask[q];
    }
    int64_t race_px = 0, cov_px = 0, diff_cov = 0, covered = 0, rule_px = 0, diff_rule = 0;
    for (size_t q = 0; q < rule_diff.size(); ++q) {
      rule_px += rule_diff[q];
      diff_rule += rule_diff[q] && c_ser.mask[q];
    }
    for (uint8_t m : race_mask) race_px += m;
    for (size_t q = 0; q < cov_diff.size(); ++q) {
      cov_px += cov_diff[q];
      diff_cov += cov_diff[q] && c_ser.mask[q];
    }
    for (size_t q = 0; q < sw.rgb.size(); q += 3) covered += sw.rgb[q] + sw.rgb[q + 1] + sw.rgb[q + 2] > 0;
    views.push_back({{"view", index}, {"software_s", t_sw}, {"gl_batched_s", t_gl}, {"gl_serialized_s", t_ser},
                     {"serialized_draws", gsr.draws}, {"software_fragments", rs.fragments},
                     {"gl_fragments", gb.fragments}, {"gl_serialized_fragments", gsr.fragments},
                     {"covered_pixels", covered}, {"coverage_differing_pixels", cov_px},
                     {"serialized_vs_sw_differing_with_coverage_difference", diff_cov},
                     // llvmpipe's fragment counts against the gl sampling rule's
                     {"coverage_differing_pixels_gl_rule", rule_px},
                     {"serialized_vs_sw_differing_with_gl_rule_coverage_difference", diff_rule},
                     {"serialized_vs_sw_gl_rule",
                      {{"differing", c_rule.differing}, {"differing_by_more_than_1", c_rule.differing_by_more_than_1},
                       {"max", c_rule.max_diff}, {"rms", c_rule.rms},
                       {"differing_with_gl_rule_coverage_difference", rule_at_cov}}},
                     {"gl_vs_sw", {{"differing", c_gl.differing}, {"max", c_gl.max_diff}, {"rms", c_gl.rms}}},
                     {"serialized_vs_sw",
                      {{"differing", c_ser.differing}, {"differing_by_more_than_1", c_ser.differing_by_more_than_1},
                       {"max", c_ser.max_diff}, {"rms", c_ser.rms}}},
                     {"race_changed_pixels", race_px}, {"batched_frames_compared", batched.size()}});
    // The GL image of the first view and every view's difference image (white: > 1/255).
    const std::string stem = ctx.image_prefix + "-v" + std::to_string(index);
    if (vi == 0) {
      write_png(glb, (fs::path(ctx.image_dir) / (stem + "-gl.png")).string());
      images["gl-v" + std::to_string(index)] = img_dir + "/" + stem + "-gl.png";
    }
    write_png(difference_image(glb, sw), (fs::path(ctx.image_dir) / (stem + "-diff.png")).string());
    images["diff-v" + std::to_string(index)] = img_dir + "/" + stem + "-diff.png";
    if (ctx.progress)
      ctx.progress("view " + std::to_string(index) + " k=" + std::to_string(k) + ": sw " +
                   std::to_string(t_sw * 1e3) + " ms, gl " + std::to_string(t_gl * 1e3) + " ms, serialized " +
                   std::to_string(t_ser * 1e3) + " ms; race-changed pixels " + std::to_string(race_px));
  }
  out["views"] = views;
  if (!ctx.views.empty()) out["size"] = {ctx.views[0].second.width, ctx.views[0].second.height};
  out["images"] = images;
  return out;
}

}  // namespace

ProbeInfo havs_gl_probe_info() {
  return {"havs-gl",
          "HAVS k-buffer as an OpenGL fragment shader on OSMesa against the software k-buffer "
          "(k=2): per view, times (batched, serialized, software), 8-bit image differences, "
          "coverage differences and race-changed pixels; GL and difference images",
          true, run_gl};
}

}  // namespace vob
