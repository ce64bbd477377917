// Probe stencil-layer-images (stencil_probes.h): Krishnan et al.'s Fig. 3.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "algorithms/stencil/stencil_layers.h"
#include "algorithms/stencil/stencil_probes.h"
#include "harness/oracle/oracle.h"
#include "harness/raster/polygon_raster.h"
#include "harness/render/compositor.h"
#include "harness/scene/input_error.h"

namespace vob {
namespace {

namespace fs = std::filesystem;

// A colour per layer: hues around the wheel, layer 0 red.
void layer_colour(int layer, float* rgb) {
  const double h = std::fmod(layer * 0.13, 1.0) * 6.0;
  const int i = int(h);
  const double f = h - i, q = 1 - f;
  double r = 0, g = 0, b = 0;
  switch (i % 6) {
    case 0: r = 1, g = f; break;
    case 1: r = q, g = 1; break;
    case 2: g = 1, b = f; break;
    case 3: g = q, b = 1; break;
    case 4: r = f, b = 1; break;
    default: r = 1, b = q; break;
  }
  rgb[0] = float(0.15 + 0.85 * r), rgb[1] = float(0.15 + 0.85 * g), rgb[2] = float(0.15 + 0.85 * b);
}

// Front-most triangle per pixel among those `keep` accepts, coloured by its layer (white:
// unclassified), on black.
Image layer_image(const Scene& s, const Camera& view, const std::vector<int32_t>& layer,
                  const std::function<bool(int32_t)>& keep) {
  const SampleFrame frame(view, 1);
  Image img;
  img.width = view.width;
  img.height = view.height;
  img.rgb.assign(size_t(img.width) * img.height * 3, 0.f);
  std::vector<double> depth(size_t(img.width) * img.height, 1e300);
  std::vector<int32_t> id(depth.size(), -1);
  const TriangleSoup& soup = s.soup();
  PolygonRaster raster;
  for (size_t t = 0; t < soup.num_triangles(); ++t) {
    if (!keep(int32_t(t))) continue;
    const Vec3 v[3] = {soup.points[soup.tris[t][0]], soup.points[soup.tris[t][1]], soup.points[soup.tris[t][2]]};
    if (!raster.setup(frame, v, 3)) continue;
    raster.scan(frame.bounds(), [&](int x, int y, double d) {
      const size_t p = size_t(y) * img.width + x;
      if (d < depth[p]) depth[p] = d, id[p] = int32_t(t);
    });
  }
  for (size_t p = 0; p < id.size(); ++p) {
    if (id[p] < 0) continue;
    const int l = layer[size_t(id[p])];
    if (l < 0)
      img.rgb[3 * p] = img.rgb[3 * p + 1] = img.rgb[3 * p + 2] = 1.f;
    else
      layer_colour(l, &img.rgb[3 * p]);
  }
  return img;
}

nlohmann::json run(Params& params, const ProbeContext& ctx) {
  const std::string backend = params.get_choice("backend", "gl", {"gl", "software"});
  const int max_images = params.get_int("images", 12, 0, 1000);
  if (params.dry_run()) return nlohmann::json::object();
  if (ctx.views.empty()) throw InputError("stencil-layer-images", ctx.dataset_label, "the suite gives no views");
  const Scene& s = *ctx.scene;
  const auto& [view_index, view] = ctx.views.front();
  Params op("stencil-layers");
  op.set("backend", backend);
  auto orderer = make_from_info(stencil_layers_orderer_info(), op);
  op.check_all_used();
  PhaseClock clock;
  orderer->prepare(s, clock);
  const Ordering o = orderer->order(view, clock);
  const OracleResult verdict = check_ordering(s, view, o.order);
  const int layers = int(o.counters.at("layers"));

  // Paths relative to the output folder (image_dir's parent), as records keep them.
  const fs::path dir(ctx.image_dir);
  fs::create_directories(dir);
  nlohmann::json images = nlohmann::json::object();
  auto save = [&](const Image& img, const std::string& name) {
    const std::string file = ctx.image_prefix + "-" + name + ".png";
    write_png(img, (dir / file).string());
    images[name] = (dir.filename() / file).string();
    return name;
  };
  const auto all = [](int32_t) { return true; };
  save(layer_image(s, view, o.layers, all), "a-layers");
  Camera back = view;
  back.eye = view.target * 2.0 - view.eye;  // the other side, as the paper's (b)
  save(layer_image(s, back, o.layers, all), "b-other-side");

  std::vector<int64_t> triangles(size_t(layers), 0);
  for (int32_t l : o.layers)
    if (l >= 0) ++triangles[size_t(l)];
  const int shown = max_images == 0 ? layers : std::min(layers, max_images);
  nlohmann::json layer_images = nlohmann::json::array();
  for (int l = 0; l < layers; ++l) {
    if (l >= shown) {
      layer_images.push_back(nullptr);
      continue;
    }
    char name[32];
    std::snprintf(name, sizeof name, "layer-%02d", l);
    layer_images.push_back(save(layer_image(s, view, o.layers, [&](int32_t t) { return o.layers[size_t(t)] == l; }), name));
  }
  return {{"backend", backend},
          {"view_index", view_index},
          {"w", view.width},
          {"h", view.height},
          {"layers", layers},
          {"triangles_per_layer", triangles},
          {"footprint", o.extras.at("footprint")},
          {"layer_images", layer_images},
          {"covered_pixels", o.counters.at("covered_pixels")},
          {"unclassified_visible", o.counters.at("unclassified_visible")},
          {"forced", o.counters.at("forced")},
          {"violating_pixels", verdict.violating_pixels},
          {"images", images}};
}

}  // namespace

ProbeInfo stencil_layer_images_probe_info() {
  return {"stencil-layer-images",
          "Krishnan et al. Fig. 3: triangles coloured by layer (from the view and the other side) and "
          "each layer's footprint as PNGs, with triangles and pixels per layer",
          true, run};
}

}  // namespace vob
