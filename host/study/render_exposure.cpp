#include "study/render_exposure.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace penumbra {

RenderExposure parseRenderExposure(const std::string& text) {
  RenderExposure exposure;
  if (text.empty()) return exposure;
  if (text == "auto-first") {
    exposure.autoFirst = true;
    return exposure;
  }
  if (text == "auto-all") {
    exposure.autoAll = true;
    return exposure;
  }
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, exposure.white);
  if (error != std::errc() || stop != end || !(exposure.white > 0) ||
      !std::isfinite(exposure.white)) {
    throw std::invalid_argument("'" + text +
                                "': expected a luminance above 0 in cd/m2 (shown as white) or "
                                "auto-first or auto-all");
  }
  return exposure;
}

}  // namespace penumbra
