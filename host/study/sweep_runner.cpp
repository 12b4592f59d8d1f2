#include "study/sweep_runner.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "glare/observer_ratings.hpp"
#include "grid/scene_grids.hpp"
#include "output/result_files.hpp"
#include "output/staged_directory.hpp"
#include "study/results_table.hpp"
#include "study/study_charts.hpp"
#include "study/study_exposure.hpp"
#include "study/study_plan.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
fs::path caseFolder(const fs::path& out, const std::string& id) {
  return out / kCasesFolder / id;
}

void writeLayout(const fs::path& out, const StudyLayout& layout) {
  writeTextFiles(out, {{kStudyJson, layoutJson(layout).dump(2) + "\n"}});
}

// The tables (and, once every case is finished, the charts) of the finished cases in `out`.
TableSummary writeStudyTables(const fs::path& out, const StudyLayout& layout,
                              const ChartWriter& chartWriter) {
  TableSummary summary;
  std::vector<CaseRecord> records;
  for (const PlannedCase& c : layout.cases) {
    if (std::optional<CaseRecord> record = readFinishedCase(out, c)) {
      records.push_back(std::move(*record));
    } else {
      summary.missing.push_back(c.id);
    }
  }
  summary.rows = records.size();
  writeTextFiles(out, {{"results.csv", csvText(resultsTable(layout, records))},
                       {"design-explorer.csv", csvText(designExplorerTable(layout, records))}});
  if (!layout.charts) {
    summary.chartsNote = "the study says charts: false";
  } else if (!chartWriter) {
    summary.chartsNote = "this penumbra was built without charts (viz/)";
  } else if (!chartWriter.unavailable.empty()) {
    summary.chartsNote = chartWriter.unavailable;
  } else if (!summary.missing.empty()) {
    summary.chartsNote =
        fmt::format("charts are drawn once all {} cases are finished", layout.cases.size());
  } else {
    const std::vector<ChartFile> charts = studyCharts(layout, records);
    if (charts.empty()) {
      summary.chartsNote = "no parameter takes more than one value";
    } else {
      // The tables are written first; charts are a view of them, and a rerun draws what is missing.
      ChartsWritten written = writeCharts(out / "charts", charts, chartWriter);
      summary.charts = written.drawn + written.kept;
      summary.chartsMissing = std::move(written.missing);
      summary.chartsError = std::move(written.why);
      if (summary.charts == 0) summary.chartsNote = "they could not be drawn";
    }
  }
  return summary;
}

// The cases this run computes: the shard's cases that are not finished in `out`.
std::vector<const PlannedCase*> casesToCompute(const StudyLayout& layout, const Shard& shard,
                                               const fs::path& out, SweepSummary& summary) {
  std::vector<const PlannedCase*> pending;
  for (std::size_t i = 0; i < layout.cases.size(); ++i) {
    if (!shard.contains(i)) continue;
    if (readFinishedCase(out, layout.cases[i])) {
      ++summary.skipped;
    } else {
      pending.push_back(&layout.cases[i]);
    }
  }
  return pending;
}

// The writers of the outputs the study asks for that can work here; a note for each other one.
std::vector<CaseOutputWriter*> chooseCaseOutputs(const Study& study, const SweepSettings& settings,
                                                 std::vector<std::string>& notes) {
  std::vector<CaseOutputWriter*> chosen;
  for (const std::string& name : requestedCaseOutputs(study)) {
    const auto it = std::find_if(
        settings.caseOutputs.begin(), settings.caseOutputs.end(),
        [&](const std::shared_ptr<CaseOutputWriter>& w) { return w && w->name() == name; });
    if (it == settings.caseOutputs.end()) {
      notes.push_back(fmt::format("{}: none (this penumbra cannot write them)", name));
    } else if (const std::string why = (*it)->unavailable(); !why.empty()) {
      notes.push_back(fmt::format("{}: none ({})", name, why));
    } else {
      chosen.push_back(it->get());
    }
  }
  return chosen;
}

std::vector<std::string> namesOf(const std::vector<CaseOutputWriter*>& writers) {
  std::vector<std::string> names;
  for (const CaseOutputWriter* w : writers) names.push_back(w->name());
  return names;
}

// The pictures of the finished case `c` the writers have not drawn yet (case_output.hpp).
void drawCasePictures(const fs::path& out, const PlannedCase& c, const Scene& scene,
                      const std::vector<CaseOutputWriter*>& outputs, SweepSummary& summary) {
  for (CaseOutputWriter* writer : outputs) {
    const PicturesWritten drawn = writer->drawPictures(scene, caseFolder(out, c.id));
    for (const std::string& name : drawn.missing) {
      summary.picturesMissing.push_back(fmt::format("{}/{}/{}", kCasesFolder, c.id, name));
    }
    if (summary.picturesError.empty()) summary.picturesError = drawn.why;
  }
}

void checkResume(const SweepSettings& settings, const StudyLayout& layout) {
  const std::optional<StudyLayout> previous = readLayout(settings.output);
  if (!settings.resume) return;
  if (!previous) {
    throw std::invalid_argument(
        fmt::format("--resume: {} holds no sweep (no {}); start one without --resume",
                    settings.output.string(), kStudyJson));
  }
  if (!previous->sameStudy(layout)) {
    throw std::invalid_argument(fmt::format(
        "--resume: {} holds a sweep of {}, which differs from this one (other values, a changed "
        "scene, grids or estimator); run without --resume to recompute the cases that changed",
        settings.output.string(), previous->studyFile));
  }
}

}  // namespace

