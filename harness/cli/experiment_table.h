// Tables of a reproduction: our measured rows beside the paper's numbers, written as
// NAME.md (Markdown) and NAME.json (the same rows, machine-readable) in the experiment's
// output folder, atomically.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/cli/experiments.h"

namespace vob {

struct ExperimentTable {
  std::string title;                 // "Table 3: phase breakdown (s)"
  std::vector<std::string> columns;  // header cells
  std::vector<std::vector<nlohmann::json>> rows;  // numbers, strings or null (shown as -)
  std::string notes;                 // Markdown under the table (paper machine, caveats)
};

struct ExperimentDoc {
  std::string name;    // NAME of NAME.md / NAME.json
  std::string title;   // first heading
  std::string intro;   // Markdown: what was run, the command, the machine
  std::vector<ExperimentTable> tables;
  std::vector<std::string> figures;  // paths relative to the output folder
  std::vector<std::string> claims;   // "holds: ...", "does not hold: ..." lines
};

// Writes ctx.out_dir/NAME.md and NAME.json; returns the Markdown path.
std::string write_experiment_doc(const ExperimentContext& ctx, const ExperimentDoc& doc);
// A number as it appears in a table: 3 significant digits, integers as integers.
std::string format_cell(const nlohmann::json& v);

}  // namespace vob
