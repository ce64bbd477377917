// The vobench program's operator new (harness/cli/huge_page_new.cpp), linked into this test
// as into the program: large blocks on advised 2 MiB-aligned mappings of their own, kept for
// reuse when freed, and the advice never on a block below the threshold.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "harness/cli/huge_page_new.h"

namespace {

// The VmFlags of the mapping that holds address p ("" when none does).
std::string vm_flags(const void* p) {
  const uintptr_t a = reinterpret_cast<uintptr_t>(p);
  std::ifstream in("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(':') > line.find(' ')) {
      inside = lo <= a && a < hi;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}
bool advised_huge(const void* p) { return vm_flags(p).find(" hg") != std::string::npos; }

// Skips where the program would not use huge pages (AddressSanitizer's build replaces
// operator new itself; the kernel's mode may be never).
#define SKIP_UNLESS_HUGE_PAGES()                                              \
  do {                                                                        \
    const vob::HugePagePolicy policy = vob::huge_page_policy();               \
    if (!policy.on) GTEST_SKIP() << "huge pages off here: " << policy.why;    \
  } while (0)

TEST(HugePageNew, LargeBlocksAreAlignedAndAdvised) {
  SKIP_UNLESS_HUGE_PAGES();
  std::vector<char> v(3 << 20, 1);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(v.data()) % vob::kHugePageBytes, 0u);
  EXPECT_TRUE(advised_huge(v.data())) << vm_flags(v.data());
}

// Kept, not unmapped: the same block comes back with its pages (and their contents) as they
// were, so a per-frame array of one size is not faulted in again every frame.
TEST(HugePageNew, FreedLargeBlockIsReusedForTheSameSize) {
  SKIP_UNLESS_HUGE_PAGES();
  const size_t n = size_t(5) << 20, probe = size_t(3) << 20;
  char* first = static_cast<char*>(::operator new(n));
  first[probe] = 7;
  const uintptr_t first_at = reinterpret_cast<uintptr_t>(first);
  ::operator delete(first);
  volatile char* again = static_cast<char*>(::operator new(n));
  EXPECT_EQ(reinterpret_cast<uintptr_t>(again), first_at);
  EXPECT_EQ(again[probe], 7);  // a fresh mapping reads 0
  ::operator delete(const_cast<char*>(again));
}

// The advice stays with the large blocks: glibc's heap, whose mmap threshold a large
// malloc'd block raises, never hands a range advised for a large block to a smaller one.
// (With large blocks taken from the heap, the 1.5 MiB blocks below landed on the advised
// ranges the freed large ones had left there.)
TEST(HugePageNew, SmallBlocksNeverLandOnAdvisedRanges) {
  SKIP_UNLESS_HUGE_PAGES();
  void* raised = std::malloc(size_t(16) << 20);  // mmapped; freed, it raises the threshold to 16 MiB
  static_cast<char*>(raised)[0] = 1;
  std::free(raised);
  std::vector<std::vector<char>*> large;
  for (int i = 0; i < 8; ++i) large.push_back(new std::vector<char>(size_t(3 + i % 3) << 20, 1));
  for (auto* v : large) delete v;
  std::vector<std::vector<char>*> small;
  for (int i = 0; i < 16; ++i) small.push_back(new std::vector<char>(size_t(3) << 19, 1));
  for (const auto* v : small) EXPECT_FALSE(advised_huge(v->data())) << vm_flags(v->data());
  for (auto* v : small) delete v;
}

}  // namespace
