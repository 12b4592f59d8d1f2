// `penumbra plot` and `penumbra grid --plot` as a user runs them (under xvfb-run): the files,
// the exit codes, and nothing written when anything fails.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "test_files.hpp"
#include "viz_test_support.hpp"

namespace {

namespace fs = std::filesystem;
using penumbra::testing::readText;
using penumbra::testing::TempDir;

struct Outcome {
  int status = -1;
  std::string err;
};

// `environment` is prepended to the command (e.g. "env -u DISPLAY").
Outcome penumbra(const fs::path& dir, const std::string& arguments,
                 const std::string& environment = "") {
  const fs::path err = dir / "stderr.txt";
  const std::string command = "cd '" + dir.string() + "' && " + environment +
                              " '" PENUMBRA_BINARY "' " + arguments + " > /dev/null 2> '" +
                              err.string() + "' < /dev/null";
  const int raw = std::system(command.c_str());
  Outcome r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readText(err)};
  fs::remove(err);
  return r;
}

std::set<std::string> filesIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  return names;
}

// The room of viz_test_support with a work plane (plotted) and two sensors (a point list).
std::string sceneWithGrids(const std::string& planeName = "work-plane") {
  return std::string(penumbra::testing::kRoomScene) + "grids:\n  - {name: " + planeName +
         ", height: 0.8, spacing: 0.5}\n  - {name: sensors, points: [[1, 1, 0.8, 0, 0, 1], "
         "[2, 2, 0.8, 0, 0, 1]]}\n";
}

TEST(PlotCli, GridWithPlotWritesEveryPicture) {
  TempDir dir("viz-cli");
  std::ofstream(dir.path() / "room.yaml") << sceneWithGrids();
  const Outcome run = penumbra(dir.path(), "grid room.yaml -o out --plot --width 800 -q");
  ASSERT_EQ(run.status, 0) << run.err;
  const std::set<std::string> expected{
      "work-plane.csv", "work-plane.res", "work-plane.pts", "sensors.csv",    "sensors.res",
      "sensors.pts",    "summary.json",   "work-plane.png", "work-plane.vti", "sensors.vtp",
      "surfaces.vtp",   "surfaces.png",   "plots.json"};
  EXPECT_EQ(filesIn(dir.path() / "out"), expected);
  const penumbra::testing::Png png(dir.path() / "out" / "work-plane.png");
  EXPECT_EQ(png.width(), 800);
  const auto summary = nlohmann::json::parse(readText(dir.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["grids"][0]["kind"], "work-plane");
  EXPECT_EQ(summary["scene_absolute"], (dir.path() / "room.yaml").string());
}

TEST(PlotCli, PlotRedrawsAFinishedRunFromAnotherDirectory) {
  TempDir dir("viz-cli");
  std::ofstream(dir.path() / "room.yaml") << sceneWithGrids();
  ASSERT_EQ(penumbra(dir.path(), "grid room.yaml -o out -q").status, 0);
  fs::create_directories(dir.path() / "elsewhere");
  const Outcome run = penumbra(dir.path() / "elsewhere",
                               "plot ../out --range 100:1000 --log --isolux 100,300 --palette "
                               "falsecolor --width 600 -q");
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "surfaces.png"));
  EXPECT_EQ(penumbra::testing::Png(dir.path() / "out" / "surfaces.png").width(), 600);
}

// The room with the cabinet's x as a parameter (default 5.5 m), under the same file name in
// `dir`, so that two runs differ in nothing but the geometry they were given.
void writeParameterisedRoom(const fs::path& dir, double cabinetDefault) {
  fs::create_directories(dir);
  std::string scene = sceneWithGrids();
  const std::string box = "box: {min: [5.5, 2.8, 0.0], max: [6.0, 3.9, 1.2]}";
  scene.replace(scene.find(box), box.size(),
                "box: {min: [\"${cabinet_x_m}\", 2.8, 0.0], max: [\"${cabinet_x_m + 0.5}\", 3.9, "
                "1.2]}");
  std::ofstream(dir / "room.yaml") << "parameters: {cabinet_x_m: " << cabinetDefault << "}\n"
                                   << scene;
}

