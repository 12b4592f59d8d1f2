#pragma once
// The display a picture is made for, after Mantiuk, Daly & Kerofsky ("Display adaptive tone
// mapping", ACM TOG 27(3), 2008): the luminance a code value V in [0, 1] shows is
//
//   L(V) = (Lmax − Lblack) · F(V) + Lblack + k · E_amb / π
//
// with Lmax the panel's white and Lblack its black in the dark (cd/m²), E_amb the illuminance on
// the screen from the room around it (lx), k the screen's reflectivity (0.01, the paper's value
// for an LCD: the reflected ambient light is a diffuse luminance k·E/π), and F the sRGB transfer
// function (IEC 61966-2-1) in place of the paper's plain power γ: the PNG is sRGB-encoded, and
// F is what an sRGB viewer applies. The tone map's display luminance targets become code values
// through the inverse of L.
namespace penumbra {

// IEC 61966-2-1: code value (0-1) → relative luminance (0-1), and back. Linear below
// 0.04045 / 0.0031308, a 2.4 power with offset above.
double srgbDecode(double code);
double srgbEncode(double linear);

struct DisplayModel {
  static constexpr double kReflectivity = 0.01;  // k: share of the ambient light reflected

  double peakLuminance = 100.0;  // Lmax, cd/m²
  double blackShare = 0.02;      // Lblack / Lmax, the panel's black in the dark
  double ambient = 0.0;          // E_amb, lx on the screen

  double blackLuminance() const { return blackShare * peakLuminance; }  // Lblack, cd/m²
  // k·E_amb/π, cd/m²
  double reflectedLuminance() const;
  // What the screen shows at code value 0 and 1: Lblack + reflected, Lmax + reflected.
  double darkest() const;
  double brightest() const;
  // The darkest over the brightest: the share of its white the display can go down to, the tone
  // map's lower bound (Fang's LowerBound, eq. 4.17) for this display; blackShare itself (to the
  // last bit) without ambient light.
  double lowerBound() const;

  // L(V) for a code value in [0, 1], cd/m².
  double luminance(double code) const;
  // The inverse: the code value that shows `luminance` (cd/m²), cut to [0, 1] where the display
  // cannot show it.
  double codeValue(double luminance) const;
  // The code value of a target given as a share of brightest() (the tone map's V).
  double codeValueOfShare(double share) const { return codeValue(share * brightest()); }
};

}  // namespace penumbra
