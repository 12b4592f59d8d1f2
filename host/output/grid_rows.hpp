#pragma once
// The rows of a grid's .csv and the lines of its .res, the only place their format is spelt out:
//   <grid>.csv   x_m,y_m,z_m,nx,ny,nz,E_lx,inside   one row per point; `inside` the name of the
//                solid containing the point as a CSV field, empty for none. With interreflection
//                x_m,y_m,z_m,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,inside: E_lx the total,
//                E_indirect_lx = E_lx - E_direct_lx (each rounded to the digits E holds, so the
//                identity holds to half an ulp of each)
//                With a sun (illuminance/sunlight.hpp), E_sun_lx follows them: the direct
//                sunlight, part of E_lx (and of E_direct_lx); with interreflection then
//                E_sun_reflected_lx, the sun's light reflected by the room (part of E_lx and of
//                E_indirect_lx).
//                With a sky (scene/daylight.hpp), the daylight factor in % follows the E columns:
//                DF_pct = 100·(E_lx − E_sun_lx − E_sun_reflected_lx)/E_h, and with
//                interreflection DF_direct_pct = 100·(E_direct_lx − E_sun_lx)/E_h (the
//                sky and ground seen through the openings) and DF_internal_pct (interreflected),
//                which add up to DF_pct; E_h the sky's unobstructed horizontal illuminance. The
//                daylight factor leaves the sun out: it is defined under the overcast sky.
//                With interreflection the BRE split of DF_pct follows: SC_pct (the sky component:
//                the sky seen through the openings), ERC_pct (the externally reflected
//                component: the ground seen through the openings and the light the faces outside
//                the room reflect to the point) and IRC_pct = DF_pct − SC_pct − ERC_pct (the
//                internally reflected component), each 100·E/E_h of its part
//   <grid>.res   E_lx (the total), one value a line
//   <grid>.pts   x y z nx ny nz (m; unit normal), one point a line in the order of .res: the
//                points as Radiance's rtrace reads them, so that .res and .pts go together
// Numbers are written as number_text.hpp says (fmt's "{}": the shortest text that reads back to
// the same double). E is written with the digits its computation holds: those of a float for
// the kernels (single precision, at most 9 significant digits), those of a double for the host
// reference; coordinates and normals are host doubles.
#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "geometry/vec.hpp"
#include "output/number_text.hpp"

namespace penumbra {

// The CSV's header line, with its line break.
inline std::string gridCsvHeader(bool withParts, bool daylight = false, bool sun = false) {
  std::string header = "x_m,y_m,z_m,nx,ny,nz,E_lx";
  if (withParts) header += ",E_direct_lx,E_indirect_lx";
  if (sun) header += withParts ? ",E_sun_lx,E_sun_reflected_lx" : ",E_sun_lx";
  if (daylight)
    header +=
        withParts ? ",DF_pct,DF_direct_pct,DF_internal_pct,SC_pct,ERC_pct,IRC_pct" : ",DF_pct";
  return header + ",inside\n";
}

// One point's values as a row holds them.
struct GridRowValues {
  double illuminance = 0.0;        // lx, total
  const double* direct = nullptr;  // lx, its direct part; null: no E_direct/E_indirect columns
  double sun = 0.0;                // lx, the sunlight in E; written with setSunColumn(true)
  double sunReflected = 0.0;       // lx, the sun's light reflected, in E; with `direct` and sun
  // lx, the sky and the externally reflected components, written with `direct` and E_h; null:
  // the split is not known, the direct daylight (direct − sun) is written as SC and ERC is 0
  const double* skyComponent = nullptr;
  const double* externalComponent = nullptr;
};

// Rows of both files, appended point by point into two buffers that keep their memory when
// cleared, so that writing a batch allocates nothing once the buffers have grown to a batch.
class GridRows {
 public:
  // `illuminance`: the digits E is written with (number_text.hpp).
  explicit GridRows(NumberDigits illuminance) : illuminanceDigits_(illuminance) {}
  // With E_h > 0 (lx), rows carry the daylight factor columns; 0: none.
  void setOutdoorIlluminance(double outdoor) { outdoor_ = outdoor; }
  // With a sun, rows carry E_sun_lx and the daylight factor leaves it out.
  void setSunColumn(bool sun) { sunColumn_ = sun; }
  // Appends the point's CSV row and its .res line; `insideField` is already a CSV field.
  void add(const Vec3& position, const Vec3& normal, double illuminance,
           std::string_view insideField);
  // The same with the direct part (and the indirect one, the difference) after E.
  void add(const Vec3& position, const Vec3& normal, double illuminance, double direct,
           std::string_view insideField);
  // The same with any columns (GridRowValues).
  void add(const Vec3& position, const Vec3& normal, const GridRowValues& values,
           std::string_view insideField);
  // Appends the .res line alone.
  void addIlluminance(double illuminance);
  // Appends the .pts line alone.
  void addPoint(const Vec3& position, const Vec3& normal);
  std::string_view csv() const { return {csv_.data(), csv_.size()}; }
  std::string_view res() const { return {res_.data(), res_.size()}; }
  std::string_view pts() const { return {pts_.data(), pts_.size()}; }
  void clear() {
    csv_.clear();
    res_.clear();
    pts_.clear();
  }
  // Room for `points` rows of the common widths (a plain grid's), so that a first batch's
  // buffers are not grown, and copied, by doubling; wider rows grow them as needed.
  void reserve(std::size_t points) {
    csv_.reserve(points * 64);
    res_.reserve(points * 16);
    pts_.reserve(points * 32);
  }

 private:
  void addResLine(const char* text, std::size_t size);
  // Writes the six numbers of a point, each followed by `separator`, at `out` (room for six
  // numbers and separators); returns the end.
  char* writePoint(char* out, const Vec3& position, const Vec3& normal, char separator);
  void addRow(const Vec3& position, const Vec3& normal, const GridRowValues& values,
              std::string_view insideField);

  NumberDigits illuminanceDigits_;
  NumberTextCache numbers_;  // coordinates and normals repeat from row to row
  // The last point's y, z and normal (their bits) and their text with its separators: along a
  // row of a planar grid only x changes, so the rest of a point is copied whole.
  std::uint64_t tailBits_[5] = {};
  char tailText_[5 * (kMaxNumberText + 1)];
  char tailBlankText_[5 * (kMaxNumberText + 1)];  // the same with blanks for separators (.pts)
  std::size_t tailSize_ = 0;                      // 0: nothing kept
  char tailSeparator_ = 0;
  double outdoor_ = 0.0;  // lx: E_h for the daylight factor columns; 0: none
  bool sunColumn_ = false;
  fmt::memory_buffer csv_, res_, pts_;
};

}  // namespace penumbra
