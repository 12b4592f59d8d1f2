#include "study/study_reader.hpp"

#include <algorithm>

#include <yaml-cpp/yaml.h>

#include "scene/scene_loader.hpp"
#include "study/sweep_values.hpp"

namespace penumbra {
namespace {

using scenefile::Field;
using scenefile::MapView;
using scenefile::Reader;
using scenefile::Where;

void checkVersion(const Reader& reader, const MapView& root) {
  const std::string expected = std::to_string(kStudyFormatVersion);
  const std::optional<Field> field = root.find("penumbra-study");
  if (!field) {
    reader.fail(Where{root.where().line, "penumbra-study"},
                "a study file starts with its format: 'penumbra-study: " + expected + "'" +
                    (root.has("penumbra") ? " (this looks like a scene: run it with "
                                            "`penumbra grid`, or sweep it from a study file)"
                                          : ""));
  }
  if (!field->node.IsScalar() || field->node.Scalar() != expected) {
    reader.fail(field->where, "this penumbra reads study format version " + expected +
                                  ", but the file says '" +
                                  (field->node.IsScalar() ? field->node.Scalar() : "?") + "'");
  }
}

bool readFlag(const Reader& reader, const Field& field) {
  if (field.node.IsScalar()) {
    const std::string& text = field.node.Scalar();
    if (text == "true" || text == "yes") return true;
    if (text == "false" || text == "no") return false;
  }
  reader.fail(field.where, "expected true or false");
}

std::vector<std::string> readNames(const Reader& reader, const Field& field,
                                   std::string_view what) {
  std::vector<std::string> names;
  for (const Field& item : reader.list(field, what)) names.push_back(reader.text(item));
  return names;
}

std::vector<StudyMetric> readMetrics(const Reader& reader, const Field& field) {
  std::vector<StudyMetric> metrics;
  for (const Field& item : reader.list(field, "a list of metrics")) {
    const std::string name = reader.text(item);
    const std::optional<StudyMetric> metric = metricNamed(name);
    if (!metric) {
      std::string known;
      for (const StudyMetricInfo& m : studyMetrics())
        known += (known.empty() ? "" : ", ") + std::string(m.name);
      reader.fail(item.where, "unknown metric '" + name + "'; the metrics are: " + known);
    }
    if (std::find(metrics.begin(), metrics.end(), *metric) != metrics.end()) {
      reader.fail(item.where, "the metric '" + name + "' is listed twice");
    }
    metrics.push_back(*metric);
  }
  return metrics;
}

// `renders: [view, ...]`: views the scene declares, each once.
std::vector<std::string> readRenders(const Reader& reader, const Field& field,
                                     const std::filesystem::path& scene) {
  if (field.node.IsNull()) return {};
  std::vector<std::string> views = readNames(reader, field, "a list of view names");
  const Scene base = loadScene(scene);
  for (std::size_t i = 0; i < views.size(); ++i) {
    const Where where{field.where.line, scenefile::indexKey(field.where.key, i)};
    if (std::find(views.begin(), views.begin() + i, views[i]) != views.begin() + i) {
      reader.fail(where, "the view '" + views[i] + "' is listed twice");
    }
    if (std::none_of(base.views.begin(), base.views.end(),
                     [&](const View& v) { return v.name == views[i]; })) {
      std::string known;
      for (const View& v : base.views) known += (known.empty() ? "" : ", ") + v.name;
      reader.fail(where, "the scene has no view '" + views[i] + "'; " +
                             (known.empty() ? "it declares none (views: in the scene file)"
                                            : "its views are: " + known));
    }
  }
  return views;
}

// Every study parameter must be one the scene declares: a typo would otherwise sweep nothing.
void checkAgainstScene(const Reader& reader, const Study& study) {
  const ParameterValues declared = loadSceneParameters(study.scene);
  for (const StudyParameter& p : study.parameters) {
    const bool known = std::any_of(declared.begin(), declared.end(),
                                   [&](const ParameterValue& d) { return d.name == p.name; });
    if (known) continue;
    std::string names;
    for (const ParameterValue& d : declared) names += (names.empty() ? "" : ", ") + d.name;
    reader.fail(p.where, "'" + p.name + "' is not a parameter of " + study.scene.string() + "; " +
                             (names.empty() ? "the scene declares none (add 'parameters: {" +
                                                  p.name + ": default}' to it)"
                                            : "it declares: " + names));
  }
}

}  // namespace

Study parseStudy(const std::string& yamlText, const std::filesystem::path& file) {
  const YAML::Node document = scenefile::parseYaml(yamlText, file);
  const Reader reader(file);
  if (!document.IsDefined() || document.IsNull()) {
    reader.fail(Where{0, ""}, "the study file is empty; it starts with 'penumbra-study: 1'");
  }
  const MapView root = reader.map(reader.root(document), "the study");
  root.allowOnly({"penumbra-study", "description", "scene", "parameters", "combination", "grids",
                  "metrics", "plots", "charts", "renders"},
                 "a study");
  checkVersion(reader, root);

  Study study;
  study.file = file;
  if (const std::optional<Field> d = root.find("description")) study.description = reader.text(*d);
  study.scene = (file.parent_path() / reader.text(root.require("scene"))).lexically_normal();

  const Field parameters = root.require("parameters");
  study.parametersWhere = parameters.where;
  const MapView parameterMap = reader.map(parameters, "parameters {name: values, ...}");
  for (const MapView::Entry& e : parameterMap.entries()) {
    study.parameters.push_back(
        StudyParameter{e.key, readSweepValues(reader, e.value), e.value.where});
  }
  if (study.parameters.empty()) reader.fail(parameters.where, "the study varies no parameters");

  study.combinationWhere = root.where();
  if (const std::optional<Field> c = root.find("combination")) {
    study.combinationWhere = c->where;
    const std::string how = reader.text(*c);
    if (how != "grid" && how != "zip") {
      reader.fail(c->where,
                  "expected 'grid' (every combination of the values) or 'zip' (the "
                  "i-th values together), got '" +
                      how + "'");
    }
    study.combination = how == "grid" ? Combination::Grid : Combination::Zip;
  }
  study.gridsWhere = root.where();
  if (const std::optional<Field> g = root.find("grids")) {
    study.gridsWhere = g->where;
    study.grids = readNames(reader, *g, "a list of grid names");
  }
  if (const std::optional<Field> m = root.find("metrics")) {
    study.metrics = readMetrics(reader, *m);
    study.metricsGiven = true;
  } else {
    for (const StudyMetricInfo& info : studyMetrics())
      if (info.needs == MetricNeeds::Nothing) study.metrics.push_back(info.metric);
  }
  if (const std::optional<Field> p = root.find("plots")) study.plots = readFlag(reader, *p);
  if (const std::optional<Field> c = root.find("charts")) study.charts = readFlag(reader, *c);
  if (const std::optional<Field> r = root.find("renders")) {
    study.renders = readRenders(reader, *r, study.scene);
  }

  checkAgainstScene(reader, study);
  return study;
}

Study loadStudy(const std::filesystem::path& file) {
  return parseStudy(scenefile::readInputFile(file, "the study file"), file);
}

}  // namespace penumbra
