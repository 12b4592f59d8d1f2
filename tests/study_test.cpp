// Study files, their cases, shards, fingerprints, and the tables and charts built from finished
// cases: everything of a sweep that needs no device.
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "scene/scene_loader.hpp"
#include "study/case_fingerprint.hpp"
#include "study/parameter_label.hpp"
#include "study/results_table.hpp"
#include "study/study_cases.hpp"
#include "study/study_charts.hpp"
#include "study/study_plan.hpp"
#include "study/study_reader.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = PENUMBRA_SOURCE_DIR;
// Studies parsed from text are "in" studies/, so that `scene: ../data/office.yaml` resolves.
const fs::path kStudyFile = kSourceDir / "studies" / "test.yaml";

std::string study(const std::string& parameters, const std::string& rest = "") {
  return "penumbra-study: 1\nscene: ../data/office.yaml\nparameters:\n" + parameters + rest;
}

Study parsed(const std::string& text) {
  return parseStudy(text, kStudyFile);
}

SceneError studyError(const std::string& text) {
  try {
    parsed(text);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a SceneError for:\n" << text;
  return SceneError("none", -1, "", "none");
}

void expectContains(const std::string& text, const std::string& words) {
  EXPECT_NE(text.find(words), std::string::npos) << text;
}

// ---------------------------------------------------------------- reading

TEST(StudyFile, ValuesRangesAndLinspaces) {
  const Study s =
      parsed(study("  window_width_m: {range: {from: 1.0, to: 3.0, step: 0.1}}\n"
                   "  panel_flux_lm: [3000, 4000]\n"
                   "  floor_reflectance: {linspace: {from: 0.1, to: 0.7, count: 4}}\n"
                   "  panel_spacing_m: {values: [2.5]}\n"));
  EXPECT_EQ(s.scene, (kSourceDir / "data" / "office.yaml").lexically_normal());
  ASSERT_EQ(s.parameters.size(), 4u);
  const std::vector<double>& widths = s.parameters[0].values;
  ASSERT_EQ(widths.size(), 21u);
  EXPECT_EQ(widths.front(), 1.0);
  EXPECT_EQ(widths[5], 1.5);  // not 1.5000000000000002
  EXPECT_EQ(widths.back(), 3.0);
  EXPECT_EQ(s.parameters[1].values, (std::vector<double>{3000, 4000}));
  EXPECT_EQ(s.parameters[2].values, (std::vector<double>{0.1, 0.3, 0.5, 0.7}));
  EXPECT_EQ(s.parameters[3].values, (std::vector<double>{2.5}));
  EXPECT_EQ(s.combination, Combination::Grid);
  EXPECT_EQ(s.metrics.size(), 5u);
  EXPECT_TRUE(s.grids.empty());
  EXPECT_TRUE(s.charts);
  EXPECT_FALSE(s.plots);
}

TEST(StudyFile, ARangeCanCountDown) {
  const Study s = parsed(study("  window_width_m: {range: {from: 2, to: 1, step: -0.5}}\n"));
  EXPECT_EQ(s.parameters[0].values, (std::vector<double>{2.0, 1.5, 1.0}));
}

TEST(StudyFile, TheBundledStudiesRead) {
  for (const char* name :
       {"window-width.yaml", "panel-spacing-flux.yaml", "floor-reflectance.yaml"}) {
    SCOPED_TRACE(name);
    const Study s = loadStudy(kSourceDir / "studies" / name);
    EXPECT_FALSE(s.parameters.empty());
  }
  EXPECT_GE(studyCases(loadStudy(kSourceDir / "studies" / "window-width.yaml")).size(), 20u);
}

TEST(StudyErrors, EachNamesItsLineAndKey) {
  struct Case {
    std::string text;
    int line;
    std::string key, words;
  };
  const std::vector<Case> cases{
      {study("  window_wdth_m: [1, 2]\n"), 4, "parameters.window_wdth_m",
       "'window_wdth_m' is not a parameter of"},
      {study("  window_width_m: {range: {from: 3, to: 1, step: 0.5}}\n"), 4,
       "parameters.window_width_m.range", "the range is empty: from 3 to 1 with step 0.5"},
      {study("  window_width_m: {range: {from: 1, to: 2, step: 0}}\n"), 4,
       "parameters.window_width_m.range.step", "cannot be 0"},
      {study("  window_width_m: []\n"), 4, "parameters.window_width_m",
       "the list of values is empty"},
      {study("  window_width_m: [1, 2, 1]\n"), 4, "parameters.window_width_m",
       "the value 1 is given twice"},
      {study("  window_width_m: {linspace: {from: 1, to: 2, count: 2.5}}\n"), 4,
       "parameters.window_width_m.linspace.count", "a whole number of at least 1"},
      {study("  window_width_m: {values: [1], range: {from: 1, to: 2, step: 1}}\n"), 4,
       "parameters.window_width_m", "exactly one"},
      {study("  window_width_m: [1]\n", "metrics: [Eavg, Emean]\n"), 5, "metrics[1]",
       "unknown metric 'Emean'"},
      {study("  window_width_m: [1]\n", "renders: [view-1]\n"), 5, "renders[0]",
       "the scene has no view 'view-1'; its views are: from-door, from-window"},
      {study("  window_width_m: [1]\n", "renders: [from-door, from-door]\n"), 5, "renders[1]",
       "the view 'from-door' is listed twice"},
      {study("  window_width_m: [1]\n", "combination: all\n"), 5, "combination", "'grid'"},
      {study("  window_width_m: [1]\n", "colour: red\n"), 5, "colour", "unknown key 'colour'"},
      {study("  window_width_m: [\"${1}\"]\n"), 4, "parameters.window_width_m[0]", "plain numbers"},
      {"scene: ../data/office.yaml\nparameters: {window_width_m: [1]}\n", 1, "penumbra-study",
       "penumbra-study: 1"},
      {"penumbra-study: 1\nparameters: {window_width_m: [1]}\n", 1, "scene", "missing key 'scene'"},
      {"penumbra-study: 1\nscene: ../data/none.yaml\nparameters: {window_width_m: [1]}\n", 0, "",
       "cannot read the scene file"},
  };
  for (const Case& c : cases) {
    const SceneError e = studyError(c.text);
    EXPECT_EQ(e.line(), c.line) << e.what();
    EXPECT_EQ(e.key(), c.key) << e.what();
    expectContains(e.what(), c.words);
  }
}

// ---------------------------------------------------------------- cases and shards

TEST(StudyCases, GridVariesTheFirstParameterSlowest) {
  const std::vector<StudyCase> cases = studyCases(
      parsed(study("  panel_spacing_m: [1.5, 3]\n  panel_flux_lm: [3000, 3400, 4000]\n")));
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(cases[0].id, "case-001");
  EXPECT_EQ(cases[5].id, "case-006");
  EXPECT_EQ(cases[1].values, (ParameterValues{{"panel_spacing_m", 1.5}, {"panel_flux_lm", 3400}}));
  EXPECT_EQ(cases[3].values, (ParameterValues{{"panel_spacing_m", 3}, {"panel_flux_lm", 3000}}));
}

TEST(StudyCases, ZipTakesTheIthValuesTogether) {
  const std::string parameters = "  panel_spacing_m: [1.5, 3]\n  panel_flux_lm: [3000, 4000]\n";
  const std::vector<StudyCase> cases = studyCases(parsed(study(parameters, "combination: zip\n")));
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[1].values, (ParameterValues{{"panel_spacing_m", 3}, {"panel_flux_lm", 4000}}));

  const Study mismatch =
      parsed(study("  panel_spacing_m: [1.5, 3]\n  panel_flux_lm: [3000]\n", "combination: zip\n"));
  try {
    studyCases(mismatch);
    ADD_FAILURE() << "zip of 2 and 1 values";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 6);
    EXPECT_EQ(e.key(), "combination");
    expectContains(e.what(), "panel_spacing_m has 2 and panel_flux_lm has 1");
  }
}

