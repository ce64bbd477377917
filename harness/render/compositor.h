// A minimal emission-absorption compositor: renders a scene in a given back-to-front order
// and in the exact per-pixel order, and measures what ordering errors do to the image.
// Fragments come from the oracle's collector (raster/fragments.h) at pixel centres, over a
// black background:
// - cells: colour from the cell's mean scalar (normalised by the point scalar range) on a
//   green-to-pink ramp; extinction tau = (2.4 / bounding radius) * (0.25 + 0.75 s), so a
//   typical ray through the mesh has an optical depth of about 2; each segment adds
//   C = c (1 - exp(-tau len)) + C exp(-tau len).
// - triangles: alpha 0.3, pale blue with two-sided headlight shading.
// - voxels: the oracle's splat footprint with a Gaussian falloff, alpha and colour from the
//   value (normalised from the threshold to the largest value).
// render_in_order composites each pixel's fragments in drawing order; render_exact in
// exact depth order (far to near by segment midpoint, ties by primitive id).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/scene/scene.h"
#include "harness/view/camera.h"

namespace vob {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // row 0 at the bottom (window convention), 3 floats per pixel in [0,1]
};

struct ImageError {
  double rmse = 0, max_error = 0;
  int64_t pixels_off = 0;  // pixels with some channel off by more than 1/255
  nlohmann::json to_json() const;  // keys: rmse, max_error, pixels_off
};

struct RenderOptions {
  double splat_radius_px = 0;  // voxels; 0 = projected voxel size
};

Image render_in_order(const Scene& scene, const Camera& view, const std::vector<int32_t>& order,
                      const RenderOptions& opt = {});
Image render_exact(const Scene& scene, const Camera& view, const RenderOptions& opt = {});
ImageError image_error(const Image& a, const Image& b);
// White where a and b differ by more than 1/255, the exact image dimmed elsewhere.
Image difference_image(const Image& test, const Image& exact);
// The violation map: the exact image dimmed to kViolationDim, and every pixel whose mask
// byte (index y * width + x, row 0 at the bottom) is set painted pure red, one pixel each,
// not dilated, so the red pixels number exactly the verdict's violating_pixels (a dimmed
// pixel never reaches a red of 1).
constexpr float kViolationDim = 0.3f;
Image violation_image(const Image& exact, const std::vector<uint8_t>& mask);
// Pixels painted as violating by violation_image (pure red at 8 bits).
int64_t marked_pixels(const Image& violations);
// PNG through VTK's writer; written atomically (temporary file, then rename).
void write_png(const Image& img, const std::string& path);
// An 8-bit RGB PNG back (row 0 at the bottom, as written); for tests.
Image read_png(const std::string& path);

}  // namespace vob
