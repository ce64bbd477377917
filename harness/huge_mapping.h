// Memory on transparent huge pages as a mapping of its own (mmap, 2 MiB-aligned, advised
// MADV_HUGEPAGE), never a range of malloc's heap: advice given to a heap range outlives the
// block and reaches whatever malloc puts there later (see docs/design-notes.md, "Large blocks
// as mappings of their own"). Used by the program's operator new and by buffers that want
// huge pages in any process (HugeWords).
#pragma once
#include <cstddef>

namespace vob {

inline constexpr size_t kHugeMappingAlign = size_t(2) << 20;

// A fresh mapping of `bytes` (a multiple of kHugeMappingAlign), aligned to it and advised
// (advice only: where the kernel refuses, plain pages); nullptr when mmap fails.
void* map_huge(size_t bytes);
// Releases a map_huge block of the same `bytes`.
void unmap_huge(void* p, size_t bytes);

}  // namespace vob