TEST(StudyCases, IdsAreWideEnoughForEveryCase) {
  const std::vector<StudyCase> cases =
      studyCases(parsed(study("  floor_reflectance: {linspace: {from: 0, to: 1, count: 1001}}\n")));
  EXPECT_EQ(cases.front().id, "case-0001");
  EXPECT_EQ(cases.back().id, "case-1001");
}

TEST(Shards, EveryNthCase) {
  const Shard shard = parseShard("2/3");
  EXPECT_EQ(shard.index, 2);
  EXPECT_EQ(shard.count, 3);
  EXPECT_FALSE(shard.contains(0));
  EXPECT_TRUE(shard.contains(1));
  EXPECT_TRUE(shard.contains(4));
  for (const char* bad : {"0/3", "4/3", "1/0", "2", "a/b", "1/2/3", "-1/2"}) {
    EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
  }
}

// ---------------------------------------------------------------- plans and fingerprints

TEST(StudyPlan, ACaseWithAnInvalidSceneNamesItsValues) {
  const Study s = parsed(study("  window_width_m: [2, 7]\n"));
  try {
    planStudy(s, "kernel", {});
    ADD_FAILURE() << "a 7 m window in a 6 m wall";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), kStudyFile);
    EXPECT_EQ(e.line(), 3);
    expectContains(e.what(), "case-002 (window_width_m = 7) makes an invalid scene: ");
    expectContains(e.what(), "office.yaml:32: room.openings[0]: opening 'window' does not fit");
  }
}

