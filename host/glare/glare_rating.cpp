#include "glare/glare_rating.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "glare/position_index.hpp"

namespace penumbra {

double GlareRating::sum() const {
  double total = 0.0;
  for (const GlareTerm& term : terms) total += term.value();
  return total;
}

std::optional<double> unifiedGlareRating(double sum, double backgroundLuminance) {
  if (!(backgroundLuminance > 0.0) || !(sum > 0.0)) return std::nullopt;
  return 8.0 * std::log10(0.25 / backgroundLuminance * sum);
}

GlareRating rateView(const EyeView& view, const Vec3& look, double backgroundLuminance) {
  GlareRating rating;
  rating.look = look.normalized();
  rating.backgroundLuminance = backgroundLuminance;
  rating.withoutArea = view.withoutArea;
  const SightFrame sight = SightFrame::along(look);
  for (const SeenSource& source : view.sources) {
    const std::optional<double> p = guthPositionIndex(sourcePosition(sight, source.toCentre));
    if (!p) {
      ++rating.outsideRange;
      continue;
    }
    rating.terms.push_back(
        GlareTerm{source.name, source.luminance, source.solidAngle, source.farFieldAngle, *p});
  }
  std::stable_sort(rating.terms.begin(), rating.terms.end(),
                   [](const GlareTerm& a, const GlareTerm& b) { return a.value() > b.value(); });
  rating.ugr = unifiedGlareRating(rating.sum(), backgroundLuminance);
  return rating;
}

std::optional<int> strictestLimitMet(double ugr) {
  constexpr std::array<int, 5> kLimits{16, 19, 22, 25, 28};
  for (const int limit : kLimits) {
    if (ugr <= limit) return limit;
  }
  return std::nullopt;
}

}  // namespace penumbra
