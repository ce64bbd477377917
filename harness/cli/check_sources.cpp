#include "harness/cli/check_sources.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

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
  for (char& c : f.label)  // printed at the start of lines: no line of its own making
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (j.contains("camera")) {
    try {
      f.camera = Camera::from_json(j["camera"]);
    } catch (const InputError& e) {
      std::string why = e.what();
      if (why.rfind("camera: ", 0) == 0) why.erase(0, 8);
      throw InputError(path, "camera", why);
    } catch (const nlohmann::json::exception&) {
      throw InputError(path, "camera", "needs eye, target, up (3 numbers each), width, height and fov or ortho_height");
    }
  }
  if (j.contains("view_index")) {
    if (!j["view_index"].is_number_integer() || j["view_index"].get<int64_t>() < -1 ||
        j["view_index"].get<int64_t>() > INT32_MAX)
      throw InputError(path, "view_index", j["view_index"].dump().substr(0, 30) + " is not a view index");
    f.view_index = j["view_index"].get<int>();
  }
  if (j.contains("primitives")) {
    if (!j["primitives"].is_number_integer() || j["primitives"].get<int64_t>() < 0)
      throw InputError(path, "primitives", j["primitives"].dump().substr(0, 30) + " is not a count");
    f.primitives = j["primitives"].get<int64_t>();
  }
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
    // Written absolute since the fingerprint came in; an older file's relative path is
    // taken from the order file's folder when it does not name a file from here.
    namespace fs = std::filesystem;
    std::string input = d["input"];
    std::error_code ec;
    if (fs::path(input).is_relative() && !fs::exists(input, ec)) {
      const fs::path beside = fs::path(f.path).parent_path() / input;
      if (fs::exists(beside, ec)) input = beside.string();
    }
    if (d.contains("input_fingerprint") && d["input_fingerprint"].is_string() && fs::exists(input, ec)) {
      const std::string now = input_fingerprint(input);
      if (now != d["input_fingerprint"].get<std::string>())
        throw InputError(f.path, "dataset.input", input + " has changed since the order was written (fingerprint " +
                                                      d["input_fingerprint"].get<std::string>() + ", now " + now + ")");
    }
    args.input = input;
    args.tetrahedralize = d.value("tetrahedralize", false);
    return;
  }
  if (!d.contains("name") || !d["name"].is_string())
    throw InputError(f.path, "dataset", "names no dataset or input: give the scene with --dataset or --input");
  args.dataset = d["name"];
  if (d.contains("set") && d["set"].is_object())
    for (const auto& [k, v] : d["set"].items()) args.sets.push_back(k + "=" + (v.is_string() ? v.get<std::string>() : v.dump()));
}

std::string input_fingerprint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", "cannot be read");
  uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a 64
  std::vector<char> buf(1 << 20);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    for (std::streamsize i = 0, n = in.gcount(); i < n; ++i) h = (h ^ static_cast<unsigned char>(buf[i])) * 0x100000001b3ull;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

PreparedOrderer prepare_fixed_order(const OrderFile& f, const Scene& scene) {
  if (f.primitives >= 0 && static_cast<size_t>(f.primitives) != scene.num_primitives())
    throw InputError(f.path, "primitives", "is " + std::to_string(f.primitives) + ", but the scene has " +
                                               std::to_string(scene.num_primitives()) + ": the order is of another scene");
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