TEST(StudyPlan, AnUnknownGrid) {
  const Study s = parsed(study("  window_width_m: [2]\n", "grids: [work-plane, desk]\n"));
  try {
    planStudy(s, "kernel", {});
    ADD_FAILURE() << "no grid desk";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.key(), "grids");
    expectContains(e.what(), "'desk' is not a grid of");
    expectContains(e.what(), "it has: work-plane, desk-1-top, sensors");
  }
}

TEST(StudyPlan, FingerprintsFollowWhatTheResultsDependOn) {
  const Study s = parsed(study("  window_width_m: [1.5, 2]\n", "grids: [work-plane]\n"));
  const StudyPlan plan = planStudy(s, "kernel", {});
  ASSERT_EQ(plan.layout.cases.size(), 2u);
  EXPECT_EQ(plan.layout.grids, std::vector<std::string>{"work-plane"});
  const std::string& first = plan.layout.cases[0].fingerprint;
  EXPECT_EQ(first.size(), 16u);
  EXPECT_NE(first, plan.layout.cases[1].fingerprint);
  EXPECT_EQ(planStudy(s, "kernel", {}).layout.cases[0].fingerprint, first);
  EXPECT_NE(planStudy(s, "reference n=64", {}).layout.cases[0].fingerprint, first);
  EXPECT_NE(planStudy(s, "kernel", {"plots"}).layout.cases[0].fingerprint, first);
  EXPECT_NE(planStudy(s, "kernel", {"renders"}).layout.cases[0].fingerprint,
            planStudy(s, "kernel", {"plots"}).layout.cases[0].fingerprint);

  // Formatting and comments do not count; a value does.
  const std::string scene = "penumbra: 1\nparameters: {w: 1}\nroom: {size: [\"${w + 3}\", 3, 3]}\n";
  const CaseOutputs outputs{{}, "kernel", {}};
  const std::string reference = caseFingerprint(parseScene(scene, "a.yaml"), outputs);
  EXPECT_EQ(caseFingerprint(parseScene("# a room\n" + scene, "b.yaml"), outputs), reference);
  EXPECT_NE(caseFingerprint(parseScene(scene, "a.yaml", {{"w", 2}}), outputs), reference);
}

// ---------------------------------------------------------------- tables and charts

StudyLayout twoByThree(const std::vector<std::string>& grids) {
  StudyLayout layout;
  layout.parameters = {"a", "b"};
  layout.grids = grids;
  layout.metrics = {StudyMetric::Eavg, StudyMetric::U0};
  for (int i = 0; i < 6; ++i) {
    layout.cases.push_back(
        {fmt::format("case-{:03}", i + 1), {{"a", 1.0 + i / 3}, {"b", 10.0 * (i % 3)}}, "f"});
  }
  return layout;
}

std::vector<CaseRecord> recordsOf(const StudyLayout& layout) {
  std::vector<CaseRecord> records;
  for (const PlannedCase& c : layout.cases) {
    CaseRecord r{c.id, c.fingerprint, c.values, {}, {}, false, std::nullopt};
    for (const std::string& grid : layout.grids) {
      GridMetrics m;
      m.eAvg = 100.0 * c.values[0].value + c.values[1].value + 0.1;
      m.u0 = c.values[1].value == 0.0 ? std::numeric_limits<double>::quiet_NaN() : 0.5;
      r.grids.push_back({{m, {}, {}}, grid});
    }
    records.push_back(r);
  }
  return records;
}

