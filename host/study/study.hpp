#pragma once
// A study file (docs/sweeps.md): a base scene, the values its parameters take, how the values
// combine into cases, and what to produce per case. Read by loadStudy (study_reader.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "scene/yaml_reader.hpp"
#include "study/study_metrics.hpp"

namespace penumbra {

// grid: every combination of the values (the first parameter varies slowest); zip: the i-th
// values of every parameter together, so all lists have one length.
enum class Combination { Grid, Zip };

struct StudyParameter {
  std::string name;
  std::vector<double> values;  // in the order given, no repeats
  scenefile::Where where;      // parameters.<name>
};

struct Study {
  std::filesystem::path file;   // the study file as given
  std::filesystem::path scene;  // the base scene: its path relative to the study's folder, resolved
  std::string description;
  std::vector<StudyParameter> parameters;
  scenefile::Where parametersWhere;
  Combination combination = Combination::Grid;
  scenefile::Where combinationWhere;
  std::vector<std::string> grids;  // the scene's grids to compute; empty: all of them
  scenefile::Where gridsWhere;
  // Table columns and charts. Without `metrics:` in the study: every illuminance metric, for a
  // scene with a sky the daylight ones too and for a scene with a sun the sun's (planStudy adds
  // them).
  std::vector<StudyMetric> metrics;
  bool metricsGiven = false;         // `metrics:` named them
  bool plots = false;                // per-case plots (what `penumbra grid --plot` draws)
  bool charts = true;                // a chart of each metric against each varied parameter
  std::vector<std::string> renders;  // views of the scene to render per case; empty: none
  // The renders' exposure (`sweep --exposure`): "" each case on its own, a white in cd/m², or
  // "auto-first".
  std::string renderExposure;
  // The renders' target display (`sweep --display-luminance/--ambient`): "" the default,
  // otherwise renderDisplayName() of it.
  std::string renderDisplay;
};

// The name of the render output for `views` ("renders:from-door,plan", "renders:plan
// display=200cd/m2,ambient=500lx exposure=200"): the views, the target display and the exposure
// are part of the name, so a case rendered with other views, for another display or with another
// exposure is not finished for this study. The exposure comes last (exposedAsOne reads it there).
inline std::string renderOutputName(const std::vector<std::string>& views,
                                    const std::string& exposure, const std::string& display = "") {
  std::string name = "renders:";
  for (std::size_t i = 0; i < views.size(); ++i) name += (i ? "," : "") + views[i];
  if (!display.empty()) name += " " + display;
  return exposure.empty() ? name : name + " exposure=" + exposure;
}

// The per-case outputs the study asks for, by the names of their writers (case_output.hpp):
// "plots" for `plots: true`, renderOutputName(renders) for `renders: [views]`.
inline std::vector<std::string> requestedCaseOutputs(const Study& study) {
  std::vector<std::string> names;
  if (study.plots) names.push_back("plots");
  if (!study.renders.empty())
    names.push_back(renderOutputName(study.renders, study.renderExposure, study.renderDisplay));
  return names;
}

}  // namespace penumbra
