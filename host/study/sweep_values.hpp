#pragma once
// The values one study parameter takes: `[1.2, 1.6]`, `{values: [..]}`,
// `{range: {from, to, step}}` or `{linspace: {from, to, count}}`.
#include <vector>

#include "scene/yaml_reader.hpp"

namespace penumbra {

// Throws SceneError at the offending key: an empty list or range, a zero step, a step that
// leads away from `to`, a count below 1, more than kMaxSweepValues values, a value given twice.
std::vector<double> readSweepValues(const scenefile::Reader& reader, const scenefile::Field& field);

// A typo (step 0.001 instead of 0.1) must not plan a million cases.
inline constexpr std::size_t kMaxSweepValues = 10000;

}  // namespace penumbra
