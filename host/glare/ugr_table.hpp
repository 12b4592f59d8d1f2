#pragma once
// The UGR table of a luminaire by the tabular method of CIE 190:2010 (docs/glare.md, "The UGR
// table of a luminaire"): UGR = 8 log₁₀(0.25/L_b · Σ L²ω/p²) for an observer seated at the middle
// of one wall of a standard room, looking horizontally along it, under a regular array of the
// luminaire.
//
// The room: X across the line of sight, Y along it, both multiples of H, the height of the
// luminaires' plane above the eye (2 m; eye 1.2 m above the floor). The luminaires at spacing
// S = ratio x H in both directions, the first row S/2 from the walls: (X/S)(Y/S) of them, each at
// R along the line of sight, T across it and H above it. For each, with r² = R² + T² + H²:
//   γ = atan(√(R² + T²)/H), I the intensity towards the eye, A_p the luminous area projected
//   across the direction to the eye (A cos γ for a flat opening, plus the sides the eye sees of
//   a rectangle with luminous sides), L = I/A_p, ω = A_p/r², p Guth's index
// (position_index.hpp; luminaires outside its range left out). Viewed crosswise the luminaire's
// C0 axis points along the line of sight, back to the observer (its C90-C270 axis, a linear
// luminaire's length, across the view); viewed endwise its C0 axis lies across the line of sight.
//
// L_b = E_WID/π, the walls' indirect illuminance by the standard's flux transfer:
//   E_WID = N Φ / A_W · (F_DF F_T,FW + F_DW F_T,WW-1 + F_DC F_T,CW)
// N luminaires of flux Φ (the 18 zones' sum, tabular_flux.hpp), A_W = 2H(X + Y), the flux
// fractions of tabular_flux.hpp and the transfer factors of room_transfer.hpp.
//
// Every term scales with the flux: the table holds for the file's flux Φ₀; for a flux Φ add
// 8 log₁₀(Φ/Φ₀).
#include <array>
#include <vector>

#include "glare/room_transfer.hpp"
#include "glare/tabular_flux.hpp"
#include "photometry/light_distribution.hpp"

namespace penumbra {

// X across the line of sight and Y along it, in multiples of H.
struct StandardRoom {
  int acrossH = 0, alongH = 0;
};

// The rows DIALux and CIE 190 show: X = 2H, 4H with Y = 2H .. 12H; X = 8H, 12H with Y = 4H ..
inline constexpr std::array<StandardRoom, 19> kStandardRooms = {{{2, 2},
                                                                 {2, 3},
                                                                 {2, 4},
                                                                 {2, 6},
                                                                 {2, 8},
                                                                 {2, 12},
                                                                 {4, 2},
                                                                 {4, 3},
                                                                 {4, 4},
                                                                 {4, 6},
                                                                 {4, 8},
                                                                 {4, 12},
                                                                 {8, 4},
                                                                 {8, 6},
                                                                 {8, 8},
                                                                 {8, 12},
                                                                 {12, 4},
                                                                 {12, 6},
                                                                 {12, 8}}};

// Ceiling, walls, floor (reference plane).
inline constexpr std::array<RoomReflectances, 5> kStandardReflectances = {{{0.70, 0.50, 0.20},
                                                                           {0.70, 0.30, 0.20},
                                                                           {0.50, 0.50, 0.20},
                                                                           {0.50, 0.30, 0.20},
                                                                           {0.30, 0.30, 0.20}}};

inline constexpr double kStandardHeightM = 2.0;  // luminaires' plane above the eye

enum class Viewing { Crosswise, Endwise };

struct UgrTableSettings {
  double spacingRatio = 0.25;  // S/H
  double heightM = kStandardHeightM;
};

// The luminaire as the table sees it: its distribution (cd), its flat luminous area facing down
// (m², > 0) and, for a rectangle with luminous sides, the sides' areas (m²) facing C0 (+x), C90
// (+y), C180 (−x) and C270 (−y) of the luminaire's frame.
struct TabularLuminaire {
  const photometry::LightDistribution* distribution = nullptr;
  double areaM2 = 0.0;
  double sideAreaM2[4] = {0.0, 0.0, 0.0, 0.0};
};

// The luminaire of `distribution` with the luminous area of `opening`: a rectangle (with its
// luminous sides), disk or ellipse; area 0 for an opening without a flat one (a point, a
// cylinder, a sphere).
TabularLuminaire tabularLuminaire(const photometry::LightDistribution& distribution,
                                  const photometry::LuminousOpening& opening);

// The area (m²) `luminaire` shows towards the unit direction `toEye` of its frame (downwards).
double projectedArea(const TabularLuminaire& luminaire, const Vec3& toEye);

// Σ L²ω/p² over the array of one room, (cd/m²)²·sr.
double arrayGlareSum(const TabularLuminaire& luminaire, const StandardRoom& room, Viewing viewing,
                     const UgrTableSettings& settings);

struct UgrTableRow {
  StandardRoom room;
  int luminaires = 0;
  std::array<double, 5> backgroundLuminance{};   // cd/m², per reflectance set
  std::array<double, 5> crosswise{}, endwise{};  // UGR; NaN where undefined
};

struct UgrTable {
  UgrTableSettings settings;
  double fluxLm = 0.0;  // Φ₀, the flux the table holds for: the table's own (zonal_flux.hpp)
  std::vector<UgrTableRow> rows;
};

UgrTable computeUgrTable(const TabularLuminaire& luminaire, const UgrTableSettings& settings);

}  // namespace penumbra
