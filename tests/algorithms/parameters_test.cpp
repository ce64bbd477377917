// Every declared parameter of every registered orderer (its ParamSpec, registry.h): the
// default parses, every choice and both range ends parse and still give a complete order,
// a value past a range end or outside the choices, and an unknown key, are refused with
// InputError. No orderer is named: the loop reads the registry.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdio>

#include "datasets/datasets.h"
#include "harness/bench/registry.h"
#include "harness/bench/runner.h"
#include "harness/scene/input_error.h"
#include "tests/support/test_util.h"

using namespace vob;

namespace {

std::string text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string value_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  return text(v.get<double>());
}

// Values the spec accepts: its default, every choice, both range ends.
std::vector<std::string> accepted(const ParamSpec& p) {
  std::vector<std::string> v = {value_text(p.def)};
  switch (p.kind) {
    case ParamSpec::Kind::Int: v.push_back(std::to_string((long long)p.lo)); v.push_back(std::to_string((long long)p.hi)); break;
    case ParamSpec::Kind::Double: v.push_back(text(p.lo)); v.push_back(text(p.hi)); break;
    case ParamSpec::Kind::Choice:
    case ParamSpec::Kind::Bool: v.insert(v.end(), p.choices.begin(), p.choices.end()); break;
  }
  return v;
}

// The resolved value of `v` in the record: numbers as numbers, booleans as booleans.
nlohmann::json expected(const ParamSpec& p, const std::string& v) {
  switch (p.kind) {
    case ParamSpec::Kind::Int: return std::stoll(v);
    case ParamSpec::Kind::Double: return std::stod(v);
    case ParamSpec::Kind::Bool: return v == "true" || v == "1";
    case ParamSpec::Kind::Choice: break;
  }
  return v;
}

// Values it must refuse: just past each range end, a non-number, a value not among the choices.
std::vector<std::string> refused(const ParamSpec& p) {
  switch (p.kind) {
    case ParamSpec::Kind::Int:
      return {std::to_string((long long)p.lo - 1), std::to_string((long long)p.hi + 1), "1.5", "x"};
    case ParamSpec::Kind::Double:
      return {text(p.lo - std::max(1.0, std::fabs(p.lo))), text(p.hi + std::max(1.0, std::fabs(p.hi))),
              "x", "nan"};
    case ParamSpec::Kind::Choice:
    case ParamSpec::Kind::Bool: return {"%bogus%", ""};
  }
  return {};
}

// A small scene of the orderer's kind.
DatasetSpec small_scene(SceneKind kind) {
  DatasetSpec s;
  switch (kind) {
    case SceneKind::Cells: s.name = "gap"; s.set = {{"nx", "3"}, {"ny", "3"}, {"nz", "4"}, {"gaps", "1"}}; break;
    case SceneKind::Triangles: s.name = "sphere"; s.set = {{"subdiv", "1"}}; break;
    case SceneKind::Voxels: s.name = "shells"; s.set = {{"nx", "8"}, {"ny", "8"}, {"nz", "8"}}; break;
  }
  return s;
}

class OrdererParams : public ::testing::TestWithParam<std::string> {};

std::vector<std::string> orderer_names() {
  std::vector<std::string> v;
  for (const auto& info : orderer_registry()) v.push_back(info.name);
  return v;
}

}  // namespace

