#include <gtest/gtest.h>

#include <filesystem>

#include "harness/bench/params.h"
#include "harness/bench/suite.h"
#include "harness/scene/input_error.h"

using namespace vob;

TEST(Params, SpecParsingAndValidation) {
  auto [name, p] = Params::parse_spec("havs:k=6,mode=fast");
  EXPECT_EQ(name, "havs");
  EXPECT_EQ(p.get_int("k", 2, 1, 8), 6);
  EXPECT_THROW(p.check_all_used(), InputError);  // mode never read
  EXPECT_EQ(p.get_choice("mode", "slow", {"slow", "fast"}), "fast");
  EXPECT_NO_THROW(p.check_all_used());
  auto [n2, q] = Params::parse_spec("x:k=12");
  EXPECT_THROW(q.get_int("k", 2, 1, 8), InputError);
  auto [n3, r] = Params::parse_spec("x:k=abc");
  EXPECT_THROW(r.get_int("k", 2, 1, 8), InputError);
  EXPECT_THROW(Params::parse_spec("x:novalue"), InputError);
}

TEST(Suite, ParsesAndRejects) {
  const auto j = nlohmann::json::parse(R"({"name": "s", "datasets": [{"name": "gap", "set": {"nx": 3}}],
      "algorithms": ["mpvo"], "sizes": ["640x480"], "views": 5})");
  const SuiteSpec s = SuiteSpec::from_json(j, "s.json");
  EXPECT_EQ(s.sizes[0], std::make_pair(640, 480));
  EXPECT_EQ(s.datasets[0].label(), "gap(nx=3)");
  auto bad = j;
  bad["colour"] = 1;
  EXPECT_THROW(SuiteSpec::from_json(bad, "s.json"), InputError);
  EXPECT_THROW(parse_size("640x"), InputError);
  EXPECT_THROW(parse_size("0x10"), InputError);
}
