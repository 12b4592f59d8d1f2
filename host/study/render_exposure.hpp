#pragma once
// The exposure of a sweep's renders (`penumbra sweep --exposure`): each case exposed on its own
// (the default), one white in cd/m² for every case, or the automatic exposure of the first case
// rendered, kept for the others; the last two make the renders of a study compare.
#include <string>

namespace penumbra {

struct RenderExposure {
  bool autoFirst = false;
  double white = 0;  // cd/m² shown as white; 0 with !autoFirst: each case on its own
  bool fixed() const { return autoFirst || white > 0; }
};

// "" (each case on its own), "auto-first", or a luminance above 0 in cd/m². Throws
// std::invalid_argument saying what is expected.
RenderExposure parseRenderExposure(const std::string& text);

}  // namespace penumbra
