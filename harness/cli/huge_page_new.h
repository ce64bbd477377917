// The vobench program's global operator new. Blocks of at least kHugePageMinBytes are
// aligned to 2 MiB and advised MADV_HUGEPAGE, so the kernel backs them with transparent
// huge pages where it allows (Debian's default mode is "madvise"): one page fault per 2 MiB
// instead of 512. On virtual machines a fault can cost 10-30 us (this project's host: 100 MB
// first touched in 0.8 s, 23 ms with huge pages), and the orderers' per-view arrays, the
// oracle's buffers and prepare's tables would otherwise be timed as page faults.
// VOBENCH_HUGE_PAGES=0 in the environment turns it off (plain malloc). Large blocks are
// mappings of their own, so the advice never reaches malloc's heap; a freed one is kept for
// reuse (up to 32 blocks, 512 MiB). Smaller blocks are plain malloc either way. Not built
// under AddressSanitizer, which replaces operator new itself. Only the program: tests,
// plugins' own programs and the Python module allocate as usual.
#pragma once
#include <cstddef>
#include <string>

#include "harness/huge_mapping.h"

namespace vob {

inline constexpr size_t kHugePageBytes = kHugeMappingAlign;  // 2 MiB
inline constexpr size_t kHugePageMinBytes = kHugePageBytes;
// Freed large blocks kept for reuse, at most (the oldest are unmapped first).
inline constexpr size_t kHugeReuseBlocks = 32, kHugeReuseBytes = size_t(512) << 20;

struct HugePagePolicy {
  bool on = false;         // large blocks are advised MADV_HUGEPAGE
  std::string kernel;      // the kernel's mode (/sys/kernel/mm/transparent_hugepage/enabled)
  std::string why;         // why off, or ""
};
HugePagePolicy huge_page_policy();

}  // namespace vob
