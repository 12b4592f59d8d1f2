#include "output/ugr_table_files.hpp"

#include <fmt/format.h>

#include <cmath>

#include "output/result_files.hpp"

namespace penumbra {
namespace {

// "70_50_20" for a reflectance set.
std::string setLabel(const RoomReflectances& r) {
  return fmt::format("{:.0f}_{:.0f}_{:.0f}", 100 * r.ceiling, 100 * r.walls, 100 * r.floor);
}

std::string ugrText(double ugr) {
  return std::isnan(ugr) ? "-" : fmt::format("{:.1f}", ugr);
}

std::string reflectanceLine(const char* label, double RoomReflectances::*member) {
  std::string line = fmt::format("  {:<16}", label);
  for (int view = 0; view < 2; ++view) {
    for (const RoomReflectances& r : kStandardReflectances)
      line += fmt::format("{:>6.2f}", r.*member);
    line += "   ";
  }
  return line + "\n";
}

}  // namespace

std::string ugrTableMethod() {
  return "CIE 190:2010 tabular method: UGR = 8 log10(0.25/L_b sum L^2 omega/p^2), observer at the "
         "middle of a wall, eye 1.2 m, far-field omega = A_p/r^2, Guth index in closed form, "
         "L_b = E_WID/pi from the standard's flux transfer";
}

std::string ugrTableText(const UgrTable& table) {
  const UgrTableSettings& s = table.settings;
  std::string text = fmt::format("UGR [-] table, S = {:.2f}H, H = {:.2f} m ({})\n", s.spacingRatio,
                                 s.heightM, ugrTableMethod());
  text +=
      fmt::format("  flux Phi0 = {:.1f} lm (the table's); for a flux Phi add 8 log10(Phi/Phi0)\n",
                  table.fluxLm);
  text += reflectanceLine("ceiling", &RoomReflectances::ceiling);
  text += reflectanceLine("walls", &RoomReflectances::walls);
  text += reflectanceLine("floor", &RoomReflectances::floor);
  text += fmt::format("  {:<6}{:<10}{:<33}{}\n", "X", "Y", "viewed crosswise", "viewed endwise");
  int previousAcross = 0;
  for (const UgrTableRow& row : table.rows) {
    const std::string across =
        row.room.acrossH == previousAcross ? "" : fmt::format("{}H", row.room.acrossH);
    previousAcross = row.room.acrossH;
    std::string line = fmt::format("  {:<6}{:<10}", across, fmt::format("{}H", row.room.alongH));
    for (double ugr : row.crosswise) line += fmt::format("{:>6}", ugrText(ugr));
    line += "   ";
    for (double ugr : row.endwise) line += fmt::format("{:>6}", ugrText(ugr));
    text += line + "\n";
  }
  return text;
}

void writeUgrTableCsv(const std::vector<UgrTable>& tables, const std::filesystem::path& path) {
  writeFile(path, [&](std::ostream& out) {
    out << "S_over_H,X_H,Y_H,X_m,Y_m,luminaires";
    for (const char* view : {"crosswise", "endwise"}) {
      for (const RoomReflectances& r : kStandardReflectances)
        out << ",UGR_" << view << "_" << setLabel(r);
    }
    for (const RoomReflectances& r : kStandardReflectances) out << ",L_b_cd_m2_" << setLabel(r);
    out << "\n";
    for (const UgrTable& table : tables) {
      const double h = table.settings.heightM;
      for (const UgrTableRow& row : table.rows) {
        out << fmt::format("{},{},{},{},{},{}", table.settings.spacingRatio, row.room.acrossH,
                           row.room.alongH, row.room.acrossH * h, row.room.alongH * h,
                           row.luminaires);
        for (double ugr : row.crosswise)
          out << "," << (std::isnan(ugr) ? "" : fmt::format("{:.2f}", ugr));
        for (double ugr : row.endwise)
          out << "," << (std::isnan(ugr) ? "" : fmt::format("{:.2f}", ugr));
        for (double lb : row.backgroundLuminance) out << "," << fmt::format("{:.4g}", lb);
        out << "\n";
      }
    }
  });
}

}  // namespace penumbra