// `grid --set ... --plot` draws the geometry it computed, whatever the scene's default: two
// scenes that differ only in the default, run with the same --set, give the same pictures (the
// plot once reloaded the scene with its defaults and drew the cabinet where they put it).
TEST(PlotCli, PlotsOfASetParameterShowTheGeometryThatWasComputed) {
  TempDir dir("viz-cli");
  writeParameterisedRoom(dir.path() / "a", 5.5);
  writeParameterisedRoom(dir.path() / "b", 3.0);
  for (const char* run : {"a", "b"}) {
    const Outcome set = penumbra(dir.path() / run,
                                 "grid room.yaml --set cabinet_x_m=1 -o out --plot --width 600 -q");
    ASSERT_EQ(set.status, 0) << set.err;
  }
  for (const char* file : {"surfaces.vtp", "surfaces.png", "work-plane.png", "work-plane.csv"}) {
    EXPECT_EQ(readText(dir.path() / "a" / "out" / file), readText(dir.path() / "b" / "out" / file))
        << file;
  }
  // The redraw by `penumbra plot` alone, too.
  ASSERT_EQ(penumbra(dir.path() / "a", "plot out --width 600 -q").status, 0);
  EXPECT_EQ(readText(dir.path() / "a" / "out" / "surfaces.png"),
            readText(dir.path() / "b" / "out" / "surfaces.png"));
}

// The parameterised room (room.yaml) and a study (study.yaml) of its work plane over the cabinet
// positions `values`, with `more` study keys.
void writeCabinetStudy(const fs::path& dir, const std::string& values, const std::string& more) {
  writeParameterisedRoom(dir, 5.5);
  std::ofstream(dir / "study.yaml") << "penumbra-study: 1\nscene: room.yaml\nparameters:\n"
                                       "  cabinet_x_m: "
                                    << values << "\ngrids: [work-plane]\n"
                                    << more;
}

// A sweep with `plots: true` draws each case's plots as `grid --set ... --plot` draws that case
// alone: the same pictures and ParaView files, listed as the case's images.
TEST(PlotCli, ASweepDrawsEachCaseAsGridPlotDrawsIt) {
  TempDir dir("viz-cli");
  writeCabinetStudy(dir.path(), "[1, 3]", "plots: true\ncharts: false\n");
  const Outcome sweep = penumbra(dir.path(), "sweep study.yaml -o sweep -q");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const Outcome alone = penumbra(
      dir.path(), "grid room.yaml --set cabinet_x_m=3 --grid work-plane -o alone --plot -q");
  ASSERT_EQ(alone.status, 0) << alone.err;
  const fs::path lastCase = dir.path() / "sweep" / "cases" / "case-002";
  for (const char* file : {"work-plane.png", "work-plane.vti", "surfaces.png", "surfaces.vtp"}) {
    EXPECT_EQ(readText(lastCase / file), readText(dir.path() / "alone" / file)) << file;
  }
  const auto record = nlohmann::json::parse(readText(lastCase / "case.json"));
  EXPECT_EQ(record["images"], nlohmann::json({"work-plane.png", "surfaces.png"}));
  const std::string table = readText(dir.path() / "sweep" / "results.csv");
  EXPECT_NE(table.find(",work-plane_png,surfaces_png\n"), std::string::npos) << table;
  EXPECT_NE(table.find(",cases/case-001/work-plane.png,cases/case-001/surfaces.png\n"),
            std::string::npos)
      << table;

  // Without a display the cases are computed without plots, and the run still succeeds.
  const Outcome blind = penumbra(dir.path(), "sweep study.yaml -o blind -q", "env -u DISPLAY");
  ASSERT_EQ(blind.status, 0) << blind.err;
  EXPECT_TRUE(fs::exists(dir.path() / "blind" / "cases" / "case-002" / "case.json"));
  EXPECT_FALSE(fs::exists(dir.path() / "blind" / "cases" / "case-002" / "work-plane.png"));
}

