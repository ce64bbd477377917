// Reproduction files (docs/pipeline.md "Reproduction file"): what `vobench reproduce NAME`
// runs. A JSON file anywhere under datasets/suites/ with a "reproduction" key:
//   {"reproduction": "xmpvo-scaling", "paper": "xmpvo" | null, "summary": "...",
//    "title": "...", "suites": [SUITE | "file.json" (a suite file under datasets/suites/)]}
#pragma once
#include <string>
#include <vector>

#include "harness/bench/suite.h"

namespace vob {

struct ReproductionEntry {
  std::string name, summary, title, path;  // title: "vobench NAME report" unless given
};

struct Reproduction {
  std::string name, paper, summary, title, path;  // paper empty: null (the generic report)
  std::string scale = "default";
  std::vector<SuiteSpec> suites;  // every suite validated, the scale's overlays applied
};

// Every reproduction file under `suites_dir`, by name. InputError for a JSON file there that
// does not parse, or two files with one reproduction name.
std::vector<ReproductionEntry> list_reproductions(const std::string& suites_dir);
// The file of reproduction `name`, or "" when no file has that name.
std::string find_reproduction(const std::string& suites_dir, const std::string& name);
// Reads and validates a reproduction file and all its suites at `scale` ("tiny", "default",
// "full"); suite references are relative to `suites_dir`. InputError naming file and entry.
Reproduction load_reproduction(const std::string& path, const std::string& scale,
                               const std::string& suites_dir);

}  // namespace vob
