#pragma once
// A case's fingerprint: a hash of everything its results depend on, recorded in its folder, so
// that a rerun skips a finished case only when nothing behind it changed (the scene file, a .pts
// file, the study's values, the grids or the estimator), never reusing stale results.
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

// What a case computes besides its scene.
struct CaseOutputs {
  std::vector<std::string> grids;  // the grids computed
  std::string estimator;           // "kernel", or "reference n=64"
  std::vector<std::string> files;  // the per-case outputs written (case_output.hpp): "plots"
};

// 16 hex digits (64-bit FNV-1a) over the built scene (materials, solids, sources, grid points,
// parameter values; every number exactly) and `outputs`. Formatting and comments of the scene
// file do not change it.
std::string caseFingerprint(const Scene& scene, const CaseOutputs& outputs);

}  // namespace penumbra
