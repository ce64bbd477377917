#include "harness/cli/huge_page_new.h"

#include <sys/mman.h>

#include <cstdlib>
#include <fstream>
#include <new>

namespace vob {
namespace {

bool requested() {
  const char* v = std::getenv("VOBENCH_HUGE_PAGES");
  return !(v && std::string(v) == "0");
}

#if !defined(__SANITIZE_ADDRESS__)
constexpr bool kBuilt = true;
#else
constexpr bool kBuilt = false;
#endif

}  // namespace

HugePagePolicy huge_page_policy() {
  HugePagePolicy p;
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::getline(in, p.kernel);
  if (p.kernel.empty()) p.kernel = "unknown";
  if (!kBuilt) p.why = "not built under AddressSanitizer";
  else if (!requested()) p.why = "VOBENCH_HUGE_PAGES=0";
  else if (p.kernel.find("[never]") != std::string::npos) p.why = "the kernel's mode is never";
  p.on = p.why.empty();
  return p;
}

}  // namespace vob

#if !defined(__SANITIZE_ADDRESS__)
namespace {
// A block of n >= kHugePageMinBytes on 2 MiB pages where allowed, or null.
void* huge_block(std::size_t n) {
  // Decided at the first large block (small ones, such as the policy's own reads, never
  // reach this static).
  static const bool on = vob::huge_page_policy().on;
  if (!on) return nullptr;
  const size_t rounded = (n + vob::kHugePageBytes - 1) / vob::kHugePageBytes * vob::kHugePageBytes;
  void* p = std::aligned_alloc(vob::kHugePageBytes, rounded);
  if (p) madvise(p, rounded, MADV_HUGEPAGE);  // advice only: refused, the block is plain pages
  return p;
}
}  // namespace

// The one replaceable form the others (array, nothrow) go through in libstdc++; aligned
// forms keep their own (aligned_alloc, also released by free).
void* operator new(std::size_t n) {
  if (n >= vob::kHugePageMinBytes)
    if (void* p = huge_block(n)) return p;
  for (;;) {
    if (void* p = std::malloc(n ? n : 1)) return p;
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}
#endif
