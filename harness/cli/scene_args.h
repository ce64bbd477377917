// Command-line options that choose a scene (--dataset/--set or --input) and views
// (--views/--view-index, an orbit, or an explicit camera), shared by the subcommands.
// Both are checked before any scene is made: values in range, and no option that the chosen
// kind of view would ignore.
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
  std::string variable;  // --input-variable (Exodus)
  // --validate cells (default): per-cell checks and face sharing, as every load does;
  // --validate full: also every pair of interpenetrating cells (cell_overlap.h).
  std::string validate = "cells";
  void add_to(CLI::App& cmd, bool validate_option = true);
  // InputError unless exactly one of --dataset / --input, and for --dataset unless the name
  // and every --set parameter are known and in range (checked without generating).
  DatasetSpec spec() const;
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
  // Checks the view options alone and together for this scene spec; InputError naming the
  // option and why. Call before making the scene.
  void validate(const DatasetSpec& spec) const;
  bool explicit_camera() const { return !eye.empty() || !target.empty(); }
  // (view index, camera) pairs for the scene; the view index is -1 for an explicit camera.
  std::vector<std::pair<int, Camera>> cameras(const DatasetSpec& spec, const Scene& scene) const;
  nlohmann::json describe() const;

 private:
  bool given(const std::string& option) const;
  CLI::App* cmd_ = nullptr;
};

// Checks an orderer spec before any scene is made: name and parameters known and in range
// (the orderer is constructed, not prepared), and for a built-in dataset that it orders that
// kind of scene. InputError otherwise.
void check_algorithm(const std::string& algorithm, const DatasetSpec& spec);

// Validators that check the text of an option before CLI11 converts it: plain decimal
// integers in [lo, hi] (no sign tricks, hex, octal or overflow), finite numbers in a range.
CLI::Validator integer_in(int64_t lo, int64_t hi);
CLI::Validator number_in(double lo, double hi, bool lo_open, bool hi_open);

}  // namespace vob
