#pragma once
// The interreflection of the CIE 190 standard room: a rectangular box X x Y x H of three diffuse
// surfaces, the reference plane at eye height ("floor", reflectance ρ_F), the walls between it
// and the luminaires' plane (ρ_W) and the luminaires' plane ("ceiling", ρ_C). Each surface is
// taken as uniformly lit (the three-surface flux transfer of the CIE tabular methods): the
// exitances M solve M_i = ρ_i (E0_i + Σ_j f_ij M_j), with f_ij the exact form factors of the box
// (floor to ceiling: two parallel, directly opposed rectangles, Hottel's closed form; the rest
// by reciprocity and closure).
//
// The transfer factors CIE 190 tabulates (its table of F_T per room and reflectance set) are the
// indirect illuminance this gives on the walls, times their area A_W = 2H(X+Y), per lumen first
// falling on one surface: F_T,FW from the floor, F_T,WW-1 from the walls (the walls' own first
// illuminance left out: "-1"), F_T,CW from the ceiling.

namespace penumbra {

struct RoomReflectances {
  double ceiling = 0.0, walls = 0.0, floor = 0.0;
};

// Per lumen first falling on the floor, walls or ceiling: the walls' indirect illuminance times
// A_W (dimensionless).
struct WallTransfer {
  double fromFloor = 0.0, fromWalls = 0.0, fromCeiling = 0.0;
};

// The form factor between two parallel, directly opposed a x b rectangles a distance c apart.
double opposedRectanglesFormFactor(double a, double b, double c);

// The box `lengthX` x `lengthY` x `height` (any one unit; only the ratios count).
WallTransfer wallTransfer(double lengthX, double lengthY, double height,
                          const RoomReflectances& reflectances);

}  // namespace penumbra