TEST_P(OrdererParams, DeclaredValuesWorkAndOthersAreRefused) {
  const OrdererInfo& info = find_orderer(GetParam());
  const DatasetSpec ds = small_scene(info.kind);
  const Scene scene = make_scene(ds);
  const Camera cam = dataset_views(ds, scene, 4, {1}, 24, 24, false, 1.0).at(0).second;

  // Defaults: every declared parameter is in the resolved set, at its default.
  const nlohmann::json defaults = resolved_parameters(info.name);
  EXPECT_EQ(defaults.size(), info.params.size()) << info.name;
  for (const ParamSpec& p : info.params) {
    ASSERT_TRUE(defaults.contains(p.name)) << info.name << " " << p.name;
    EXPECT_EQ(defaults.at(p.name), p.def) << info.name << " " << p.name;
  }

  for (const ParamSpec& p : info.params) {
    for (const std::string& v : accepted(p)) {
      const std::string spec = info.name + ":" + p.name + "=" + v;
      SCOPED_TRACE(spec);
      ASSERT_NO_THROW(make_orderer(spec));
      std::unique_ptr<PreparedOrderer> po;
      try {
        po = std::make_unique<PreparedOrderer>(prepare_orderer(spec, scene));
      } catch (const InputError& e) {
        // Only an OpenGL backend may be unavailable; that configuration is then untestable here.
        if (resolved_parameters(spec).value("backend", "") == "gl") continue;
        ADD_FAILURE() << e.what();
        continue;
      }
      const FrameMeasurement m = measure_frame(*po, cam, 0, 1);
      EXPECT_NO_THROW(check_complete(scene, m.ordering, spec));
      // The record names the value given, in the declared kind.
      const nlohmann::json r = resolved_parameters(spec);
      EXPECT_EQ(r.at(p.name), expected(p, v));
    }
    for (const std::string& v : refused(p))
      EXPECT_THROW(make_orderer(info.name + ":" + p.name + "=" + v), InputError)
          << info.name << ":" << p.name << "=" << v;
  }
  EXPECT_THROW(make_orderer(info.name + ":no_such_parameter=1"), InputError);
  EXPECT_THROW(make_orderer(info.name + ":novalue"), InputError);
}

INSTANTIATE_TEST_SUITE_P(EveryOrderer, OrdererParams, ::testing::ValuesIn(orderer_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string s = i.param;
                           for (char& ch : s)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return s;
                         });

TEST(OrdererParamErrors, TheLineNamesOrdererKeyAndReason) {
  // (spec, what its error line must name: the orderer, the key and the reason)
  const std::pair<const char*, std::vector<std::string>> cases[] = {
      {"vtk-centroid:chunk=0", {"vtk-centroid", "chunk", "not in [1, 2147483647]"}},
      {"centroid:depth=1", {"centroid", "depth", "not a known parameter"}},
  };
  for (const auto& [spec, parts] : cases) {
    const std::string m = test::input_error([&] { make_orderer(spec); });
    for (const std::string& part : parts) EXPECT_TRUE(test::contains(m, part)) << spec << ": " << m;
  }
  EXPECT_THROW(make_orderer("no-such-orderer"), InputError);
}

TEST(ResolvedParameters, EveryDeclaredParameterWithItsValueNumbersAsNumbers) {
  const nlohmann::json j = resolved_parameters("bsp-xmpvo:sample=100");
  EXPECT_EQ(j, (nlohmann::json{{"candidates", 5}, {"sample", 100}, {"split_weight", 8}, {"stop", true}}));
  EXPECT_TRUE(j.at("sample").is_number_integer());
  EXPECT_EQ(resolved_parameters("mpvo:renumber=false"), (nlohmann::json{{"curve", "hilbert"}, {"keep_coherent", true}, {"renumber", false}}));
  EXPECT_TRUE(resolved_parameters("mpvo").at("renumber").is_boolean());
}

TEST(ResolvedParameters, ReadingAnUndeclaredKeyOrTheWrongKindIsAProgrammingError) {
  Params given("t");
  given.set("n", "3");
  const ResolvedParams r = resolve_params({ParamSpec::integer("n", 1, 0, 9, "n"),
                                           ParamSpec::boolean("b", false, "b")}, given);
  EXPECT_EQ(r.get_int("n"), 3);
  EXPECT_FALSE(r.get_bool("b"));
  EXPECT_THROW(r.get_int("m"), std::logic_error);
  EXPECT_THROW(r.get_double("n"), std::logic_error);
}
