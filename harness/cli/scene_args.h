// Command-line options that choose a scene (--dataset/--set or --input) and views
// (--views/--view-index, an orbit, or an explicit camera), shared by the subcommands.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "harness/bench/suite.h"
#include "harness/view/camera.h"

namespace vob {

struct SceneArgs {
  std::string dataset, input;
  std::vector<std::string> sets;  // k=v
  bool tetrahedralize = false;
  // --validate cells (default): per-cell checks and face sharing, as every load does;
  // --validate full: also every pair of interpenetrating cells (cell_overlap.h).
  std::string validate = "cells";
  void add_to(CLI::App& cmd, bool validate_option = true);
  DatasetSpec spec() const;  // InputError unless exactly one of --dataset / --input
  // make_scene(spec) plus what --validate asks; InputError naming the first overlapping
  // pair under --validate full.
  Scene load(const DatasetSpec& spec) const;
};

// How error lines name a scene: the input path as given, else the dataset label.
std::string source_name(const DatasetSpec& spec);

struct ViewArgs {
  int views = 14;
  int view_index = -1;
  int orbit = 0;  // frames of an orbit path instead of the Fibonacci set
  std::string eye, target, up = "0,0,1";
  double fov = 40.0, ortho = 0.0, zoom = 1.0;
  bool ortho_views = false;
  std::string size = "512x512";
  void add_to(CLI::App& cmd);
  // (view index, camera) pairs for the scene; the view index is -1 for an explicit camera.
  std::vector<std::pair<int, Camera>> cameras(const DatasetSpec& spec, const Scene& scene) const;
  nlohmann::json describe() const;
};

}  // namespace vob
