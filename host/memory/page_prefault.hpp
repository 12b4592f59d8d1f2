#pragma once
// Page faults are dear on the virtual machines penumbra runs on: about 15 µs for each 4 KB page
// first written on the 2-core test machine (20-27 µs under load), against about 1 µs a page
// (1.6 µs under load) when madvise(MADV_POPULATE_WRITE) maps a whole range in one call. The large
// buffers of a run (a grid batch's points and rows, a launch's per-source outputs, the transfer
// matrix) are mapped this way before their first write. A kernel without MADV_POPULATE_WRITE
// (before Linux 5.14) refuses the call and leaves the pages to their first use: the same values,
// the old cost.
#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace penumbra {

// Below this a buffer's faults cost less than the call.
constexpr std::size_t kPopulateMinBytes = std::size_t{1} << 20;

// Maps the whole pages within [data, data + bytes) for writing, at once.
inline void populatePages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
}

// Room for `extra` more elements after v's, growing as push_back does (at least doubling), the
// new allocation's pages mapped before the elements are copied in: for tables appended to piece
// by piece whose final size is not known ahead.
template <typename T>
void reservePopulated(std::vector<T>& v, std::size_t extra) {
  const std::size_t needed = v.size() + extra;
  if (needed <= v.capacity()) return;
  const std::size_t capacity = std::max(needed, 2 * v.capacity());
  if (capacity * sizeof(T) < kPopulateMinBytes) {
    v.reserve(capacity);
    return;
  }
  std::vector<T> grown;
  grown.reserve(capacity);
  populatePages(grown.data(), capacity * sizeof(T));
  grown.assign(v.begin(), v.end());
  v.swap(grown);
}

// v resized to n (new elements value-initialised), a new allocation's pages mapped before
// anything is written to them.
template <typename T>
void resizePopulated(std::vector<T>& v, std::size_t n) {
  if (n > v.size()) reservePopulated(v, n - v.size());
  v.resize(n);
}

// Allocates `bytes` in blocks of 4 MB, maps their pages and frees them: with main()'s malloc
// settings (blocks up to 32 MB kept in the heap, the heap's top not trimmed) the calling thread's
// next allocations up to that size reuse mapped pages. A grid of many batches allocates the same
// few tens of MB per batch and reuses them from the second batch on; this maps the first batch's
// ahead. Without those settings (a test program) the blocks are mmap'd and unmapped again,
// which costs the mapping only.
inline void prefaultHeap(std::size_t bytes) {
  constexpr std::size_t kBlock = std::size_t{4} << 20;
  std::vector<void*> blocks;
  for (std::size_t done = 0; done < bytes; done += kBlock) {
    void* block = std::malloc(kBlock);
    if (block == nullptr) break;
    blocks.push_back(block);
    populatePages(block, kBlock);
  }
  for (void* block : blocks) std::free(block);
}

}  // namespace penumbra
