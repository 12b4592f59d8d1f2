#pragma once
// The cases of a study: one set of parameter values each, with a stable id, and which of them a
// shard (`--shard i/N`) runs.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "scene/parameters.hpp"
#include "study/study.hpp"

namespace penumbra {

struct StudyCase {
  std::size_t index = 0;   // 0-based, in case order
  std::string id;          // "case-007": 1-based, zero-padded to the width of the last id
  ParameterValues values;  // the study's parameters, in its order
};

// grid: the first parameter varies slowest; zip: lists of different lengths are a SceneError at
// the study's `combination` naming both parameters and their lengths.
std::vector<StudyCase> studyCases(const Study& study);

// Shard i of N (1 ≤ i ≤ N) runs the cases whose index is i-1 modulo N: every N-th case, so that
// shards get a similar mix of cheap and costly cases.
struct Shard {
  int index = 1;
  int count = 1;
  bool contains(std::size_t caseIndex) const {
    return static_cast<int>(caseIndex % static_cast<std::size_t>(count)) == index - 1;
  }
};

// "2/4" → {2, 4}. Throws std::invalid_argument with a message for anything else.
Shard parseShard(std::string_view text);

}  // namespace penumbra
