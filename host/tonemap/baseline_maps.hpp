#pragma once
// The two straightforward maps of the thesis (Fig. 4.1(b), (c)), as display V per pixel, so that
// they reach the PNG through the same HSV → RGB → device path as the constraint map.
#include "image/images.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/region_map.hpp"

namespace penumbra {

// Linear (eq. 4.2 with D_min = LowerBound, D_max = 1): exactly the Space-3 V.
ScalarImage linearDisplayValues(const DisplaySpaces& spaces);

// Clip: a camera's exposure, then what falls outside the display is cut to its limits: V =
// V₀ / white in [LowerBound, 1], `white` in cd/m². The same white gives the same V for the same
// cd/m² in every picture.
ScalarImage clipDisplayValues(const DisplaySpaces& spaces, double white);

// The usual automatic exposure: the white (cd/m²) that puts the log-average Space-0 V of the
// surfaces at 18 % of white (photographic middle grey); the window then clips to white and the
// shadows to black.
double automaticWhite(const DisplaySpaces& spaces, const RegionMap& regions);

}  // namespace penumbra
