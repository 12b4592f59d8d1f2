#pragma once
// How the penumbra process keeps freed memory: batches of points allocate and free buffers of a
// few MB to a few tens of MB, launch after launch (points, patch tables, per-source outputs, the
// OpenCL buffers, a render's per-pixel layers). By default glibc serves such blocks by mmap and
// unmaps them on free, so every launch faults its pages in afresh (about 15 µs a page on the test
// machine, page_prefault.hpp): a fifth of the office's grid run time. Keeping blocks up to 32 MB
// (glibc's largest threshold) in the heap, and the heap's top up to 1 GB untrimmed, lets the next
// batch reuse them: `penumbra grid data/office.yaml` 2.6-2.8 s -> 2.0-2.3 s, page faults
// 70 000 -> 53 000. main() sets it first thing; the benches that time the product's paths in
// their own process set it too, so that they measure what the command does.
#include <malloc.h>

namespace penumbra {

inline void keepFreedBlocksInTheHeap() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace penumbra
