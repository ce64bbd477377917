// XMPVO's per-view sign decisions in the chosen arithmetic (predicates=exact|double|
// compare); compare mode evaluates both and counts where they differ.
#pragma once
#include <cstdint>

#include "algorithms/xmpvo/face_pairs.h"

namespace vob::xmpvo {

enum class Mode { Exact, Double, Compare };

struct Signs {
  Mode mode = Mode::Exact;
  ViewGeometry g;
  int64_t facing = 0, side = 0, crossing = 0;                    // decisions
  int64_t dis_facing = 0, dis_side = 0, dis_crossing = 0;         // disagreements

  int eye_side(Vec3 a, Vec3 b, Vec3 c) {
    ++facing;
    if (mode == Mode::Double) return eye_side_double(g, a, b, c);
    const int e = xmpvo::eye_side(g, a, b, c);
    if (mode == Mode::Compare) dis_facing += e != eye_side_double(g, a, b, c);
    return e;
  }
  int edge_side(Vec3 a, Vec3 b, Vec3 p) {
    ++side;
    if (mode == Mode::Double) return edge_side_double(g, a, b, p);
    const int e = xmpvo::edge_side(g, a, b, p);
    if (mode == Mode::Compare) dis_side += e != edge_side_double(g, a, b, p);
    return e;
  }
  int crossing_side(Vec3 a, Vec3 b, Vec3 c, Vec3 d, Vec3 p, Vec3 q) {
    ++side;
    if (mode == Mode::Double) return crossing_side_double(g, a, b, c, d, p, q);
    const int e = xmpvo::crossing_side(g, a, b, c, d, p, q);
    if (mode == Mode::Compare) dis_side += e != crossing_side_double(g, a, b, c, d, p, q);
    return e;
  }
  // Proper crossing of projected segments (a, b) and (c, d).
  bool crosses(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    ++crossing;
    auto test = [&](auto side) {
      return side(c, d, a) * side(c, d, b) < 0 && side(a, b, c) * side(a, b, d) < 0;
    };
    auto exact = [&](Vec3 x, Vec3 y, Vec3 z) { return xmpvo::edge_side(g, x, y, z); };
    auto plain = [&](Vec3 x, Vec3 y, Vec3 z) { return edge_side_double(g, x, y, z); };
    if (mode == Mode::Double) return test(plain);
    const bool e = test(exact);
    if (mode == Mode::Compare) dis_crossing += e != test(plain);
    return e;
  }
};

}  // namespace vob::xmpvo
