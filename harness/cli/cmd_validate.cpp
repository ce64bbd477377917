// vobench validate: load a scene with every check, including the search for interpenetrating
// cells (harness/scene/cell_overlap.h) that loads skip unless --validate full.
// By default the boundary check certifies a clean mesh; when it finds an overlap (or cannot
// decide) the exhaustive search lists every pair. --exhaustive runs only the latter.
// Cells with a warped quad are also judged as the oracle models them (cell_overlap.h,
// "Warped quads"): pairs that overlap only so are listed with their thickness.
// Exit 0: clean; 2: bad input, including any interpenetrating pair (one stderr line naming
// the first; stdout lists the first 20, --json all of them).
#include <cstdio>
#include <iostream>

#include "harness/cli/commands.h"
#include "harness/cli/scene_args.h"
#include "harness/scene/cell_overlap.h"
#include "harness/scene/input_error.h"

namespace vob {

Command add_validate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("validate", "check a mesh fully, interpenetrating cells included (exit 2 if any)");
  auto scene_args = std::make_shared<SceneArgs>();
  auto file = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto exhaustive = std::make_shared<bool>(false);
  cmd->add_option("file", *file, "mesh or volume file (same as --input)");
  scene_args->add_to(*cmd, false);
  cmd->add_flag("--json", *json, "print the result, every pair included, as JSON");
  cmd->add_flag("--exhaustive", *exhaustive,
                "decide every overlapping box pair (the reference search) instead of certifying "
                "from the boundary first");
  return [=]() {
    SceneArgs args = *scene_args;
    if (!file->empty()) {
      if (!args.input.empty()) throw InputError("validate", *file, "give the file or --input, not both");
      args.input = *file;
    }
    if (args.input.empty() && args.dataset.empty())
      throw InputError("validate: give FILE, --input FILE or --dataset NAME");
    const DatasetSpec spec = args.spec();
    const Scene scene = make_scene(spec);  // per-cell validation and face sharing
    const std::string source = source_name(spec);
    nlohmann::json out{{"dataset", spec.to_json()},
                       {"primitive_kind", scene_kind_name(scene.kind())},
                       {"primitives", scene.num_primitives()}};
    if (scene.kind() != SceneKind::Cells) {
      out["overlapping_pairs"] = 0;
      if (*json)
        std::cout << out.dump(2) << "\n";
      else
        std::printf("%s: %zu %s valid (the overlap search applies to cell meshes only)\n",
                    source.c_str(), scene.num_primitives(), scene_kind_name(scene.kind()));
      return 0;
    }
    const CellOverlapReport r = check_overlapping_cells(
        scene.mesh(), scene.faces(), *exhaustive ? OverlapSearch::Exhaustive : OverlapSearch::Fast);
    const OverlapCertificate& cert = r.certificate;
    out["method"] = r.method;
    if (cert.result != OverlapCertificate::NotRun) {
      const char* verdict[] = {"not run", "clean", "overlap", "undecided"};
      out["certificate"] = {{"result", verdict[cert.result]},
                            {"why", cert.why},
                            {"boundary_triangles", cert.boundary_triangles},
                            {"triangle_cell_pairs", cert.triangle_cell_pairs},
                            {"contact_pairs", cert.contact_pairs},
                            {"components", cert.components},
                            {"nesting_pairs", cert.nesting_pairs},
                            {"seconds", cert.seconds},
                            {"cpu_seconds", cert.cpu_seconds}};
    }
    out["overlapping_pairs"] = r.pairs.size();
    out["pairs"] = r.pairs;
    if (r.warped_cells > 0) {
      // Cells with a warped quad, decided as the oracle models them too (cell_overlap.h).
      nlohmann::json mp = nlohmann::json::array();
      for (const auto& m : r.model_pairs) mp.push_back({{"cells", m.cells}, {"thickness", m.thickness}});
      out["oracle_model"] = {{"warped_cells", r.warped_cells},
                             {"tolerance", r.model_tolerance},
                             {"pairs_tested", r.model_tests},
                             {"exact_lps", r.model_lps},
                             {"overlapping_pairs", mp}};
    }
    out["seconds"] = {{"total", r.total_seconds}};
    if (r.method == "exhaustive") {
      out["candidates"] = r.candidates;
      out["seconds"]["boxes"] = r.box_seconds;
    }
    if (*json) {
      std::cout << out.dump(2) << "\n";
    } else {
      if (r.method == "boundary") {
        const auto counted = [](long long n, const char* noun) {  // "1 component", "2 components"
          return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
        };
        std::printf("%s: %s, 0 interpenetrating pairs (certified by the boundary check: %s, %s, %s; "
                    "%.2f s, %.2f s CPU)\n",
                    source.c_str(), counted((long long)scene.num_primitives(), "cell").c_str(),
                    counted(cert.boundary_triangles, "boundary triangle").c_str(),
                    counted(cert.contact_pairs, "exact pair test").c_str(), counted(cert.components, "component").c_str(),
                    cert.seconds, cert.cpu_seconds);
      } else {
        if (cert.result == OverlapCertificate::Overlap)
          std::printf("%s: the boundary check found cells %d and %d interpenetrating (%.2f s); "
                      "the exhaustive search lists every pair\n",
                      source.c_str(), cert.witness.first, cert.witness.second, cert.seconds);
        else if (cert.result == OverlapCertificate::Undecided)
          std::printf("%s: the boundary check does not apply (%s); exhaustive search\n",
                      source.c_str(), cert.why.c_str());
        std::printf("%s: %zu cells, %lld candidate box pairs, %zu interpenetrating pairs, all "
                    "listed (exhaustive search, %.2f s)\n",
                    source.c_str(), scene.num_primitives(), (long long)r.candidates,
                    r.pairs.size(), r.total_seconds);
        if (r.warped_cells > 0)
          std::printf("%s: %lld cells with a non-planar quad; %lld pairs with one also tested as the "
                      "oracle models them (%lld by exact LP), %zu overlapping by more than its "
                      "threshold %.2g\n",
                      source.c_str(), (long long)r.warped_cells, (long long)r.model_tests,
                      (long long)r.model_lps, r.model_pairs.size(), r.model_tolerance);
      }
      const size_t shown = std::min<size_t>(r.pairs.size(), 20);
      for (size_t i = 0; i < shown; ++i) {
        const double thick = model_pair_thickness(r, r.pairs[i]);
        if (thick >= 0)
          std::printf("  cells %d and %d (only as the oracle models them: %.2g thick)\n", r.pairs[i].first,
                      r.pairs[i].second, thick);
        else
          std::printf("  cells %d and %d\n", r.pairs[i].first, r.pairs[i].second);
      }
      if (r.pairs.size() > shown)
        std::printf("  ... %zu more (--json lists all)\n", r.pairs.size() - shown);
    }
    if (r.pairs.empty()) return 0;
    std::fflush(stdout);
    std::fprintf(stderr, "vobench: %s\n", describe_overlap(source, r, &scene.mesh()).c_str());
    return 2;
  };
}

}  // namespace vob