// A display that goes away while the charts are drawn (VTK aborts the process drawing them): the
// sweep keeps every result, names the charts it could not draw and fails; the rerun draws them,
// and only the charts that are missing.
TEST(PlotCli, ChartsThatAbortCostNoResultsAndARerunDrawsThem) {
  TempDir dir("viz-cli");
  writeCabinetStudy(dir.path(), "[1, 2, 3]", "");
  const fs::path charts = dir.path() / "out" / "charts";
  const Outcome broken = penumbra(dir.path(), "sweep study.yaml -o out -q", "env DISPLAY=:9999");
  EXPECT_EQ(broken.status, 1) << broken.err;
  EXPECT_NE(broken.err.find("5 charts not drawn"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("Eavg_lx-vs-cabinet_x_m.png"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("killed by signal 6"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("the results are written"), std::string::npos) << broken.err;
  EXPECT_EQ(penumbra::testing::lines(readText(dir.path() / "out" / "results.csv")).size(), 4u);
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "cases" / "case-003" / "case.json"));
  EXPECT_FALSE(fs::exists(charts / "Eavg_lx-vs-cabinet_x_m.png"));

  const Outcome rerun = penumbra(dir.path(), "sweep study.yaml -o out -q");
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_EQ(rerun.err.find("not drawn"), std::string::npos) << rerun.err;
  std::set<std::string> pngs;
  for (const std::string& name : filesIn(charts)) {
    if (name.ends_with(".png")) pngs.insert(name);
  }
  EXPECT_EQ(pngs.size(), 5u);  // Eavg, Emin, Emax, U0, Ud against cabinet_x_m

  // One chart lost: the rerun draws it and leaves the others as they are.
  const fs::path kept = charts / "Eavg_lx-vs-cabinet_x_m.png";
  const fs::path lost = charts / "U0-vs-cabinet_x_m.png";
  ASSERT_TRUE(fs::exists(lost));
  const auto keptTime = fs::last_write_time(kept);
  fs::remove(lost);
  ASSERT_EQ(penumbra(dir.path(), "sweep study.yaml -o out -q").status, 0);
  EXPECT_TRUE(fs::exists(lost));
  EXPECT_EQ(fs::last_write_time(kept), keptTime);
}

// `grid --plot` with a display that goes away (VTK aborts the process drawing): the results and
// the ParaView files are written, the pictures named with the signal, the status 1; `penumbra
// plot` then draws them, and afterwards only what is missing.
TEST(PlotCli, PicturesThatAbortCostNoResultsAndARerunDrawsOnlyThem) {
  TempDir dir("viz-cli");
  std::ofstream(dir.path() / "room.yaml") << sceneWithGrids();
  const fs::path out = dir.path() / "out";
  const Outcome broken =
      penumbra(dir.path(), "grid room.yaml -o out --plot --width 600 --surface-spacing 0.5 -q",
               "env DISPLAY=:9999");
  EXPECT_EQ(broken.status, 1) << broken.err;
  EXPECT_NE(broken.err.find("2 pictures not drawn (work-plane.png, surfaces.png)"),
            std::string::npos)
      << broken.err;
  EXPECT_NE(broken.err.find("killed by signal 6"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("the results and the ParaView files are written"), std::string::npos)
      << broken.err;
  for (const char* file : {"summary.json", "work-plane.csv", "work-plane.vti", "surfaces.vtp"}) {
    EXPECT_TRUE(fs::exists(out / file)) << file;
  }
  EXPECT_FALSE(fs::exists(out / "work-plane.png"));

  const Outcome rerun = penumbra(dir.path(), "plot out --width 600 --surface-spacing 0.5 -q");
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_EQ(penumbra::testing::Png(out / "work-plane.png").width(), 600);
  EXPECT_EQ(penumbra::testing::Png(out / "surfaces.png").width(), 600);

  // One picture lost: `plot` draws it and leaves the other; a display gone again costs it alone.
  const auto keptTime = fs::last_write_time(out / "work-plane.png");
  fs::remove(out / "surfaces.png");
  const Outcome lost =
      penumbra(dir.path(), "plot out --width 600 --surface-spacing 0.5 -q", "env DISPLAY=:9999");
  EXPECT_EQ(lost.status, 1);
  EXPECT_NE(lost.err.find("1 picture not drawn (surfaces.png)"), std::string::npos) << lost.err;
  ASSERT_EQ(penumbra(dir.path(), "plot out --width 600 --surface-spacing 0.5 -q").status, 0);
  EXPECT_TRUE(fs::exists(out / "surfaces.png"));
  EXPECT_EQ(fs::last_write_time(out / "work-plane.png"), keptTime);
}

// The same for a sweep's per-case plots: every case is finished with its results, the pictures
// not drawn are named, and the rerun draws them without computing a case again.
TEST(PlotCli, CasePicturesThatAbortCostNoResults) {
  TempDir dir("viz-cli");
  writeCabinetStudy(dir.path(), "[3]", "plots: true\ncharts: false\n");
  const Outcome broken = penumbra(dir.path(), "sweep study.yaml -o out -q", "env DISPLAY=:9999");
  EXPECT_EQ(broken.status, 1) << broken.err;
  EXPECT_NE(broken.err.find("2 case pictures not drawn"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("cases/case-001/surfaces.png"), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("killed by signal 6"), std::string::npos) << broken.err;
  const fs::path theCase = dir.path() / "out" / "cases" / "case-001";
  EXPECT_EQ(penumbra::testing::lines(readText(dir.path() / "out" / "results.csv")).size(), 2u);
  EXPECT_TRUE(fs::exists(theCase / "work-plane.vti"));
  EXPECT_FALSE(fs::exists(theCase / "work-plane.png"));
  const auto computed = fs::last_write_time(theCase / "work-plane.csv");

  const Outcome rerun = penumbra(dir.path(), "sweep study.yaml -o out -q");
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_TRUE(fs::exists(theCase / "work-plane.png"));
  EXPECT_TRUE(fs::exists(theCase / "surfaces.png"));
  EXPECT_EQ(fs::last_write_time(theCase / "work-plane.csv"), computed);  // not computed again
}

TEST(PlotCli, WithoutADisplayItSaysHowAndWritesNothing) {
  TempDir dir("viz-cli");
  std::ofstream(dir.path() / "room.yaml") << sceneWithGrids();
  ASSERT_EQ(penumbra(dir.path(), "grid room.yaml -o out -q").status, 0);
  const auto before = filesIn(dir.path() / "out");
  const Outcome run = penumbra(dir.path(), "plot out", "env -u DISPLAY");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.err.find("xvfb-run"), std::string::npos) << run.err;
  EXPECT_EQ(filesIn(dir.path() / "out"), before);
}

TEST(PlotCli, ABrokenGridFileLeavesNoPictureBehind) {
  TempDir dir("viz-cli");
  std::ofstream(dir.path() / "room.yaml") << sceneWithGrids();
  ASSERT_EQ(penumbra(dir.path(), "grid room.yaml -o out -q").status, 0);
  // The second grid's CSV is cut short: the first grid would plot, but nothing may appear.
  std::ofstream(dir.path() / "out" / "sensors.csv") << "x_m,y_m,z_m,nx,ny,nz,E_lx,inside\n1,1\n";
  const auto before = filesIn(dir.path() / "out");
  const Outcome run = penumbra(dir.path(), "plot out");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.err.find("sensors.csv:2"), std::string::npos) << run.err;
  EXPECT_EQ(filesIn(dir.path() / "out"), before);
}

TEST(PlotCli, AGridNamedSurfacesIsRefused) {
  TempDir dir("viz-cli");
  std::ofstream(dir.path() / "room.yaml") << sceneWithGrids("surfaces");
  const Outcome run = penumbra(dir.path(), "grid room.yaml -o out --plot -q");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.err.find("surfaces.png"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "surfaces.png"));
}

