// vobench generate: make a built-in dataset (or read a file) and write it out.
#include <filesystem>
#include <iostream>
#include <set>

#include "datasets/datasets.h"
#include "harness/bench/runner.h"
#include "harness/cli/commands.h"
#include "harness/cli/scene_args.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
// Refuses an output file that write_scene could not write, before generating: the
// extensions mirror write_scene's (datasets/io/scene_files.cpp).
void check_output_extension(const DatasetSpec& spec, const std::string& out) {
  const std::string ext = std::filesystem::path(out).extension().string();
  std::set<std::string> fits = {".vtu", ".vtk", ".node", ".off", ".vti"};
  if (spec.input.empty()) {
    switch (find_dataset(spec.name).kind) {
      case SceneKind::Cells: fits = {".vtu", ".vtk", ".node"}; break;
      case SceneKind::Triangles: fits = {".off"}; break;
      case SceneKind::Voxels: fits = {".vti"}; break;
    }
  }
  if (!fits.count(ext)) {
    std::string all;
    for (const auto& f : fits) all += (all.empty() ? "" : " ") + f;
    throw InputError("--output", "'" + out + "'", "this scene is written as one of " + all);
  }
}
}  // namespace

Command add_generate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("generate", "write a dataset to a file (.vtu .vtk .off .vti)");
  auto args = std::make_shared<SceneArgs>();
  auto out = std::make_shared<std::string>();
  args->add_to(*cmd);
  cmd->add_option("-o,--output", *out, "output file")->required();
  return [args, out]() {
    const DatasetSpec spec = args->spec();
    check_output_extension(spec, *out);
    const Scene scene = args->load(spec);
    write_scene(scene, *out);
    nlohmann::json facts = scene_facts(scene);
    facts["dataset"] = spec.label();
    facts["file"] = *out;
    std::cout << facts.dump() << "\n";
    return 0;
  };
}

}  // namespace vob
