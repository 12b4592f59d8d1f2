#include "cli/luminaire_command.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "glare/ugr_table.hpp"
#include "output/ugr_table_files.hpp"
#include "photometry/photometric_error.hpp"
#include "photometry/photometric_file.hpp"
#include "photometry/zonal_flux.hpp"

namespace penumbra {
namespace {

using namespace photometry;

// The largest difference between the zonal flux and the file's that reads as agreement.
constexpr double kFluxTolerance = 1e-3;

// "37 γ angles (0° to 90°)", or "1 C plane (0°)".
std::string range(const std::vector<double>& angles, const char* singular, const char* plural) {
  if (angles.size() == 1) return fmt::format("1 {} ({}°)", singular, angles.front());
  return fmt::format("{} {} ({}° to {}°)", angles.size(), plural, angles.front(), angles.back());
}

std::string lampsLine(const PhotometricData& data) {
  if (data.absolutePhotometry && data.format == PhotometricFormat::Ies) {
    return "absolute photometry (lumens -1): the table is the luminaire's own, in cd";
  }
  std::string text;
  for (const LampSet& set : data.lamps) {
    if (!text.empty()) text += " + ";
    text += fmt::format("{} x {}{}", std::abs(set.count), set.type.empty() ? "lamp" : set.type,
                        data.format == PhotometricFormat::Eulumdat
                            ? fmt::format(" ({:.0f} lm for the set)", set.lumens)
                            : "");
  }
  text += fmt::format(" = {:.1f} lm", data.lampLumens);
  if (data.absolutePhotometry) text += " (absolute photometry)";
  return text;
}

std::string openingLine(const LuminousOpening& o) {
  if (o.shape == OpeningShape::Point) return "point (no luminous dimensions)";
  return fmt::format("{}, length {:.3f} m (C0-C180) x width {:.3f} m (C90-C270) x height {:.3f} m",
                     openingShapeName(o.shape), o.lengthM, o.widthM, o.heightM);
}

std::string anglesOfPeak(PhotometricType type, const TableAngles& at) {
  if (type == PhotometricType::C)
    return fmt::format("C {}°, γ {}°", at.horizontalDeg, at.verticalDeg);
  return fmt::format("H {}°, V {}°", at.horizontalDeg, at.verticalDeg);
}

std::string fluxLines(const FluxComparison& flux) {
  std::string text = fmt::format("  {:<18}{:.1f} lm (zonal method on the table's nodes)\n",
                                 "flux of the table", flux.zonalLm);
  if (!flux.relativeDifference) {
    return text + fmt::format("  {:<18}not stated (needs lamp lumens and a LOR)\n", "file flux");
  }
  const double d = *flux.relativeDifference;
  return text +
         fmt::format("  {:<18}{:.1f} lm = lamp lumens x LOR; the table differs by {:+.3f} %{}\n",
                     "file flux", *flux.fileLm, 100 * d,
                     std::abs(d) <= kFluxTolerance ? " (within 0.1 %)" : " (MORE than 0.1 %)");
}

}  // namespace

std::string describeLuminaire(const std::filesystem::path& file, const PhotometricData& data,
                              const LightDistribution& distribution) {
  const bool typeC = data.type == PhotometricType::C;
  std::string text = file.string() + "\n";
  const auto row = [&](const char* label, const std::string& value) {
    text += fmt::format("  {:<18}{}\n", label, value);
  };
  row("format",
      formatName(data.format) + (data.format == PhotometricFormat::Ies ? " " + data.version : ""));
  row("photometric type", typeName(data.type) + (typeC ? " (C, γ: vertical polar axis)"
                                                       : " (H, V: horizontal polar axis)"));
  row("symmetry", symmetryName(data.symmetry));
  row("angles", range(data.horizontalAnglesDeg, typeC ? "C plane" : "H angle",
                      typeC ? "C planes" : "H angles") +
                    ", " +
                    range(data.verticalAnglesDeg, typeC ? "γ angle" : "V angle",
                          typeC ? "γ angles" : "V angles"));
  row("lamps", lampsLine(data));
  row("LOR", data.lightOutputRatio ? fmt::format("{:.2f} %", 100 * *data.lightOutputRatio)
                                   : std::string("not stated"));
  row("input power", fmt::format("{:.1f} W", data.inputWatts));
  row("opening", openingLine(data.opening));
  const PeakIntensity peak = distribution.peak();
  row("peak intensity",
      fmt::format("{:.1f} cd at {}", peak.candela, anglesOfPeak(data.type, peak.at)));
  text += fluxLines(compareFlux(data, distribution));
  if (data.tilt) {
    row("tilt table", fmt::format("{} angles, lamp-to-luminaire geometry {}",
                                  data.tilt->anglesDeg.size(), data.tilt->lampToLuminaireGeometry));
  }
  if (data.warnings.empty()) {
    row("warnings", "none");
  } else {
    for (const std::string& w : data.warnings) row("warning", w);
  }
  return text;
}

namespace {

// The tables at S = 0.25H (DIALux's) and 1.0H (CIE 190's standard condition), printed and, with
// -o, written as CSV.
int printUgrTables(const LuminaireOptions& options, const PhotometricData& data,
                   const LightDistribution& distribution) {
  const TabularLuminaire luminaire = tabularLuminaire(distribution, data.opening);
  if (!(luminaire.areaM2 > 0.0)) {
    fmt::print(stderr,
               "{}: no luminous area to rate (opening: {}): the UGR table needs L = I/A_p, so "
               "the file must state a rectangle (with or without luminous sides), a disk or an "
               "ellipse\n",
               options.file.string(), openingLine(data.opening));
    return 1;
  }
  std::vector<UgrTable> tables;
  for (double spacing : {0.25, 1.0}) {
    tables.push_back(computeUgrTable(luminaire, UgrTableSettings{spacing, kStandardHeightM}));
    fmt::print("\n{}", ugrTableText(tables.back()));
  }
  if (!options.outputDirectory.empty()) {
    const std::filesystem::path csv =
        options.outputDirectory / (options.file.stem().string() + "-ugr-table.csv");
    try {
      std::filesystem::create_directories(options.outputDirectory);
      writeUgrTableCsv(tables, csv);
    } catch (const std::exception& e) {
      fmt::print(stderr, "{}: {}\n", csv.string(), e.what());
      return 1;
    }
    fmt::print("\nwrote {}\n", csv.string());
  }
  return 0;
}

}  // namespace

int runLuminaireCommand(const LuminaireOptions& options) {
  try {
    const PhotometricData data = readPhotometricFile(options.file);
    const LightDistribution distribution(data);
    fmt::print("{}", describeLuminaire(options.file, data, distribution));
    return options.ugrTable ? printUgrTables(options, data, distribution) : 0;
  } catch (const PhotometricError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return e.line() > 0 ? 2 : 1;
  }
}

}  // namespace penumbra
