#pragma once
// A study made ready to run: every case's scene is built once up front, so that a case with an
// invalid scene stops the sweep before anything is computed or written, and fingerprinted
// (case_fingerprint.hpp) so that finished cases can be recognised.
#include <string>
#include <vector>

#include "illuminance/estimator.hpp"
#include "scene/scene.hpp"
#include "study/study.hpp"
#include "study/study_layout.hpp"

namespace penumbra {

struct StudyPlan {
  Study study;
  StudyLayout layout;
};

// How the fingerprints name the estimator: "kernel" or "reference n=<n>".
std::string estimatorIdentity(const EstimatorOptions& options);

// `estimator` is "kernel" or "reference n=<n>"; `caseOutputs` the per-case outputs that will be
// written (case_output.hpp: "plots"), which are part of every case's fingerprint;
// `interreflected` whether E includes the interreflected light (the daylight factor's components
// are then among the default metrics of a scene with a sky).
// Throws SceneError: a case whose scene is invalid (naming the case, its values and the scene's
// file:line:key), or a grid in `grids:` that the scene does not have.
StudyPlan planStudy(const Study& study, const std::string& estimator,
                    const std::vector<std::string>& caseOutputs, bool interreflected = false);

// The scene of one case, with the same error as planStudy.
Scene loadCaseScene(const Study& study, const PlannedCase& planned);

}  // namespace penumbra
