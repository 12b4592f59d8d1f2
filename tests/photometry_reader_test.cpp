// What the IES and EULUMDAT readers take from a file: versions, keywords, units, multipliers,
// absolute photometry, tilt tables, openings, lamp sets and the stored planes of each symmetry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "photometry/ies_reader.hpp"
#include "photometry/ldt_reader.hpp"
#include "photometry_files.hpp"

namespace {

using namespace penumbra::photometry;
using testfiles::IesSpec;
using testfiles::LdtSpec;
using testfiles::steps;

IesSpec smallIes() {
  IesSpec spec;
  spec.vertical = {0, 45, 90};
  spec.horizontal = {0, 90};
  spec.candela = [](double c, double g) { return 100 + c + 2 * g; };
  return spec;
}

TEST(IesReader, ReadsTheVersionKeywordsAndTable) {
  IesSpec spec = smallIes();
  spec.keywords = {"[TEST] 1234", "[MANUFAC] penumbra", "[LAMP] LED module", "[MORE] 4000 K"};
  const PhotometricData data = parseIes(testfiles::iesText(spec), "a.ies");
  EXPECT_EQ(data.format, PhotometricFormat::Ies);
  EXPECT_EQ(data.version, "LM-63-2002");
  EXPECT_EQ(data.type, PhotometricType::C);
  EXPECT_EQ(data.symmetry, HorizontalSymmetry::Quadrant);
  ASSERT_EQ(data.header.size(), 3u);
  EXPECT_EQ(data.header[0].name, "TEST");
  EXPECT_EQ(data.header[0].value, "1234");
  EXPECT_EQ(data.header[0].line, 2);
  EXPECT_EQ(data.header[2].value, "LED module\n4000 K");
  EXPECT_EQ(data.lamps.at(0).type, "LED module\n4000 K");
  EXPECT_EQ(data.verticalAnglesDeg, spec.vertical);
  EXPECT_EQ(data.horizontalAnglesDeg, spec.horizontal);
  for (std::size_t h = 0; h < 2; ++h) {
    for (std::size_t v = 0; v < 3; ++v) {
      EXPECT_EQ(data.candelaAt(h, v), spec.candela(spec.horizontal[h], spec.vertical[v]));
    }
  }
  EXPECT_EQ(data.lampLumens, 1000);
  EXPECT_FALSE(data.absolutePhotometry);
  EXPECT_FALSE(data.lightOutputRatio.has_value());
  EXPECT_TRUE(data.warnings.empty());

  spec.versionLine = "IES:LM-63-2019";
  spec.keywords.push_back("[_LOR] 82.5");
  const PhotometricData v2019 = parseIes(testfiles::iesText(spec), "b.ies");
  EXPECT_EQ(v2019.version, "LM-63-2019");
  EXPECT_DOUBLE_EQ(*v2019.lightOutputRatio, 0.825);
  // A UTF-8 byte order mark before the version line.
  EXPECT_EQ(parseIes("\xEF\xBB\xBF" + testfiles::iesText(spec), "bom.ies").version, "LM-63-2019");
  spec.versionLine = "IESNA91";
  EXPECT_EQ(parseIes(testfiles::iesText(spec), "c.ies").version, "LM-63-1991");
  // LM-63-1986: no version line, free label lines.
  spec.versionLine = "Some manufacturer's downlight";
  spec.keywords = {"made in 1987"};
  const PhotometricData v1986 = parseIes(testfiles::iesText(spec), "d.ies");
  EXPECT_EQ(v1986.version, "LM-63-1986");
  EXPECT_EQ(v1986.header.at(0).value, "Some manufacturer's downlight");
  EXPECT_TRUE(v1986.warnings.empty());
}

TEST(IesReader, NumbersMaySplitAcrossLinesAnyhow) {
  const IesSpec base = smallIes();
  const PhotometricData reference = parseIes(testfiles::iesText(base), "a.ies");
  for (int perLine : {1, 2, 7}) {
    for (std::string separator : {" ", ",", " , ", "\t"}) {
      IesSpec spec = base;
      spec.perLine = perLine;
      spec.separator = separator;
      std::string text = testfiles::iesText(spec);
      // CRLF line ends read the same.
      if (perLine == 2) {
        std::string crlf;
        for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
        text = crlf;
      }
      const PhotometricData data = parseIes(text, "split.ies");
      EXPECT_EQ(data.candela, reference.candela) << perLine << "'" << separator << "'";
      EXPECT_EQ(data.verticalAnglesDeg, reference.verticalAnglesDeg);
    }
  }
  // The line before TILT ends, then every value on its own line with blank lines between.
  std::string text = "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n";
  for (const char* word :
       {"1",  "1000", "1",  "3",  "2", "1",  "2",   "0",   "0",   "0",   "1",   "1",
        "20", "0",    "45", "90", "0", "90", "100", "190", "280", "190", "280", "370"}) {
    text += std::string(word) + "\n\n";
  }
  EXPECT_EQ(parseIes(text, "one.ies").candela, reference.candela);
}

TEST(IesReader, FeetBecomeMetresAndSignsGiveTheShape) {
  IesSpec spec = smallIes();
  spec.units = 1;
  spec.width = 2;
  spec.length = 4;
  const PhotometricData feet = parseIes(testfiles::iesText(spec), "feet.ies");
  EXPECT_EQ(feet.opening.shape, OpeningShape::Rectangle);
  EXPECT_DOUBLE_EQ(feet.opening.widthM, 2 * 0.3048);
  EXPECT_DOUBLE_EQ(feet.opening.lengthM, 4 * 0.3048);
  spec.units = 2;
  struct Case {
    double w, l, h;
    OpeningShape shape;
  };
  const Case cases[] = {
      {0, 0, 0, OpeningShape::Point},
      {0.6, 0.3, 0.1, OpeningShape::RectangleWithLuminousSides},
      {-0.2, -0.2, 0, OpeningShape::Disk},
      {-0.2, 0, 0, OpeningShape::Disk},
      {-0.2, 0, 0.1, OpeningShape::VerticalCylinder},
      {-0.2, -0.3, 0, OpeningShape::Ellipse},
      {-0.2, -0.2, 0.4, OpeningShape::VerticalCylinder},
      {-0.2, -0.2, -0.2, OpeningShape::Sphere},
      {-0.2, -0.3, -0.2, OpeningShape::Ellipsoid},
      {-0.1, 1.2, -0.1, OpeningShape::HorizontalCylinderAlongLength},
      {1.2, -0.1, -0.1, OpeningShape::HorizontalCylinderAlongWidth},
      {-0.2, 0, -0.2, OpeningShape::VerticalDiskFacingLength},
      {0, -0.2, -0.2, OpeningShape::VerticalDiskFacingWidth},
  };
  for (const Case& c : cases) {
    spec.width = c.w;
    spec.length = c.l;
    spec.height = c.h;
    const PhotometricData data = parseIes(testfiles::iesText(spec), "shape.ies");
    EXPECT_EQ(data.opening.shape, c.shape) << c.w << " " << c.l << " " << c.h;
    EXPECT_EQ(data.opening.widthM, std::abs(c.w));
    // A round opening given by its width alone has that diameter along C0-C180 too.
    EXPECT_EQ(data.opening.lengthM, c.l == 0 && c.h >= 0 ? std::abs(c.w) : std::abs(c.l));
    EXPECT_EQ(data.opening.heightM, std::abs(c.h));
    EXPECT_TRUE(data.warnings.empty());
  }
  spec.width = -0.2;  // w < 0, l > 0, h = 0: not in LM-63's table
  spec.length = 0.5;
  spec.height = 0;
  const PhotometricData odd = parseIes(testfiles::iesText(spec), "odd.ies");
  EXPECT_EQ(odd.opening.shape, OpeningShape::Point);
  ASSERT_EQ(odd.warnings.size(), 1u);
  EXPECT_NE(odd.warnings[0].find("sign combination"), std::string::npos);
}

TEST(IesReader, MultipliersAndAbsolutePhotometry) {
  IesSpec spec = smallIes();
  spec.multiplier = 2;
  spec.ballast = 0.9;
  spec.third = 0.95;
  spec.lamps = 2;
  spec.lumensPerLamp = 1500;
  // LM-63-2002: the third factor is "future use" and multiplies nothing.
  const PhotometricData v2002 = parseIes(testfiles::iesText(spec), "m.ies");
  EXPECT_DOUBLE_EQ(v2002.candelaAt(1, 2), (100 + 90 + 180) * 2 * 0.9);
  EXPECT_EQ(v2002.lampLumens, 3000);
  // LM-63-1995: it is the ballast-lamp photometric factor.
  spec.versionLine = "IESNA:LM-63-1995";
  const PhotometricData v1995 = parseIes(testfiles::iesText(spec), "m.ies");
  EXPECT_DOUBLE_EQ(v1995.candelaAt(1, 2), (100 + 90 + 180) * 2 * 0.9 * 0.95);
  // Lumens -1: absolute photometry, candela as given.
  spec = smallIes();
  spec.lumensPerLamp = -1;
  const PhotometricData absolute = parseIes(testfiles::iesText(spec), "abs.ies");
  EXPECT_TRUE(absolute.absolutePhotometry);
  EXPECT_EQ(absolute.lampLumens, 0);
  EXPECT_EQ(absolute.candelaAt(0, 1), 190);
}

TEST(IesReader, ReadsTheTiltTable) {
  IesSpec spec = smallIes();
  spec.tilt = "INCLUDE";
  spec.tiltBlock = "1\n7\n0 15 30 45 60 75\n90\n1.0 0.95 0.94 0.90 0.88\n0.87 0.98\n";
  const PhotometricData data = parseIes(testfiles::iesText(spec), "tilt.ies");
  ASSERT_TRUE(data.tilt.has_value());
  EXPECT_EQ(data.tilt->lampToLuminaireGeometry, 1);
  EXPECT_EQ(data.tilt->anglesDeg, (std::vector<double>{0, 15, 30, 45, 60, 75, 90}));
  EXPECT_EQ(data.tilt->factors, (std::vector<double>{1.0, 0.95, 0.94, 0.90, 0.88, 0.87, 0.98}));
  EXPECT_EQ(data.candela, parseIes(testfiles::iesText(smallIes()), "a.ies").candela);
  EXPECT_FALSE(parseIes(testfiles::iesText(smallIes()), "a.ies").tilt.has_value());
}

TEST(IesReader, HorizontalAnglesGiveTheSymmetry) {
  IesSpec spec = smallIes();
  const std::pair<std::vector<double>, HorizontalSymmetry> cases[] = {
      {{0}, HorizontalSymmetry::Rotational},
      {{0, 45, 90}, HorizontalSymmetry::Quadrant},
      {{0, 90, 180}, HorizontalSymmetry::AboutC0C180},
      {{0, 90, 180, 270, 360}, HorizontalSymmetry::None},
      {{0, 120, 240}, HorizontalSymmetry::None},
      {{90, 180, 270}, HorizontalSymmetry::AboutC90C270},
  };
  for (const auto& [angles, symmetry] : cases) {
    spec.horizontal = angles;
    EXPECT_EQ(parseIes(testfiles::iesText(spec), "s.ies").symmetry, symmetry) << angles.size();
  }
}

TEST(LdtReader, ReadsHeaderLampSetsAndConvertsToCandela) {
  LdtSpec spec;
  spec.isym = 0;
  spec.areaLength = 1200;
  spec.areaWidth = 300;
  spec.lorPercent = 78.5;
  spec.conversion = 1.25;
  spec.lampSets = {{2, 1600, 30}, {1, 800, 12}};
  spec.cdPerKlm = [](double c, double g) { return 200 + c + g; };
  const PhotometricData data = parseLdt(testfiles::ldtText(spec), "panel.ldt");
  EXPECT_EQ(data.format, PhotometricFormat::Eulumdat);
  EXPECT_EQ(data.symmetry, HorizontalSymmetry::None);
  EXPECT_EQ(data.lampLumens, 2400);
  EXPECT_DOUBLE_EQ(*data.lightOutputRatio, 0.785);
  EXPECT_EQ(data.inputWatts, 42);
  ASSERT_EQ(data.lamps.size(), 2u);
  EXPECT_EQ(data.lamps[0].count, 2);
  EXPECT_EQ(data.lamps[1].type, "LED");
  EXPECT_EQ(data.lamps[1].colour, "3000 K");
  EXPECT_EQ(data.lamps[1].renderingIndex, "80");
  EXPECT_FALSE(data.absolutePhotometry);
  EXPECT_EQ(data.opening.shape, OpeningShape::Rectangle);
  EXPECT_DOUBLE_EQ(data.opening.lengthM, 1.2);
  EXPECT_DOUBLE_EQ(data.opening.widthM, 0.3);
  EXPECT_EQ(data.horizontalAnglesDeg, steps(0, 345, 15));
  EXPECT_EQ(data.verticalAnglesDeg, steps(0, 180, 5));
  // cd = cd/klm x CFLI x klm of all lamp sets.
  EXPECT_DOUBLE_EQ(data.candelaAt(3, 4), (200 + 45 + 20) * 1.25 * 2.4);
  const auto name = std::find_if(data.header.begin(), data.header.end(),
                                 [](const HeaderField& f) { return f.name == "luminaire name"; });
  ASSERT_NE(name, data.header.end());
  EXPECT_EQ(name->value, "test luminaire");
  EXPECT_EQ(name->line, 9);
}

TEST(LdtReader, StoresThePlanesOfEachSymmetry) {
  const std::pair<int, std::vector<double>> cases[] = {
      {0, steps(0, 345, 15)}, {1, {0}}, {2, steps(0, 180, 15)}, {3, steps(90, 270, 15)},
      {4, steps(0, 90, 15)},
  };
  const HorizontalSymmetry symmetries[] = {
      HorizontalSymmetry::None, HorizontalSymmetry::Rotational, HorizontalSymmetry::AboutC0C180,
      HorizontalSymmetry::AboutC90C270, HorizontalSymmetry::Quadrant};
  for (const auto& [isym, planes] : cases) {
    LdtSpec spec;
    spec.isym = isym;
    spec.cdPerKlm = [](double c, double g) { return c + g / 1000; };
    const PhotometricData data = parseLdt(testfiles::ldtText(spec), "s.ldt");
    EXPECT_EQ(data.symmetry, symmetries[isym]);
    EXPECT_EQ(data.horizontalAnglesDeg, planes) << isym;
    ASSERT_EQ(data.candela.size(), planes.size() * 37);
    // Each stored row is the plane it claims to be.
    for (std::size_t p = 0; p < planes.size(); ++p) {
      EXPECT_DOUBLE_EQ(data.candelaAt(p, 36), planes[p] + 0.18) << isym << " " << p;
    }
  }
}

TEST(LdtReader, AreasAbsolutePhotometryAndDecimalCommas) {
  LdtSpec spec;
  spec.isym = 1;
  spec.areaLength = 150;  // width 0: a disk of 150 mm
  spec.lampSets = {{-1, 2000, 20}};
  spec.cdPerKlm = [](double, double g) { return 300 - g; };
  std::string text = testfiles::ldtText(spec);
  const PhotometricData disk = parseLdt(text, "disk.ldt");
  EXPECT_EQ(disk.opening.shape, OpeningShape::Disk);
  EXPECT_DOUBLE_EQ(disk.opening.lengthM, 0.15);
  EXPECT_DOUBLE_EQ(disk.opening.widthM, 0.15);
  EXPECT_TRUE(disk.absolutePhotometry);
  EXPECT_DOUBLE_EQ(disk.candelaAt(0, 2), 290 * 2.0);
  // The same file with decimal commas (written with a German locale).
  const std::size_t at = text.find("\n0.5\n");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 5, "\n0,5\n");
  text.replace(text.find("\n300\n"), 5, "\n300,0\n");
  EXPECT_EQ(parseLdt(text, "comma.ldt").candela, disk.candela);
  EXPECT_EQ(parseLdt("\xEF\xBB\xBF" + text, "bom.ldt").candela, disk.candela);
  spec.areaHeights[1] = 40;
  spec.areaWidth = 100;
  const PhotometricData box = parseLdt(testfiles::ldtText(spec), "box.ldt");
  EXPECT_EQ(box.opening.shape, OpeningShape::RectangleWithLuminousSides);
  EXPECT_DOUBLE_EQ(box.opening.sideHeightsM[1], 0.04);
  EXPECT_DOUBLE_EQ(box.opening.heightM, 0.04);
}

}  // namespace
