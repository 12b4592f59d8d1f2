#pragma once
// The exposure of a sweep's renders (`penumbra sweep --exposure`): each case exposed on its own
// (the default), one white in cd/m² for every case, the automatic exposure of the first case
// rendered, kept for the others, or the automatic exposure of the whole study (auto-all,
// study_exposure.hpp); the last three make the renders of a study compare.
#include <string>

namespace penumbra {

struct RenderExposure {
  bool autoFirst = false;
  bool autoAll = false;  // each case automatic first, then all again with the study's white
  double white = 0;      // cd/m² shown as white; 0 with neither: each case on its own
  bool fixed() const { return autoFirst || autoAll || white > 0; }
};

// "" (each case on its own), "auto-first", "auto-all", or a luminance above 0 in cd/m². Throws
// std::invalid_argument saying what is expected.
RenderExposure parseRenderExposure(const std::string& text);

}  // namespace penumbra
