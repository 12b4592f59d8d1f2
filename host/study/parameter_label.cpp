#include "study/parameter_label.hpp"

#include <array>
#include <utility>

namespace penumbra {
namespace {

// The suffixes a name may end with, and the unit each stands for. Only units a lighting study
// varies; an unknown suffix stays part of the name rather than being guessed at.
constexpr std::array<std::pair<std::string_view, std::string_view>, 12> kUnitSuffixes{{
    {"m", "m"},
    {"mm", "mm"},
    {"cm", "cm"},
    {"lm", "lm"},
    {"lx", "lx"},
    {"cdm2", "cd/m²"},
    {"cd", "cd"},
    {"deg", "°"},
    {"K", "K"},
    {"W", "W"},
    {"s", "s"},
    {"pct", "%"},
}};

// The name before its unit suffix, when it has one ("window_width_m" → "window_width").
std::string_view withoutUnit(std::string_view name, std::string_view& unit) {
  const std::size_t underscore = name.rfind('_');
  unit = {};
  if (underscore == std::string_view::npos || underscore == 0) return name;
  const std::string_view suffix = name.substr(underscore + 1);
  for (const auto& [text, symbol] : kUnitSuffixes) {
    if (suffix == text) {
      unit = symbol;
      return name.substr(0, underscore);
    }
  }
  return name;
}

}  // namespace

std::string parameterUnit(std::string_view name) {
  std::string_view unit;
  withoutUnit(name, unit);
  return std::string(unit);
}

std::string parameterLabel(std::string_view name) {
  std::string_view unit;
  std::string label(withoutUnit(name, unit));
  for (char& c : label) {
    if (c == '_') c = ' ';
  }
  return unit.empty() ? label : label + " [" + std::string(unit) + "]";
}

}  // namespace penumbra
