#pragma once
// Colours as RGB in [0, 1], and the few fixed ones every picture uses.
#include <array>

namespace penumbra::viz {

using Rgb = std::array<double, 3>;

inline constexpr Rgb kInk{0.12, 0.12, 0.12};  // text, frames, lines: near black, softer on white
inline constexpr Rgb kWhite{1.0, 1.0, 1.0};
inline constexpr Rgb kSubtle{0.35, 0.35, 0.35};     // notes and names that must not shout
inline constexpr Rgb kSourceEdge{0.85, 0.45, 0.0};  // luminaires and windows: warm orange

}  // namespace penumbra::viz
