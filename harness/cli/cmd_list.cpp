// vobench list: orderers, probes, datasets and reproductions.
#include <iostream>

#include "datasets/datasets.h"
#include "harness/bench/probe.h"
#include "harness/bench/registry.h"
#include "harness/bench/reproduction.h"
#include "harness/bench/resources.h"
#include "harness/cli/commands.h"
#include "harness/cli/plugin_loader.h"

namespace vob {

Command add_list_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("list", "list orderers, probes, datasets and reproductions");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "machine-readable output");
  return [json]() {
    const auto reproductions = list_reproductions(resource_path("datasets/suites"));
    if (*json) {
      nlohmann::json j{{"orderers", nlohmann::json::array()},
                       {"probes", nlohmann::json::array()},
                       {"datasets", nlohmann::json::array()},
                       {"reproductions", nlohmann::json::array()}};
      for (const auto& o : orderer_registry()) {
        // Claims of the default configuration (some depend on a parameter, e.g. backend).
        const Claims c = make_orderer(o.name)->claims();
        nlohmann::json params = nlohmann::json::array();
        for (const ParamSpec& s : o.params) params.push_back(s.to_json());
        j["orderers"].push_back({{"name", o.name}, {"kind", scene_kind_name(o.kind)},
                                 {"summary", o.summary},
                                 {"claims", {{"object_exact", c.object_exact},
                                             {"image_exact", c.image_exact},
                                             {"image_exact_under", raster_rule_name(c.image_exact_under)},
                                             {"detects_cycles", c.detects_cycles},
                                             {"composites", c.composites}}},
                                 {"params", params}});
        if (const std::string from = plugin_of(o.name); !from.empty()) j["orderers"].back()["plugin"] = from;
      }
      for (const auto& p : probe_registry())
        j["probes"].push_back({{"name", p.name}, {"summary", p.summary}, {"needs_scene", p.needs_scene}});
      for (const auto& d : dataset_registry())
        j["datasets"].push_back({{"name", d.name}, {"kind", scene_kind_name(d.kind)},
                                 {"summary", d.summary}, {"parameters", d.parameters},
                                 {"hard_case", d.hard_case}});
      for (const auto& r : reproductions)
        j["reproductions"].push_back({{"name", r.name}, {"summary", r.summary}, {"file", r.path}});
      std::cout << j.dump(2) << "\n";
      return 0;
    }
    std::cout << "Orderers (--algorithm NAME[:k=v,...]):\n";
    for (const auto& o : orderer_registry()) {
      const std::string from = plugin_of(o.name);
      std::cout << "  " << o.name << " [" << scene_kind_name(o.kind)
                << (from.empty() ? "" : ", plugin " + from) << "]  " << o.summary << "\n";
      for (const ParamSpec& s : o.params) std::cout << "      " << s.describe() << "\n";
    }
    std::cout << "\nProbes (suite \"probes\" entries):\n";
    for (const auto& p : probe_registry())
      std::cout << "  " << p.name << (p.needs_scene ? " [datasets]" : "") << "  " << p.summary << "\n";
    std::cout << "\nDatasets (--dataset NAME --set k=v ...):\n";
    for (const auto& d : dataset_registry()) {
      std::cout << "  " << d.name << " [" << scene_kind_name(d.kind) << (d.hard_case ? ", hard case" : "")
                << "]  " << d.summary << "\n";
      if (!d.parameters.empty()) std::cout << "      " << d.parameters << "\n";
    }
    std::cout << "\nReproductions (vobench reproduce NAME [--tiny|--full]):\n";
    for (const auto& r : reproductions) std::cout << "  " << r.name << "  " << r.summary << "\n";
    return 0;
  };
}

}  // namespace vob
