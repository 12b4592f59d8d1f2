#pragma once
// The UGR map of an observer grid (docs/glare.md, "UGR maps"): each eye's UGR_max (the largest
// over its lines of sight) in false colour over the grid, the EN 12464-1 limit drawn as an
// isoline, with the method in the title. Drawn by `penumbra plot` on the folder of
// `penumbra glare`, from its summary.json, with the heat map of illuminance grids (heat_map.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "viz/heat_map.hpp"
#include "viz/planar_field.hpp"

namespace penumbra::viz {

// One map's data: the eyes of one `grid:` observer entry as a lattice, UGR_max per eye (valid 0
// where the eye has no UGR: no glare source in range, or no background).
struct UgrGrid {
  std::string entry;
  PlanarField field;
  int undefined = 0;  // eyes without a UGR
};

// The observer grids in a glare summary.json (entries whose observers are named entry[c,r], at
// least 2 x 2 eyes); single eyes and single rows are left out. Throws std::runtime_error when the
// JSON is not a glare summary.
std::vector<UgrGrid> ugrGrids(const nlohmann::json& summary);

// "<entry>-ugr.png".
std::string ugrMapFileName(const std::string& entry);

// Draws the map of `grid` to `png`, the limit `limit` (UGR_L) as the isoline.
HeatMapFigure drawUgrMap(const UgrGrid& grid, const Scene& scene, double limit, int width,
                         const std::string& subtitle, const std::filesystem::path& png);

}  // namespace penumbra::viz
