// The hard cases the issue asked for are registered as such. Every orderer runs on every
// hard case of its kind in tests/algorithms/conformance_test.cpp.
#include <gtest/gtest.h>

#include "datasets/datasets.h"

using namespace vob;

TEST(HardCases, TheRegistryHasTheIssuesHardCases) {
  for (const char* name : {"offset", "slivers", "edge-on", "eye-in-plane", "eye-inside", "cycle", "tiny"}) {
    bool found = false;
    for (const auto& d : dataset_registry()) found |= (d.name == name && d.hard_case);
    EXPECT_TRUE(found) << name;
  }
}
