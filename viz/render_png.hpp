#pragma once
// Rendering to a PNG file. Debian's VTK renders through X only (docs/building.md): without a
// display it aborts, so callers check first and say how to get one.
#include <filesystem>

#include <vtkRenderer.h>

namespace penumbra::viz {

// Throws std::runtime_error, with the xvfb-run command line to use, when $DISPLAY is not set.
void requireDisplay();

// Renders `renderer` (alone in an off-screen window of width × height px, no multisampling, so
// that colours are exactly those of the lookup table) and writes an 8-bit RGB PNG. Throws
// std::runtime_error when the file cannot be written.
void renderToPng(vtkRenderer* renderer, int width, int height, const std::filesystem::path& png);

}  // namespace penumbra::viz
