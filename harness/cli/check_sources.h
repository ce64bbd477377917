// Where `vobench check` gets its orderings besides a registered orderer (--algorithm): a
// permutation in a file written by `vobench order` or by any program (--order ORDER.json),
// or another program speaking the sorter protocol (--command, external_orderer.h).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/bench/measure.h"
#include "harness/cli/scene_args.h"

namespace vob {

struct OrderFile {
  std::string path;
  std::string label;             // its "algorithm", else the file name
  std::vector<int32_t> order;    // checked against the scene by prepare_fixed_order
  std::optional<Camera> camera;  // its "camera" (absent: view options are needed)
  int view_index = -1;           // its "view_index"
  nlohmann::json dataset;        // its "dataset" (null when absent)
  std::string kind;              // its "primitive_kind" (empty when absent)
  int64_t primitives = -1;       // its "primitives" (-1 when absent)
};
// The fingerprint `order` writes beside an input file's path (FNV-1a 64 of its bytes, in
// hex): `check --order` refuses a file that changed since (another mesh of the same size
// would be judged as if it were the one ordered).
std::string input_fingerprint(const std::string& path);
// InputError naming the file and the key for anything malformed.
OrderFile read_order_file(const std::string& path);
// Neither --dataset nor --input given: the scene the file names in "dataset".
void scene_from_order_file(const OrderFile& f, SceneArgs& args);
// An orderer that answers the file's order at every view; InputError naming the file when
// the order is not a complete permutation of this scene's primitives.
PreparedOrderer prepare_fixed_order(const OrderFile& f, const Scene& scene);
// The sorter program, started (its scene written) once for all views.
PreparedOrderer prepare_command(const std::string& command, double timeout_seconds, const Scene& scene);

}  // namespace vob
