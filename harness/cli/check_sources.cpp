#include "harness/cli/check_sources.h"

#include <chrono>
#include <filesystem>

#include "harness/bench/external_orderer.h"
#include "harness/bench/suite.h"
#include "harness/scene/input_error.h"

namespace vob {

namespace {
class FixedOrderer final : public Orderer {
 public:
  explicit FixedOrderer(std::vector<int32_t> order) : order_(std::move(order)) {}
  Claims claims() const override { return {}; }
  void prepare(const Scene&, PhaseClock&) override {}
  Ordering order(const Camera&, PhaseClock&) override {
    Ordering o;
    o.order = order_;
    return o;
  }
  size_t bytes() const override { return order_.capacity() * sizeof(int32_t); }

 private:
  std::vector<int32_t> order_;
};

PreparedOrderer prepared(const std::string& label, std::unique_ptr<Orderer> orderer, const Scene& scene) {
  PreparedOrderer p;
  p.spec = label;
  p.orderer = std::move(orderer);
  p.scene = scene.fresh();
  const auto t0 = std::chrono::steady_clock::now();
  p.orderer->prepare(p.scene, p.prepare_clock);
  p.prepare_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}
}  // namespace

OrderFile read_order_file(const std::string& path) {
  const nlohmann::json j = read_json_file(path, "order file");
  OrderFile f;
  f.path = path;
  if (!j.is_object()) throw InputError(path, "order file", "must be a JSON object with an \"order\" array");
  if (!j.contains("order") || !j["order"].is_array())
    throw InputError(path, "order", "is missing or not an array of primitive ids");
  const auto& ids = j["order"];
  f.order.reserve(ids.size());
  for (size_t i = 0; i < ids.size(); ++i) {
    if (!ids[i].is_number_integer() || ids[i].get<int64_t>() < INT32_MIN || ids[i].get<int64_t>() > INT32_MAX)
      throw InputError(path, "order[" + std::to_string(i) + "]", ids[i].dump().substr(0, 30) + " is not an id");
    f.order.push_back(static_cast<int32_t>(ids[i].get<int64_t>()));
  }
  f.label = j.contains("algorithm") && j["algorithm"].is_string() ? j["algorithm"].get<std::string>()
                                                                   : std::filesystem::path(path).filename().string();
  if (j.contains("camera")) {
    try {
      f.camera = Camera::from_json(j["camera"]);
    } catch (const InputError& e) {
      throw InputError(path, "camera", e.what());
    } catch (const nlohmann::json::exception&) {
      throw InputError(path, "camera", "needs eye, target, up (3 numbers each), width, height and fov or ortho_height");
    }
  }
  if (j.contains("view_index") && j["view_index"].is_number_integer()) f.view_index = j["view_index"].get<int>();
  if (j.contains("dataset")) f.dataset = j["dataset"];
  if (j.contains("primitive_kind") && j["primitive_kind"].is_string()) f.kind = j["primitive_kind"];
  return f;
}

void scene_from_order_file(const OrderFile& f, SceneArgs& args) {
  if (!args.dataset.empty() || !args.input.empty()) return;
  const nlohmann::json& d = f.dataset;
  if (!d.is_object())
    throw InputError(f.path, "dataset", "is not in the file: give the scene with --dataset or --input");
  if (d.contains("input") && d["input"].is_string()) {
    args.input = d["input"];
    args.tetrahedralize = d.value("tetrahedralize", false);
    return;
  }
  if (!d.contains("name") || !d["name"].is_string())
    throw InputError(f.path, "dataset", "names no dataset or input: give the scene with --dataset or --input");
  args.dataset = d["name"];
  if (d.contains("set") && d["set"].is_object())
    for (const auto& [k, v] : d["set"].items()) args.sets.push_back(k + "=" + (v.is_string() ? v.get<std::string>() : v.dump()));
}

PreparedOrderer prepare_fixed_order(const OrderFile& f, const Scene& scene) {
  if (!f.kind.empty() && f.kind != scene_kind_name(scene.kind()))
    throw InputError(f.path, "primitive_kind", "is " + f.kind + ", but the scene has " + scene_kind_name(scene.kind()));
  const std::string problem = permutation_problem(scene, f.order);
  if (!problem.empty()) throw InputError(f.path, "order", problem);
  return prepared(f.label, std::make_unique<FixedOrderer>(f.order), scene);
}

PreparedOrderer prepare_command(const std::string& command, double timeout_seconds, const Scene& scene) {
  return prepared("command", make_external_orderer(command, timeout_seconds), scene);
}

}  // namespace vob
