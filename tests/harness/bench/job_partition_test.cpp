// List scheduling and shards (job_partition.h): largest first to the least loaded part,
// deterministic, every group in exactly one shard.
#include <gtest/gtest.h>

#include <set>

#include "harness/bench/job_partition.h"

namespace vob {
namespace {

TEST(JobPartition, ListScheduleLargestFirstToLeastLoaded) {
  // 5 | 4; 3 -> the 4 (7); 3 -> the 5 (8); 2 -> 7 (9); 2 -> 8 (10).
  const Schedule s = list_schedule({2, 3, 5, 2, 4, 3}, 2);
  EXPECT_DOUBLE_EQ(s.total, 19);
  EXPECT_DOUBLE_EQ(s.makespan, 10);
  EXPECT_EQ(s.largest, 2);
  EXPECT_EQ(s.part[2], 0);
  EXPECT_EQ(s.part[4], 1);
  // One item that outweighs all others bounds the makespan whatever the ranks.
  EXPECT_DOUBLE_EQ(list_schedule({100, 1, 1, 1}, 512).makespan, 100);
  EXPECT_DOUBLE_EQ(list_schedule({1, 2, 3}, 1).makespan, 6);
}

TEST(JobPartition, ShardsCoverEveryGroupOnce) {
  std::vector<JobGroup> groups;
  for (int i = 0; i < 23; ++i) {
    JobGroup g;
    g.id = "s / d" + std::to_string(i % 5) + " / o" + std::to_string(i);
    g.cost = double((i * 37) % 11 + 1);  // ties included
    groups.push_back(g);
  }
  for (int n = 1; n <= 6; ++n) {
    std::multiset<std::string> seen;
    double worst = 0, total = 0;
    for (int i = 1; i <= n; ++i) {
      double load = 0;
      for (const JobGroup* g : shard_groups(groups, i, n)) {
        seen.insert(g->id);
        load += g->cost;
      }
      worst = std::max(worst, load);
      total += load;
    }
    EXPECT_EQ(seen.size(), groups.size()) << n << " shards";
    EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()).size(), groups.size()) << n << " shards";
    // LPT's bound: within 4/3 of the optimum, which is at least total / n and the largest group.
    EXPECT_LE(worst, 4.0 / 3.0 * std::max(total / n, 11.0) + 1e-9) << n << " shards";
  }
}

}  // namespace
}  // namespace vob
