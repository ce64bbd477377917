#include "harness/cli/huge_page_new.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <new>

#include "harness/huge_mapping.h"

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
// Large blocks are mappings of their own, never carved from malloc's heap: advice given to
// a heap range outlives the block (glibc hands the range to later, smaller blocks, which
// then sat on huge pages or not depending on the process's history: MPVONC's DFS on the
// 1.5M helix ran about a quarter slower in 10 of 22 processes). A freed block is kept for
// reuse (its pages stay faulted in, as a heap block's would) up to the header's caps.
constexpr size_t kCacheBlocks = vob::kHugeReuseBlocks, kCacheBytes = vob::kHugeReuseBytes;
constexpr size_t kLiveBlocks = 4096;  // blocks out at once; beyond it, plain malloc
struct Block {
  void* p;
  size_t bytes;
};
std::mutex& lock() {
  static std::mutex m;
  return m;
}
// Under lock(): the blocks handed out and the freed ones kept, oldest first.
Block live[kLiveBlocks];
size_t live_n = 0;
Block cache[kCacheBlocks];
size_t cache_n = 0, cache_bytes = 0;

// A block of n >= kHugePageMinBytes on 2 MiB pages where allowed, or null.
void* huge_block(std::size_t n) {
  // Decided at the first large block (small ones, such as the policy's own reads, never
  // reach this static).
  static const bool on = vob::huge_page_policy().on;
  if (!on) return nullptr;
  const size_t rounded = (n + vob::kHugePageBytes - 1) / vob::kHugePageBytes * vob::kHugePageBytes;
  {
    std::lock_guard<std::mutex> g(lock());
    if (live_n == kLiveBlocks) return nullptr;
    // The smallest kept block that fits without wasting more than the request.
    size_t best = cache_n;
    for (size_t i = 0; i < cache_n; ++i)
      if (cache[i].bytes >= rounded && cache[i].bytes <= 2 * rounded &&
          (best == cache_n || cache[i].bytes < cache[best].bytes))
        best = i;
    if (best < cache_n) {
      const Block b = cache[best];
      for (size_t i = best; i + 1 < cache_n; ++i) cache[i] = cache[i + 1];
      --cache_n;
      cache_bytes -= b.bytes;
      live[live_n++] = b;
      return b.p;
    }
  }
  void* p = vob::map_huge(rounded);
  if (!p) return nullptr;
  std::lock_guard<std::mutex> g(lock());
  if (live_n == kLiveBlocks) {
    vob::unmap_huge(p, rounded);
    return nullptr;
  }
  live[live_n++] = {p, rounded};
  return p;
}

// True when p was a large block (then kept or unmapped).
bool release_huge(void* p) {
  if ((reinterpret_cast<uintptr_t>(p) & (vob::kHugePageBytes - 1)) != 0) return false;  // malloc's
  Block evicted[kCacheBlocks + 1];
  size_t n_evicted = 0;
  {
    std::lock_guard<std::mutex> g(lock());
    size_t i = 0;
    while (i < live_n && live[i].p != p) ++i;
    if (i == live_n) return false;
    const Block b = live[i];
    live[i] = live[--live_n];
    if (b.bytes > kCacheBytes / 2) {
      evicted[n_evicted++] = b;
    } else {
      while (cache_n == kCacheBlocks || cache_bytes + b.bytes > kCacheBytes) {  // oldest out
        evicted[n_evicted++] = cache[0];
        cache_bytes -= cache[0].bytes;
        for (size_t k = 0; k + 1 < cache_n; ++k) cache[k] = cache[k + 1];
        --cache_n;
      }
      cache[cache_n++] = b;
      cache_bytes += b.bytes;
    }
  }
  for (size_t k = 0; k < n_evicted; ++k) vob::unmap_huge(evicted[k].p, evicted[k].bytes);
  return true;
}
}  // namespace

// The one replaceable form the others (array, nothrow) go through in libstdc++; aligned
// forms keep their own (aligned_alloc, released by free).
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

// libstdc++'s sized, array and nothrow forms call this one.
void operator delete(void* p) noexcept {
  if (p && release_huge(p)) return;
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { ::operator delete(p); }
#endif
