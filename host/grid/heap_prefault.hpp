#pragma once
// Page faults are dear on the virtual machines penumbra runs on: 12-27 µs for each 4 KB page
// first written (the 2-core test machine), against 1.6 µs a page when madvise(MADV_POPULATE_WRITE)
// maps a whole range at once. A grid of many batches allocates the same few tens of MB per batch
// (points, Morton keys, patch tables, outputs) and, with main()'s malloc settings (blocks up to
// 32 MB kept in the heap, the heap's top not trimmed), reuses them from the second batch on: what
// is left is the first batch's faults, about 8 000 on a 65 536-point batch. prefaultHeap maps
// that memory in the calling thread's malloc arena ahead, in one call a block.
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace penumbra {

// Allocates `bytes` in blocks of 4 MB, maps their pages at once and frees them: the calling
// thread's next allocations up to that size reuse mapped pages. Without main()'s malloc settings
// (a test program) the blocks are mmap'd and unmapped again, which costs the mapping only. A
// kernel without MADV_POPULATE_WRITE (before Linux 5.14) leaves the pages to their first use.
inline void prefaultHeap(std::size_t bytes) {
  constexpr std::size_t kBlock = std::size_t{4} << 20, kPage = 4096;
  std::vector<void*> blocks;
  for (std::size_t done = 0; done < bytes; done += kBlock) {
    void* block = std::malloc(kBlock);
    if (block == nullptr) break;
    blocks.push_back(block);
    const std::uintptr_t first =
        (reinterpret_cast<std::uintptr_t>(block) + kPage - 1) & ~(kPage - 1);
    madvise(reinterpret_cast<void*>(first), kBlock - kPage, MADV_POPULATE_WRITE);
  }
  for (void* block : blocks) std::free(block);
}

}  // namespace penumbra
