#pragma once
// Iso-band vector drawings (Conway & Cottingham's isoluminance laminae, as SVG): every surface is
// split by its isolux contours into bands of constant colour (the legend's colour of the band),
// drawn as filled polygons with thin contour lines. For a view, every face that faces the camera
// is drawn whole, the faces back to front (the painter's algorithm), so nearer faces cover farther
// ones; for a planar grid, the calculation area in plan. The number of bands bounds the size of
// the file, not the resolution of an image. No display needed: these are text files.
#include <filesystem>
#include <span>
#include <vector>

#include "grid/iso_bands.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"
#include "viz/point_light.hpp"
#include "viz/rgb.hpp"

namespace penumbra::viz {

// Isolux levels: the 1-2-5 series below `eMax` lx, at most `bands` - 1 of them (the top ones).
std::vector<double> isobandLevels(double eMax, int bands);
// The colour of band `band` of `bandCount`: the legend's palette at the middle of the band.
Rgb bandRgb(int band, int bandCount);

struct IsobandFigure {
  std::vector<double> levels;  // lx
  std::size_t polygons = 0, contourSegments = 0, faces = 0;
};

// `spacing` (m): the mesh on each face (0: a 50th of the scene's size).
IsobandFigure writeViewIsobands(const Scene& scene, const View& view, const PointLight& light,
                                int bands, const std::filesystem::path& svg, double spacing = 0.0);

// The raster counterpart of the drawing: each pixel of a render in the colour of its E's band
// (sources white, nothing black), for comparing the two and for a quick look.
DisplayImage bandedRaster(const RenderedView& rendered, const Scene& scene,
                          std::span<const double> levels);

// <view>.svg (writeViewIsobands) and <view>.isobands.png (bandedRaster, the same levels) into
// `folder`.
IsobandFigure writeViewIsobandFiles(const Scene& scene, const RenderedView& rendered,
                                    const PointLight& light, int bands,
                                    const std::filesystem::path& folder);

// A planar grid (rows × columns of points) with its E (lx) per point, in plan.
IsobandFigure writeGridIsobands(const CalculationGrid& grid, std::span<const double> illuminance,
                                const PointLight& light, int bands,
                                const std::filesystem::path& svg, int widthPx = 1200);

// The faces of a view as the drawing has them (exposed for the tests): per convex piece of a face
// that faces the eye and that no other solid covers, its mesh, the E at the mesh's vertices and
// its bands.
struct FaceBands {
  int solid = -1, face = -1;
  ConvexPolygon polygon;
  TriangleMesh mesh;
  std::vector<double> illuminance;
  IsoBands bands;
};
std::vector<FaceBands> viewFaceBands(const Scene& scene, const View& view, const PointLight& light,
                                     std::vector<double>& levels, int bands, double spacing);

}  // namespace penumbra::viz