TEST(SweepTables, OneRowPerCaseWithUnitsInTheHeader) {
  const StudyLayout layout = twoByThree({"work-plane"});
  std::vector<CaseRecord> records = recordsOf(layout);
  records[1].images = {"work-plane-heatmap.png"};
  const std::string results = csvText(resultsTable(layout, records));
  const std::vector<std::string> expected{
      "case_id,a,b,Eavg_lx,U0,work-plane-heatmap_png",
      "case-001,1,0,100.1,,",
      "case-002,1,10,110.1,0.5,cases/case-002/work-plane-heatmap.png",
  };
  EXPECT_EQ(results.rfind(expected[0] + "\n", 0), 0u) << results;
  for (const std::string& line : expected) expectContains(results, line + "\n");
  EXPECT_EQ(std::count(results.begin(), results.end(), '\n'), 7);
  const std::string explorer = csvText(designExplorerTable(layout, records));
  EXPECT_EQ(explorer.substr(0, explorer.find('\n')),
            "in:a,in:b,out:Eavg_lx,out:U0,img:work-plane-heatmap_png");
}

TEST(SweepTables, SeveralGridsNameTheirColumns) {
  const StudyLayout layout = twoByThree({"work-plane", "desk, top"});
  const std::string results = csvText(resultsTable(layout, recordsOf(layout)));
  EXPECT_EQ(results.substr(0, results.find('\n')),
            "case_id,a,b,Eavg_lx@work-plane,U0@work-plane,\"Eavg_lx@desk, top\",\"U0@desk, top\"");
}

// The unit comes from the name's last part (docs/sweeps.md): known units only, never guessed.
TEST(SweepCharts, ParametersAreLabelledWithTheUnitTheirNameCarries) {
  EXPECT_EQ(parameterLabel("window_width_m"), "window width [m]");
  EXPECT_EQ(parameterLabel("panel_flux_lm"), "panel flux [lm]");
  EXPECT_EQ(parameterLabel("sky_luminance_cdm2"), "sky luminance [cd/m²]");
  EXPECT_EQ(parameterLabel("tilt_deg"), "tilt [°]");
  EXPECT_EQ(parameterUnit("window_width_m"), "m");
  // No unit suffix: unitless (a reflectance), or a last part that only looks like one.
  EXPECT_EQ(parameterLabel("floor_reflectance"), "floor reflectance");
  EXPECT_EQ(parameterUnit("floor_reflectance"), "");
  EXPECT_EQ(parameterLabel("panel_count_x"), "panel count x");
  EXPECT_EQ(parameterLabel("m"), "m");
  EXPECT_EQ(parameterUnit("_m"), "");
  EXPECT_EQ(parameterLabel("a"), "a");
}

TEST(SweepCharts, TheAxisOfAParameterReadsAsWordsAndUnit) {
  StudyLayout layout = twoByThree({"work-plane"});
  layout.parameters = {"window_width_m", "b"};
  std::vector<CaseRecord> records = recordsOf(twoByThree({"work-plane"}));
  for (CaseRecord& r : records) r.values[0].name = "window_width_m";
  const std::vector<ChartFile> charts = studyCharts(layout, records);
  ASSERT_FALSE(charts.empty());
  EXPECT_EQ(charts[0].fileName, "Eavg_lx-vs-window_width_m.png");  // files keep the column name
  EXPECT_EQ(charts[0].chart.xLabel, "window width [m]");
  EXPECT_EQ(charts[0].chart.title, "Eavg [lx] vs window width [m]");
}

