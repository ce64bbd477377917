#include "datasets/datasets.h"

#include "harness/scene/input_error.h"

namespace vob {

const std::vector<DatasetInfo>& dataset_registry() {
  static const std::vector<DatasetInfo> registry = {};
  return registry;
}

Scene make_dataset(const std::string& name, Params params) {
  params.set_owner(name);
  for (const auto& info : dataset_registry())
    if (info.name == name) {
      Scene s = info.make(params);
      params.check_all_used();
      return s;
    }
  throw InputError("--dataset", name, "unknown dataset (see: vobench list)");
}

}  // namespace vob
