#include "study/study_plan.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "grid/scene_grids.hpp"
#include "scene/scene_loader.hpp"
#include "study/case_fingerprint.hpp"
#include "study/study_cases.hpp"

namespace penumbra {
namespace {

void checkGrids(const Study& study, const Scene& scene, const std::string& caseId) {
  for (const std::string& name : study.grids) {
    const bool known = std::any_of(scene.grids.begin(), scene.grids.end(),
                                   [&](const CalculationGrid& g) { return g.name == name; });
    if (known) continue;
    std::string names;
    for (const CalculationGrid& g : scene.grids) names += (names.empty() ? "" : ", ") + g.name;
    throw SceneError(study.file, study.gridsWhere.line, "grids",
                     "'" + name + "' is not a grid of " + study.scene.string() + " (" + caseId +
                         "); it has: " + (names.empty() ? "none" : names));
  }
}

}  // namespace

std::string estimatorIdentity(const EstimatorOptions& options) {
  if (options.reference) return "reference n=" + std::to_string(options.referenceN);
  if (!options.interreflection) return "kernel, direct only";
  return fmt::format("kernel, interreflection, elements {} m", options.mesh.elementSize);
}

Scene loadCaseScene(const Study& study, const PlannedCase& planned) {
  try {
    return loadScene(study.scene, planned.values);
  } catch (const SceneError& e) {
    throw SceneError(study.file, study.parametersWhere.line, "parameters",
                     planned.id + " (" + describeParameters(planned.values) +
                         ") makes an invalid scene: " + e.what());
  }
}

StudyPlan planStudy(const Study& study, const std::string& estimator,
                    const std::vector<std::string>& caseOutputs, bool interreflected) {
  StudyPlan plan;
  plan.study = study;
  StudyLayout& layout = plan.layout;
  layout.studyFile = study.file.string();
  layout.sceneFile = study.scene.string();
  for (const StudyParameter& p : study.parameters) layout.parameters.push_back(p.name);
  layout.combination = study.combination;
  layout.metrics = study.metrics;
  layout.caseOutputs = caseOutputs;
  layout.charts = study.charts;
  for (const StudyCase& c : studyCases(study)) {
    PlannedCase planned{c.id, c.values, ""};
    const Scene scene = loadCaseScene(study, planned);
    checkGrids(study, scene, c.id);
    if (layout.cases.empty()) {
      for (const CalculationGrid* g : selectGrids(scene, study.grids))
        layout.grids.push_back(g->name);
      if (!study.metricsGiven) {
        // The daylight metrics with a sky (the EN 17037 level also needs the site's median
        // diffuse illuminance, the components interreflection), the sun's with a sun.
        const bool verdict = scene.site && scene.site->medianDiffuseIlluminance;
        for (const StudyMetricInfo& info : studyMetrics()) {
          const bool given =
              (info.needs == MetricNeeds::Sky && scene.sky &&
               (info.metric != StudyMetric::EN17037 || verdict)) ||
              (info.needs == MetricNeeds::Components && scene.sky && interreflected) ||
              (info.needs == MetricNeeds::Sun && scene.sun);
          if (given) layout.metrics.push_back(info.metric);
        }
      }
    }
    planned.fingerprint = caseFingerprint(scene, CaseOutputs{layout.grids, estimator, caseOutputs});
    layout.cases.push_back(std::move(planned));
  }
  return plan;
}

}  // namespace penumbra
