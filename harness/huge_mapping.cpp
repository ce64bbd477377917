#include "harness/huge_mapping.h"

#include <sys/mman.h>

#include <cstdint>

namespace vob {

void* map_huge(size_t bytes) {
  const size_t span = bytes + kHugeMappingAlign;  // room to align, the rest given back
  void* raw = mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const uintptr_t lo = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t p = (lo + kHugeMappingAlign - 1) & ~(uintptr_t(kHugeMappingAlign) - 1);
  if (p > lo) munmap(raw, p - lo);
  if (lo + span > p + bytes) munmap(reinterpret_cast<void*>(p + bytes), lo + span - (p + bytes));
  madvise(reinterpret_cast<void*>(p), bytes, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(p);
}

void unmap_huge(void* p, size_t bytes) {
  if (p) munmap(p, bytes);
}

}  // namespace vob
