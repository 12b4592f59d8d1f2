#pragma once
// JSON has no NaN: an undefined metric (no points, or U0 with Eavg = 0) is written as null, and
// null reads back as NaN.
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace penumbra {

template <class Json = nlohmann::json>
Json jsonNumber(double value) {
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

template <class Json>
double numberFromJson(const Json& json) {
  return json.is_null() ? std::numeric_limits<double>::quiet_NaN() : json.template get<double>();
}

}  // namespace penumbra
