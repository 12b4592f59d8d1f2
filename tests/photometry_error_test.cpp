// Malformed photometric files: each gives one PhotometricError that names the file, the line and
// the field, never a crash.
#include <gtest/gtest.h>

#include <string>

#include "photometry/ies_reader.hpp"
#include "photometry/ldt_reader.hpp"
#include "photometry/photometric_error.hpp"

namespace {

using namespace penumbra::photometry;

// Ten lines, numbered as in the comments of the cases below.
const std::string kIes =
    "IESNA:LM-63-2002\n"        // 1
    "[TEST] E1\n"               // 2
    "[MANUFAC] penumbra\n"      // 3
    "TILT=NONE\n"               // 4
    "1 1000 1 3 2 1 2 0 0 0\n"  // 5
    "1 1 10\n"                  // 6
    "0 45 90\n"                 // 7
    "0 180\n"                   // 8
    "100 70 0\n"                // 9
    "100 60 0\n";               // 10

// Isym 1, one C plane, three γ angles: 49 lines.
std::string ldtLines() {
  std::string text =
      "penumbra tests\n1\n1\n1\n0\n3\n45\nR1\nTest luminaire\nT-1\nt.ldt\n"
      "2026-12-02\n600\n600\n50\n600\n600\n0\n0\n0\n0\n100\n80\n1\n0\n"  // 1-25
      "1\n1\nLED\n1000\n3000K\n80\n20\n";                                // 26-32
  for (int i = 0; i < 10; ++i) text += "0.5\n";                          // 33-42
  return text + "0\n0\n45\n90\n100\n70\n0\n";                            // 43-49
}
const std::string kLdt = ldtLines();

// `text` with its 1-based line `line` replaced by `replacement` (which may hold several lines or
// none).
std::string withLine(const std::string& text, int line, const std::string& replacement) {
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  const std::size_t end = text.find('\n', start);
  return text.substr(0, start) + replacement + text.substr(end);
}

// The first `lines` lines of `text`.
std::string firstLines(const std::string& text, int lines) {
  std::size_t end = 0;
  for (int i = 0; i < lines; ++i) end = text.find('\n', end) + 1;
  return text.substr(0, end);
}

struct BadFile {
  std::string name;
  std::string text;
  int line;
  std::string field;    // the error's field starts with this
  std::string message;  // and its message contains this
};

template <typename Parse>
void expectOneError(const BadFile& bad, Parse parse, const std::string& file) {
  try {
    parse(bad.text, file);
    ADD_FAILURE() << bad.name << ": accepted";
  } catch (const PhotometricError& e) {
    EXPECT_EQ(e.file(), file) << bad.name;
    EXPECT_EQ(e.line(), bad.line) << bad.name << ": " << e.what();
    EXPECT_EQ(e.field().rfind(bad.field, 0), 0u) << bad.name << ": " << e.what();
    EXPECT_NE(e.message().find(bad.message), std::string::npos) << bad.name << ": " << e.what();
    const std::string prefix = file + ":" + std::to_string(bad.line) + ": " + e.field() + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
  }
}

TEST(PhotometricErrors, TheWellFormedFilesRead) {
  EXPECT_EQ(parseIes(kIes, "ok.ies").candela.size(), 6u);
  EXPECT_EQ(parseLdt(kLdt, "ok.ldt").candela.size(), 3u);
}

TEST(PhotometricErrors, MalformedIesFiles) {
  const BadFile cases[] = {
      {"empty", "", 1, "IES file", "empty"},
      {"blank", "\n  \n", 1, "IES file", "empty"},
      {"no TILT", withLine(kIes, 4, "[OTHER] x"), 10, "TILT", "no TILT= line"},
      {"header only", firstLines(kIes, 3), 3, "TILT", "no TILT= line"},
      {"TILT without =", withLine(kIes, 4, "TILT NONE"), 4, "TILT", "expected TILT="},
      {"tilt file", withLine(kIes, 4, "TILT=lamp.tlt"), 4, "TILT", "'lamp.tlt' is not read"},
      {"tilt block cut", firstLines(kIes, 3) + "TILT=INCLUDE\n1\n3\n0 45", 7, "tilt angles",
       "expected 3 values, found 2 (the file ends)"},
      {"tilt geometry 4", withLine(kIes, 4, "TILT=INCLUDE\n4\n1\n0\n1"), 5,
       "lamp-to-luminaire geometry", "from 1 to 3"},
      {"ends after TILT", firstLines(kIes, 4), 4, "number of lamps", "missing (the file ends)"},
      {"lamps not a number", withLine(kIes, 5, "1x 1000 1 3 2 1 2 0 0 0"), 5, "number of lamps",
       "expected a number, found '1x'"},
      {"lamps not whole", withLine(kIes, 5, "1.5 1000 1 3 2 1 2 0 0 0"), 5, "number of lamps",
       "not a whole number"},
      {"lumens -5", withLine(kIes, 5, "1 -5 1 3 2 1 2 0 0 0"), 5, "lumens per lamp", "-1 for "},
      {"multiplier 0", withLine(kIes, 5, "1 1000 0 3 2 1 2 0 0 0"), 5, "candela multiplier",
       "positive"},
      {"huge count", withLine(kIes, 5, "1 1000 1 100000 2 1 2 0 0 0"), 5,
       "number of vertical angles", "at most 1801"},
      {"count 0", withLine(kIes, 5, "1 1000 1 3 0 1 2 0 0 0"), 5, "number of horizontal angles",
       "from 1 to 3601"},
      {"type 4", withLine(kIes, 5, "1 1000 1 3 2 4 2 0 0 0"), 5, "photometric type",
       "1 = C, 2 = B, 3 = A"},
      {"units 3", withLine(kIes, 5, "1 1000 1 3 2 1 3 0 0 0"), 5, "units type", "1 = feet"},
      {"ballast 0", withLine(kIes, 6, "0 1 10"), 6, "ballast factor", "positive"},
      {"negative watts", withLine(kIes, 6, "1 1 -10"), 6, "input watts", "negative"},
      {"vertical cut", firstLines(kIes, 6) + "0 45", 7, "vertical angles",
       "expected 3 values, found 2 (the file ends)"},
      {"vertical not increasing", withLine(kIes, 7, "0 45 40"), 7, "vertical angles",
       "not increasing"},
      {"vertical above 180", withLine(kIes, 7, "0 45 200"), 7, "vertical angles",
       "outside 0° to 180°"},
      {"horizontal 0-45", withLine(kIes, 8, "0 45"), 8, "horizontal angles", "no LM-63 symmetry"},
      {"horizontal from 30", withLine(kIes, 8, "30 180"), 8, "horizontal angles", "start at 0°"},
      {"candela cut", firstLines(kIes, 9), 9, "candela values (horizontal angle 180°)",
       "expected 3 values, found 0 (the file ends)"},
      {"negative candela", withLine(kIes, 10, "100 -60 0"), 10, "candela values",
       "negative value -60 at vertical angle 45°"},
      {"nan candela", withLine(kIes, 9, "100 nan 0"), 9, "candela values", "found 'nan'"},
      {"huge candela", withLine(kIes, 9, "100 1e400 0"), 9, "candela values", "found '1e400'"},
      {"candela above 10^12 cd", withLine(kIes, 5, "1 1000 2e10 3 2 1 2 0 0 0"), 9,
       "candela values (horizontal angle 0°)", "cd at vertical angle 0°: above 10^12 cd"},
      {"extra values", kIes + "5 5\n", 11, "candela values", "2 more values"},
      {"bad [_LOR]", withLine(kIes, 3, "[_LOR] most"), 3, "[_LOR]", "in %"},
  };
  for (const BadFile& bad : cases) expectOneError(bad, parseIes, "bad.ies");
}

TEST(PhotometricErrors, MalformedEulumdatFiles) {
  const BadFile cases[] = {
      {"empty", "", 1, "EULUMDAT file", "empty"},
      {"Ityp 7", withLine(kLdt, 2, "7"), 2, "type indicator Ityp", "from 0 to 3"},
      {"Isym 5", withLine(kLdt, 3, "5"), 3, "symmetry indicator Isym", "from 0 to 4"},
      {"Mc not a number", withLine(kLdt, 4, "one"), 4, "number of C planes Mc", "found 'one'"},
      {"Mc for Isym 4", withLine(withLine(kLdt, 3, "4"), 4, "6"), 4, "number of C planes Mc",
       "multiple of 4"},
      {"Mc huge", withLine(kLdt, 4, "99999"), 4, "number of C planes Mc", "at most 3600"},
      {"Ng 0", withLine(kLdt, 6, "0"), 6, "number of γ angles Ng", "from 1 to 1801"},
      {"ends in the header", firstLines(kLdt, 12), 12, "luminaire length", "the file ends"},
      {"negative area", withLine(kLdt, 16, "-600"), 16, "luminous area length", "outside"},
      {"LORL 150", withLine(kLdt, 23, "150"), 23, "light output ratio LORL", "outside 0 to 100"},
      {"CFLI 0", withLine(kLdt, 24, "0"), 24, "conversion factor CFLI", "positive"},
      {"no lamp sets", withLine(kLdt, 26, "0"), 26, "number of lamp sets", "from 1 to 100"},
      {"lamp count 0", withLine(kLdt, 27, "0"), 27, "number of lamps (set 1)", "not be 0"},
      {"lamp flux 0", withLine(kLdt, 29, "0"), 29, "lamp luminous flux (set 1)", "positive"},
      {"wattage text", withLine(kLdt, 32, "twenty"), 32, "wattage (set 1)", "found 'twenty'"},
      {"direct ratio text", withLine(kLdt, 35, "n/a"), 35, "direct ratio 3 of 10", "'n/a'"},
      {"γ not increasing", withLine(kLdt, 45, "0"), 45, "γ angles", "not increasing"},
      {"γ above 180", withLine(kLdt, 46, "190"), 46, "γ angles", "outside 0° to 180°"},
      {"intensities cut", firstLines(kLdt, 48), 48, "luminous intensities (C 0°)",
       "expected 3 values, found 2 (the file ends)"},
      {"negative intensity", withLine(kLdt, 48, "-70"), 48, "luminous intensities",
       "negative value -70 at γ 45°"},
      {"lamp flux 1e300", withLine(kLdt, 29, "1e300"), 47, "luminous intensities (C 0°)",
       "above 10^12 cd"},
      {"extra lines", kLdt + "\n12\n", 51, "luminous intensities", "counts do not match"},
  };
  for (const BadFile& bad : cases) expectOneError(bad, parseLdt, "bad.ldt");
}

TEST(PhotometricErrors, EulumdatPlanesMustCloseTheirSymmetry) {
  // Isym 2 with Mc = 4 every 90°: plane 3 must be at 180°.
  std::string text = withLine(withLine(kLdt, 3, "2"), 4, "4");
  text = withLine(text, 43, "0\n90\n170\n270");  // C angles now on lines 43-46
  text = withLine(text, 52, "100\n70\n0\n100\n70\n0\n100\n70\n0");
  expectOneError({"Isym 2 plane", text, 45, "C angles", "must be at 180°"}, parseLdt, "s.ldt");
  std::string isym0 = withLine(withLine(kLdt, 3, "0"), 4, "2");
  isym0 = withLine(isym0, 43, "0\n360");
  expectOneError({"Isym 0 with 360", isym0, 44, "C angles", "below 360°"}, parseLdt, "s.ldt");
}

}  // namespace
