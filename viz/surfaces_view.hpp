#pragma once
// The room's surfaces in false colour, seen in perspective from above one corner (cutaway.hpp),
// with the faces outlined, the light sources drawn, and the same legend as the heat maps.
#include <filesystem>
#include <string>

#include <vtkPolyData.h>

#include "scene/scene.hpp"
#include "viz/colour_scale.hpp"

namespace penumbra::viz {

struct SurfacesStyle {
  ColourScale scale;
  int width = 1600;      // px; the height is 5/8 of it
  std::string subtitle;  // scene, spacing
};

// `surfaces` as surfacePolyData makes it. Needs a display (render_png.hpp). Returns the
// height of the image in px.
int drawSurfaces(const Scene& scene, vtkPolyData* surfaces, const SurfacesStyle& style,
                 const std::filesystem::path& png);

}  // namespace penumbra::viz
