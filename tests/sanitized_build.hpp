#pragma once
// What the tests do differently in the sanitizer build (-DPENUMBRA_SANITIZE, docs/reliability.md),
// and why. Two things, each where a sanitizer changes a cost, not a result:
//  * referenceSamples: how finely the tests sample the reference (below);
//  * scale_test runs `penumbra` without ASan's quarantine of freed memory when it measures RSS.
//
// The reference is a sampling loop: at n = 1024 one point costs about 10^6 segment tests per source
// face. Under ASan + UBSan that loop runs about 18× slower (Occlusion.BoxBetweenPanelAndFloor:
// 1.4 s in the Release build, 26.6 s under g++ -O2 ASan + UBSan, perf: 94 % of it in the
// reference's chunkSum), and the sanitizer suite, where a dozen tests each spend 40-250 s in it,
// does not fit CI's hour (docs/reliability.md). The sanitizer build is there to find invalid
// accesses, leaks and undefined behaviour; the reference runs the same code at n = 256, only fewer
// times round its innermost loop. Its error there is 2e-5 of E_unoccluded on the CIE 171 scenes
// (host/reference/reference_illuminance.cpp), a hundred times inside the 2e-3 criterion these tests
// hold the kernel to, but not at every point: 1 mm in front of an opening's edge it errs 2.7e-3, so
// aperture_test samples it at n = 1024 or, in the sanitizer build, not at all (the exact reference,
// host/reference/exact_illuminance, holds the kernel there to 1e-5 instead, in milliseconds). The
// Release build, which holds the numbers, keeps every n as asked.
#include <algorithm>

namespace penumbra::testing {

#ifdef PENUMBRA_SANITIZED
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

// The largest n the sanitizer build samples the reference with.
inline constexpr int kSanitizedReferenceN = 256;

// n for the reference in this build: as asked, or at most kSanitizedReferenceN under sanitizers.
constexpr int referenceSamples(int n) {
  return kSanitizedBuild ? std::min(n, kSanitizedReferenceN) : n;
}

}  // namespace penumbra::testing
