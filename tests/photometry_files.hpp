#pragma once
// Photometric files written by the tests: an IES or EULUMDAT text for a distribution given as a
// function of the table's angles, with every number printed exactly (17 significant digits).
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace penumbra::photometry::testfiles {

// cd (or cd/klm for EULUMDAT) at (horizontal, vertical) angles in degrees.
using Intensity = std::function<double(double horizontalDeg, double verticalDeg)>;

inline std::vector<double> steps(double first, double last, double step) {
  std::vector<double> out;
  const int n = static_cast<int>(std::lround((last - first) / step));
  for (int i = 0; i <= n; ++i) out.push_back(first + i * step);
  return out;
}

inline std::string exact(double value) {
  return fmt::format("{:.17g}", value);
}

struct IesSpec {
  std::string versionLine = "IESNA:LM-63-2002";
  std::vector<std::string> keywords = {"[TEST] written by the photometry tests",
                                       "[MANUFAC] penumbra"};
  std::string tilt = "NONE";
  std::string tiltBlock;  // the lines after TILT=INCLUDE
  int lamps = 1;
  double lumensPerLamp = 1000;
  double multiplier = 1;
  int type = 1;
  int units = 2;
  double width = 0, length = 0, height = 0;
  double ballast = 1, third = 1, watts = 20;
  std::vector<double> vertical, horizontal;
  Intensity candela;
  int perLine = 10;             // values per line
  std::string separator = " ";  // between values on a line
};

inline std::string joinValues(const std::vector<double>& values, int perLine,
                              const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += exact(values[i]);
    const bool lineEnd = (i + 1) % static_cast<std::size_t>(perLine) == 0 || i + 1 == values.size();
    out += lineEnd ? "\n" : separator;
  }
  return out;
}

inline std::string iesText(const IesSpec& s) {
  std::string out = s.versionLine + "\n";
  for (const auto& k : s.keywords) out += k + "\n";
  out += "TILT=" + s.tilt + "\n" + s.tiltBlock;
  out += fmt::format("{} {} {} {} {} {} {} {} {} {}\n", s.lamps, exact(s.lumensPerLamp),
                     exact(s.multiplier), s.vertical.size(), s.horizontal.size(), s.type, s.units,
                     exact(s.width), exact(s.length), exact(s.height));
  out += fmt::format("{} {} {}\n", exact(s.ballast), exact(s.third), exact(s.watts));
  out += joinValues(s.vertical, s.perLine, s.separator);
  out += joinValues(s.horizontal, s.perLine, s.separator);
  for (double h : s.horizontal) {
    std::vector<double> row;
    for (double v : s.vertical) row.push_back(s.candela(h, v));
    out += joinValues(row, s.perLine, s.separator);
  }
  return out;
}

struct LdtLampSet {
  int count = 1;
  double lumens = 1000;
  double watts = 20;
};

struct LdtSpec {
  int ityp = 1;
  int isym = 0;
  double dc = 15;                        // the C angles are 0, dc, ... below 360
  double dg = 5;                         // the γ angles are 0, dg, ... 180
  double areaLength = 0, areaWidth = 0;  // mm
  double areaHeights[4] = {0, 0, 0, 0};
  double lorPercent = 100;
  double conversion = 1;
  std::vector<LdtLampSet> lampSets = std::vector<LdtLampSet>(1);  // one lamp set of defaults
  Intensity cdPerKlm;                                             // of (C, γ)
};

// The C planes stored for Isym (EULUMDAT: Isym 3 stores C90-C270).
inline std::vector<double> storedLdtPlanes(const LdtSpec& s) {
  const std::vector<double> all = steps(0, 360 - s.dc, s.dc);
  const int mc = static_cast<int>(all.size());
  int first = 0, end = mc;
  if (s.isym == 1) end = 1;
  if (s.isym == 2) end = mc / 2 + 1;
  if (s.isym == 3) first = mc / 4, end = 3 * mc / 4 + 1;
  if (s.isym == 4) end = mc / 4 + 1;
  return {all.begin() + first, all.begin() + end};
}

inline std::string ldtText(const LdtSpec& s) {
  const std::vector<double> c = steps(0, 360 - s.dc, s.dc);
  const std::vector<double> g = steps(0, 180, s.dg);
  std::string out = "penumbra photometry tests\n";
  out += fmt::format("{}\n{}\n{}\n{}\n{}\n{}\n", s.ityp, s.isym, c.size(), exact(s.dc), g.size(),
                     exact(s.dg));
  out += "report 1\ntest luminaire\nT-1\ntest.ldt\n2026-12-02 tests\n";
  out += fmt::format("{}\n{}\n{}\n", exact(s.areaLength), exact(s.areaWidth), 50);
  out += fmt::format("{}\n{}\n", exact(s.areaLength), exact(s.areaWidth));
  for (double h : s.areaHeights) out += exact(h) + "\n";
  out += fmt::format("100\n{}\n{}\n0\n", exact(s.lorPercent), exact(s.conversion));
  out += fmt::format("{}\n", s.lampSets.size());
  for (const auto& l : s.lampSets) {
    out += fmt::format("{}\nLED\n{}\n3000 K\n80\n{}\n", l.count, exact(l.lumens), exact(l.watts));
  }
  for (int i = 0; i < 10; ++i) out += "0.5\n";
  for (double a : c) out += exact(a) + "\n";
  for (double a : g) out += exact(a) + "\n";
  for (double plane : storedLdtPlanes(s)) {
    for (double gamma : g) out += exact(s.cdPerKlm(plane, gamma)) + "\n";
  }
  return out;
}

// I0 cos γ below the horizon, 0 above.
inline double lambertian(double i0, double gammaDeg) {
  return gammaDeg <= 90 ? std::max(0.0, i0 * std::cos(gammaDeg * std::numbers::pi / 180)) : 0.0;
}

}  // namespace penumbra::photometry::testfiles
