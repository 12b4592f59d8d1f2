#pragma once
// Rendering to a PNG file. Debian's VTK renders through X only (docs/building.md): without a
// display it aborts, so callers check first and say how to get one.
#include <filesystem>
#include <string>

#include <vtkRenderer.h>

namespace penumbra::viz {

// Why nothing can be rendered here, with the xvfb-run command line to use, when $DISPLAY is not
// set; "" when it is.
std::string displayUnavailable();

// Throws std::runtime_error with displayUnavailable() when $DISPLAY is not set.
void requireDisplay();

// Renders `renderer` (alone in an off-screen window of width × height px, no multisampling, so
// that colours are exactly those of the lookup table) and writes an 8-bit RGB PNG. Throws
// std::runtime_error when the file cannot be written.
void renderToPng(vtkRenderer* renderer, int width, int height, const std::filesystem::path& png);

}  // namespace penumbra::viz
