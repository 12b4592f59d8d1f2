// `penumbra glare SCENE -o DIR` as a user runs it: the files it writes, what it says when UGR is
// undefined, and its exit status for scenes it cannot rate.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "penumbra_process.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::lines;
using penumbra::testing::readText;
using penumbra::testing::Result;
using penumbra::testing::runPenumbra;
using penumbra::testing::TempDir;

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A 4 × 3 × 2.8 m room with grey surfaces, a 0.6 m ceiling panel ahead of a seated eye.
const std::string kRoom = R"(penumbra: 1
materials: {grey: 0.5}
room: {size: [4, 3, 2.8], materials: {floor: grey, ceiling: grey, walls: grey}}
sources:
  - {name: panel, rect: {center: [3.0, 1.5, 2.79], size: [0.6, 0.6], normal: [0, 0, -1]}, luminance: 3000}
)";

// Writes the room with `observers` (YAML) as room.yaml in `dir` and runs `penumbra glare` on it
// into out/ with `options`.
Result runGlare(const TempDir& dir, const std::string& observers, const std::string& options) {
  std::ofstream(dir.path() / "room.yaml") << kRoom << observers;
  return runPenumbra(dir.path(), "glare room.yaml -o out " + options);
}

TEST(GlareCommand, DirectOnlyWritesUndefinedRatingsWithTheReason) {
  TempDir dir("glare-cli");
  const Result r =
      runGlare(dir, "observers:\n  - {name: desk, eye: [0.8, 1.5, 1.2], look: [1, 0, 0]}\n",
               "--direct-only");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "UGR (CIE 117-1995)")) << r.out;
  EXPECT_TRUE(contains(r.out, "L_b [cd/m²]")) << r.out;
  EXPECT_TRUE(contains(r.out, "undef: L_b = 0 (direct light only)")) << r.out;

  const std::vector<std::string> rows = lines(readText(dir.path() / "out/desk.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(rows[0].starts_with("observer,eye_x_m,eye_y_m,eye_z_m,look_x"));
  EXPECT_TRUE(contains(rows[1], "L_b = 0 (direct light only)")) << rows[1];
  const std::vector<std::string> sources = lines(readText(dir.path() / "out/desk-sources.csv"));
  ASSERT_EQ(sources.size(), 2u);  // the panel is rated; only L_b is missing
  EXPECT_TRUE(contains(sources[1], "panel")) << sources[1];

  const nlohmann::json summary = nlohmann::json::parse(readText(dir.path() / "out/summary.json"));
  EXPECT_TRUE(summary["UGR_max"].is_null());
  const nlohmann::json& view = summary["observers"][0]["views"][0];
  EXPECT_TRUE(view["UGR"].is_null());
  EXPECT_EQ(view["L_b_cd_m2"], 0.0);
  EXPECT_EQ(view["sources"][0]["L_cd_m2"], 3000.0);
}

TEST(GlareCommand, InterreflectionGivesTheBackgroundAndTheRating) {
  TempDir dir("glare-cli");
  const Result r =
      runGlare(dir, "observers:\n  - {name: desk, eye: [0.8, 1.5, 1.2]}\n", "--device cpu");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(readText(dir.path() / "out/summary.json"));
  const nlohmann::json& views = summary["observers"][0]["views"];
  ASSERT_EQ(views.size(), 4u);  // +x, +y, −x, −y
  // Along +x the panel is ahead and above: rated, with a lit background. Each output agrees with
  // the formula on its own terms: 10^(UGR/8) = 0.25/L_b · Σ L²ω/p².
  const nlohmann::json& ahead = views[0];
  ASSERT_FALSE(ahead["UGR"].is_null()) << ahead.dump(2);
  const double background = ahead["L_b_cd_m2"];
  EXPECT_GT(background, 0.0);
  EXPECT_NEAR(ahead["E_ind_lx"].get<double>(), std::numbers::pi * background, 1e-9 * background);
  double sum = 0.0;
  for (const nlohmann::json& s : ahead["sources"]) {
    const double l = s["L_cd_m2"], omega = s["omega_sr"], p = s["p_guth"];
    sum += l * l * omega / (p * p);
  }
  EXPECT_NEAR(ahead["UGR"].get<double>(), 8.0 * std::log10(0.25 / background * sum), 1e-9);
  EXPECT_EQ(summary["UGR_max"], ahead["UGR"]);
  // Along −x the panel is behind the eye: counted, not rated, and UGR undefined.
  EXPECT_TRUE(views[2]["UGR"].is_null());
  EXPECT_EQ(views[2]["sources_outside_guth_range"], 1);
}

TEST(GlareCommand, SceneWithoutObserversIsAnErrorAndWritesNothing) {
  TempDir dir("glare-cli");
  const Result r = runGlare(dir, "", "--direct-only");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "has no observers")) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(GlareCommand, EyeInsideASolidIsStatusTwoWithFileLineAndKey) {
  TempDir dir("glare-cli");
  const Result r =
      runGlare(dir, "observers:\n  - {name: desk, eye: [0.8, 1.5, -0.1]}\n", "--direct-only");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "room.yaml:7: observers[0].eye: observer 'desk': the eye")) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(GlareCommand, HelpTeachesTheFormulaAndTheFiles) {
  TempDir dir("glare-cli");
  const Result r = runPenumbra(dir.path(), "glare --help");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* part :
       {"UGR = 8 log10(0.25/L_b * sum L^2 omega / p^2)", "Guth position index", "--direct-only",
        "<entry>.csv", "<entry>-sources.csv", "summary.json", "undefined"}) {
    EXPECT_TRUE(contains(r.out, part)) << part << "\n" << r.out;
  }
}

}  // namespace
