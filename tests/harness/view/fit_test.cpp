// fit_window_to_box: the window takes the box's projected aspect at about the pixel budget,
// and the box's projection fills it (inside, touching on one side).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "harness/bench/jobs.h"
#include "harness/scene/input_error.h"
#include "harness/view/fit.h"
#include "harness/view/view_set.h"
#include "tests/support/test_util.h"

using namespace vob;

TEST(FitWindow, TheBoxFillsTheWindowAtAboutThePixelBudget) {
  Aabb box;
  box.add({-3, -3, -1});
  box.add({3, 3, 10});
  for (bool ortho : {false, true})
    for (int i = 0; i < 14; ++i) {
      ViewOptions vo;
      vo.ortho = ortho;
      const Camera c = fit_window_to_box(fibonacci_view(box, 14, i, vo), box, 168750);
      EXPECT_NEAR(double(c.width) * c.height, 168750, 0.01 * 168750) << i;
      double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
      for (int k = 0; k < 8; ++k) {
        const Vec3 p{k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y, k & 4 ? box.hi.z : box.lo.z};
        double wx, wy, d;
        ASSERT_TRUE(c.project(p, wx, wy, d));
        lo_x = std::min(lo_x, wx), hi_x = std::max(hi_x, wx), lo_y = std::min(lo_y, wy), hi_y = std::max(hi_y, wy);
      }
      EXPECT_GE(lo_x, -1e-6);
      EXPECT_GE(lo_y, -1e-6);
      EXPECT_LE(hi_x, c.width + 1e-6);
      EXPECT_LE(hi_y, c.height + 1e-6);
      // Touching on the tighter side: the symmetric frustum's margin there is below a pixel.
      const double gap_x = std::min(lo_x, c.width - hi_x), gap_y = std::min(lo_y, c.height - hi_y);
      EXPECT_LT(std::min(gap_x, gap_y), 1.0) << i;
      // The window's aspect is the projection's (up to rounding and perspective asymmetry).
      const double half_x = std::max(std::fabs(lo_x - 0.5 * c.width), std::fabs(hi_x - 0.5 * c.width));
      const double half_y = std::max(std::fabs(lo_y - 0.5 * c.height), std::fabs(hi_y - 0.5 * c.height));
      EXPECT_NEAR(half_x / half_y, double(c.width) / c.height, 0.02 * c.width / c.height) << i;
    }
}

TEST(FitWindow, ImpossibleFitsAreRefused) {
  Aabb box;
  box.add({-1, -1, -1});
  box.add({1, 1, 1});
  Camera c;
  c.eye = {0, 0, 0.5};  // inside the box: corners behind the eye
  EXPECT_THROW(fit_window_to_box(c, box, 1000), InputError);
  EXPECT_THROW(fit_window_to_box(fibonacci_view(box, 1, 0), box, 0), InputError);
}

TEST(FitWindow, ASuiteWithFitGivesFittedJobsUnderItsOwnKeys) {
  const auto j = nlohmann::json::parse(R"({"name": "f", "datasets": [{"name": "helix", "set": {"cells": 2000}}],
      "algorithms": ["centroid"], "views": 14, "spread_views": 3, "fit": true, "sizes": ["450x375"]})");
  const SuiteSpec s = SuiteSpec::from_json(j, "fit.json");
  ASSERT_TRUE(s.fit);
  const auto plans = plan_datasets(s);
  const Scene scene = vob::test::make("helix", {{"cells", "2000"}});
  const auto jobs = dataset_jobs(s, plans.at(0), scene, RunTags{});
  ASSERT_EQ(jobs.size(), 3u);
  for (const Job& job : jobs) {
    // The size entry stays in the key (docs/pipeline.md "Jobs and keys"), and |fit ends it.
    EXPECT_NE(job.key.find("|450x375|"), std::string::npos) << job.key;
    EXPECT_EQ(job.key.substr(job.key.size() - 4), "|fit") << job.key;
    EXPECT_EQ(job.w, job.camera.width);
    EXPECT_EQ(job.h, job.camera.height);
    EXPECT_NEAR(double(job.w) * job.h, 450.0 * 375, 0.01 * 450 * 375);
  }
}