TEST(SweepCharts, GridCombinationsGiveOneSeriesPerOtherValue) {
  const StudyLayout layout = twoByThree({"work-plane"});
  const std::vector<ChartFile> charts = studyCharts(layout, recordsOf(layout));
  ASSERT_EQ(charts.size(), 4u);  // {Eavg, U0} × {a, b}
  EXPECT_EQ(charts[0].fileName, "Eavg_lx-vs-a.png");
  EXPECT_EQ(charts[0].chart.title, "Eavg [lx] vs a");
  EXPECT_EQ(charts[0].chart.xLabel, "a");
  EXPECT_EQ(charts[0].chart.yLabel, "Eavg [lx]");
  ASSERT_EQ(charts[0].chart.series.size(), 3u);
  EXPECT_EQ(charts[0].chart.series[1].name, "b = 10");
  EXPECT_EQ(charts[0].chart.series[1].x, (std::vector<double>{1, 2}));
  EXPECT_EQ(charts[0].chart.series[1].y, (std::vector<double>{110.1, 210.1}));
  EXPECT_EQ(charts[1].fileName, "Eavg_lx-vs-b.png");
  EXPECT_EQ(charts[1].chart.series.size(), 2u);
  // U0 is undefined where b = 0: those points are left out.
  EXPECT_EQ(charts[3].chart.series[0].x, (std::vector<double>{10, 20}));
}

TEST(SweepCharts, AMetricUndefinedInEveryCaseHasNoChart) {
  // A point list's U0 is undefined in every case: Eavg is charted against a and b, U0 not at all.
  const StudyLayout layout = twoByThree({"work-plane"});
  std::vector<CaseRecord> records = recordsOf(layout);
  for (CaseRecord& r : records) r.grids[0].metrics.u0 = std::numeric_limits<double>::quiet_NaN();
  const std::vector<ChartFile> charts = studyCharts(layout, records);
  ASSERT_EQ(charts.size(), 2u);
  EXPECT_EQ(charts[0].fileName, "Eavg_lx-vs-a.png");
  EXPECT_EQ(charts[1].fileName, "Eavg_lx-vs-b.png");
}

TEST(SweepCharts, ZipGivesOneSeriesAndFixedParametersNone) {
  StudyLayout layout = twoByThree({"work-plane"});
  layout.combination = Combination::Zip;
  layout.parameters.push_back("c");
  for (PlannedCase& c : layout.cases) c.values.push_back({"c", 5});
  const std::vector<ChartFile> charts = studyCharts(layout, recordsOf(layout));
  ASSERT_EQ(charts.size(), 4u);  // c never varies
  EXPECT_EQ(charts[0].chart.series.size(), 1u);
  EXPECT_EQ(charts[0].chart.series[0].x.size(), 6u);
  EXPECT_TRUE(
      std::is_sorted(charts[0].chart.series[0].x.begin(), charts[0].chart.series[0].x.end()));
}

TEST(SweepFolders, LayoutsAndRecordsReadBackAsWritten) {
  StudyLayout layout = twoByThree({"work-plane"});
  layout.studyFile = "studies/x.yaml";
  const StudyLayout back =
      layoutFromJson(nlohmann::ordered_json::parse(layoutJson(layout).dump()), "x");
  EXPECT_TRUE(back.sameStudy(layout));
  EXPECT_EQ(back.studyFile, "studies/x.yaml");
  EXPECT_EQ(back.cases[4].values, layout.cases[4].values);
  StudyLayout other = layout;
  other.cases[2].fingerprint = "g";
  EXPECT_FALSE(other.sameStudy(layout));

  CaseRecord record = recordsOf(layout)[0];
  record.values = {{"b", 0.1 + 0.2}, {"a", 1}};  // order kept, every digit kept
  record.images = {"x.png"};
  record.grids[0].sun = CaseSun{3452.9814, 22397.717, 100.0 / 3.0};  // every digit kept
  const CaseRecord again =
      caseRecordFromJson(nlohmann::ordered_json::parse(caseJson(record).dump()), "c");
  EXPECT_EQ(again.values, record.values);
  EXPECT_EQ(again.grids[0].metrics.eAvg, record.grids[0].metrics.eAvg);
  EXPECT_TRUE(std::isnan(again.grids[0].metrics.u0));
  EXPECT_EQ(again.grids[0].sun.eAvg, record.grids[0].sun.eAvg);
  EXPECT_EQ(again.grids[0].sun.eMax, record.grids[0].sun.eMax);
  EXPECT_EQ(again.grids[0].sun.sunlitShare, record.grids[0].sun.sunlitShare);
  EXPECT_TRUE(std::isnan(again.grids[0].daylight.mean));  // no sky: null, read back as NaN
  EXPECT_EQ(again.images, record.images);
  EXPECT_THROW(caseRecordFromJson(nlohmann::ordered_json::parse("{\"id\": 3}"), "c"),
               std::runtime_error);
}

}  // namespace
}  // namespace penumbra