TEST(PlotCli, UsageErrors) {
  TempDir dir("viz-cli");
  EXPECT_EQ(penumbra(dir.path(), "plot").status, 1);                      // no folder
  EXPECT_EQ(penumbra(dir.path(), "plot missing-folder").status, 1);       // not there
  EXPECT_EQ(penumbra(dir.path(), "plot . --range 5:1").status, 1);        // max below min
  EXPECT_EQ(penumbra(dir.path(), "plot . --isolux 100,abc").status, 1);   // not a number
  EXPECT_EQ(penumbra(dir.path(), "plot . --palette jet").status, 1);      // unknown palette
  EXPECT_EQ(penumbra(dir.path(), "grid x.yaml -o out --log").status, 1);  // needs --plot
  const Outcome noRun = penumbra(dir.path(), "plot .");                   // no summary.json
  EXPECT_EQ(noRun.status, 1);
  EXPECT_NE(noRun.err.find("summary.json"), std::string::npos) << noRun.err;
}

TEST(PlotCli, HelpNamesTheOutputsAndUnits) {
  TempDir dir("viz-cli");
  const std::string command = "'" PENUMBRA_BINARY "' plot --help";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string help;
  char buffer[4096];
  while (std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) help.append(buffer, n);
  EXPECT_EQ(pclose(pipe), 0);
  for (const char* words :
       {"<grid>.png", "<grid>.vti", "surfaces.vtp", "surfaces.png", "lx", "--range", "--log",
        "--isolux", "--palette", "--width", "--surface-spacing", "xvfb-run"}) {
    EXPECT_NE(help.find(words), std::string::npos) << words;
  }
}

}  // namespace
