// vobench generate: make a built-in dataset (or read a file) and write it out.
#include <iostream>

#include "datasets/datasets.h"
#include "harness/bench/runner.h"
#include "harness/cli/commands.h"
#include "harness/cli/scene_args.h"

namespace vob {

Command add_generate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("generate", "write a dataset to a file (.vtu .vtk .off .vti)");
  auto args = std::make_shared<SceneArgs>();
  auto out = std::make_shared<std::string>();
  args->add_to(*cmd);
  cmd->add_option("-o,--output", *out, "output file")->required();
  return [args, out]() {
    const DatasetSpec spec = args->spec();
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
