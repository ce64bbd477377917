// Camera and the pixel-sampling convention (DESIGN.md "Views"):
// OpenGL conventions, window y up; pixel (i, j) is sampled at window (i + 0.5, j + 0.5);
// depth is the ray parameter t: distance from the eye (perspective) or distance along the
// view direction from the eye plane (orthographic), never NDC z.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "harness/geometry/vec3.h"

namespace vob {

struct Ray {
  Vec3 origin, dir;  // dir unit length
};

struct Camera {
  Vec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  bool ortho = false;
  double fov_deg = 40.0;      // vertical field of view (perspective)
  double ortho_height = 2.0;  // view height in world units (orthographic)
  int width = 512, height = 512;

  // Orthonormal basis: forward (eye -> target), right, true up. Throws InputError when
  // eye == target or up is parallel to the view direction.
  Vec3 forward() const;
  Vec3 right() const;
  Vec3 true_up() const;

  // Half the view's extent: at unit view depth (perspective: tan(fov/2), times the aspect
  // ratio for x) or in world units (orthographic). Window x from 0 to width spans
  // [-half_x, half_x]. The one definition that SampleFrame and the GL matrices use.
  struct HalfExtents {
    double x, y;
  };
  HalfExtents half_extents() const;

  // Ray through window coordinates (wx, wy); pixel centres are (i + 0.5, j + 0.5).
  Ray ray(double wx, double wy) const;
  Ray pixel_ray(int i, int j) const { return ray(i + 0.5, j + 0.5); }
  // Window coordinates of p and its view depth (distance along forward from the eye).
  // Returns false when p is not strictly in front of the eye (perspective).
  bool project(Vec3 p, double& wx, double& wy, double& view_depth) const;
  // The ordering depth of point p: |p - eye| (perspective) or (p - eye).forward (ortho).
  double depth(Vec3 p) const;

  void validate() const;  // InputError on an impossible camera
  nlohmann::json to_json() const;
  static Camera from_json(const nlohmann::json& j);
};

}  // namespace vob