SweepSummary runSweep(const Study& study, const SweepSettings& settings, SweepObserver& observer) {
  SweepSummary summary;
  // Outputs that cannot be written here are left out before planning: the fingerprints then say
  // the cases were computed without them, and a later run that can write them redoes the cases.
  const std::vector<CaseOutputWriter*> outputs =
      chooseCaseOutputs(study, settings, summary.outputNotes);
  const StudyPlan plan =
      planStudy(study, estimatorIdentity(settings.estimator), namesOf(outputs),
                settings.estimator.interreflection && !settings.estimator.reference);
  const StudyLayout& layout = plan.layout;
  checkOutputTarget(settings.output);
  checkResume(settings, layout);

  summary.cases = layout.cases.size();
  writeLayout(settings.output, layout);
  const std::vector<const PlannedCase*> pending =
      casesToCompute(layout, settings.shard, settings.output, summary);
  // Pictures an earlier run could not draw (its display went away) are drawn first.
  if (!outputs.empty() && summary.skipped > 0) {
    for (std::size_t i = 0; i < layout.cases.size(); ++i) {
      const PlannedCase& c = layout.cases[i];
      if (!settings.shard.contains(i) ||
          std::find(pending.begin(), pending.end(), &c) != pending.end()) {
        continue;
      }
      drawCasePictures(settings.output, c, loadCaseScene(study, c), outputs, summary);
    }
  }

  std::unique_ptr<Scene> scene;
  std::unique_ptr<Estimator> estimator;
  if (!pending.empty()) {
    scene = std::make_unique<Scene>(loadCaseScene(study, *pending.front()));
    estimator = std::make_unique<Estimator>(settings.estimator, *scene);
    summary.device = estimator->device();
  }
  observer.planned(pending.size(), summary.skipped);
  for (const PlannedCase* c : pending) {
    observer.caseStarted(*c);
    const auto start = Clock::now();
    if (c != pending.front()) {
      // The new scene is uploaded to the device already holding the program; the old one goes.
      auto next = std::make_unique<Scene>(loadCaseScene(study, *c));
      estimator->setScene(*next);
      scene = std::move(next);
    }
    RunReport report = runReport(*scene, study.scene, *estimator, settings.version);
    report.grids = evaluateGrids(*scene, selectGrids(*scene, layout.grids), *estimator);
    report.totalSeconds = secondsSince(start);

    CaseRecord record{c->id, c->fingerprint, c->values, {}, {}, false, std::nullopt};
    const NumberDigits digits = illuminanceDigits(report);
    for (const GridReport& g : report.grids) {
      CaseGridResult grid;
      grid.name = g.name;
      grid.metrics = reportedMetrics(g.metrics, g.kind, digits);
      if (g.daylight) grid.daylight = caseDaylight(*g.daylight);
      if (g.sunMetrics) grid.sun = caseSun(*g.sunMetrics, digits);
      record.grids.push_back(grid);
    }
    if (!scene->observers.empty()) {
      // UGR_max over the observers (docs/glare.md): L_b from the case's interreflection.
      record.rated = true;
      record.ugrMax = highestUgr(rateObservers(*scene, [&](std::span<const SamplePoint> points) {
        return estimator->interreflected(points);
      }));
    }
    const bool stale = fs::exists(caseFolder(settings.output, c->id));
    writeCaseFolder(caseFolder(settings.output, c->id), *scene, report, caseJson(record), outputs);
    drawCasePictures(settings.output, *c, *scene, outputs, summary);
    ++summary.computed;
    if (stale) ++summary.recomputed;
    observer.caseFinished(record, secondsSince(start));
  }
  if (exposedAsOne(layout)) exposeStudyRenders(settings.output, layout);
  summary.table = writeStudyTables(settings.output, layout, settings.charts);
  return summary;
}

TableSummary mergeSweeps(const std::vector<fs::path>& inputs, const fs::path& output,
                         const ChartWriter& charts) {
  if (inputs.empty()) throw std::invalid_argument("merge: name the sweep folders to join");
  std::vector<StudyLayout> layouts;
  for (const fs::path& in : inputs) {
    std::optional<StudyLayout> layout = readLayout(in);
    if (!layout) {
      throw std::invalid_argument(
          fmt::format("{} is not the output folder of `penumbra sweep` (it has no {})", in.string(),
                      kStudyJson));
    }
    if (!layouts.empty() && !layouts.front().sameStudy(*layout)) {
      throw std::invalid_argument(fmt::format(
          "{} and {} hold different sweeps (other values, scenes, grids or estimators); merge "
          "only the shards of one study",
          inputs.front().string(), in.string()));
    }
    layouts.push_back(std::move(*layout));
  }
  const StudyLayout& layout = layouts.front();
  checkOutputTarget(output);
  if (const std::optional<StudyLayout> existing = readLayout(output);
      existing && !existing->sameStudy(layout)) {
    throw std::invalid_argument(
        fmt::format("{} already holds another sweep ({}); merge into a new folder", output.string(),
                    existing->studyFile));
  }
  writeLayout(output, layout);
  const fs::path target = normalizedTarget(output);
  for (const PlannedCase& c : layout.cases) {
    if (readFinishedCase(output, c)) continue;
    for (const fs::path& in : inputs) {
      if (normalizedTarget(in) == target || !readFinishedCase(in, c)) continue;
      copyCaseFolder(caseFolder(in, c.id), caseFolder(output, c.id));
      break;
    }
  }
  // Each shard exposed its own cases as one; the joined study is exposed as one again.
  if (exposedAsOne(layout)) exposeStudyRenders(output, layout);
  return writeStudyTables(output, layout, charts);
}

}  // namespace penumbra
