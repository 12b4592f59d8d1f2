#include "study/study_cases.hpp"

#include <charconv>
#include <stdexcept>

#include <fmt/format.h>

#include "scene/scene_loader.hpp"

namespace penumbra {
namespace {

std::vector<ParameterValues> gridCombinations(const std::vector<StudyParameter>& parameters) {
  std::vector<ParameterValues> combinations{{}};
  for (const StudyParameter& p : parameters) {
    std::vector<ParameterValues> next;
    for (const ParameterValues& prefix : combinations) {
      for (double v : p.values) {
        next.push_back(prefix);
        next.back().push_back(ParameterValue{p.name, v});
      }
    }
    combinations = std::move(next);
  }
  return combinations;
}

std::vector<ParameterValues> zipCombinations(const Study& study) {
  const StudyParameter& first = study.parameters.front();
  for (const StudyParameter& p : study.parameters) {
    if (p.values.size() != first.values.size()) {
      throw SceneError(study.file, study.combinationWhere.line, "combination",
                       fmt::format("'zip' takes the i-th value of every parameter together, so "
                                   "all have as many values, but {} has {} and {} has {}",
                                   first.name, first.values.size(), p.name, p.values.size()));
    }
  }
  std::vector<ParameterValues> combinations(first.values.size());
  for (const StudyParameter& p : study.parameters) {
    for (std::size_t i = 0; i < p.values.size(); ++i) {
      combinations[i].push_back(ParameterValue{p.name, p.values[i]});
    }
  }
  return combinations;
}

// A study of a million cases is a typo, not a plan.
constexpr std::size_t kMaxCases = 100000;

}  // namespace

std::vector<StudyCase> studyCases(const Study& study) {
  if (study.combination == Combination::Grid) {
    double count = 1.0;
    for (const StudyParameter& p : study.parameters) count *= static_cast<double>(p.values.size());
    if (count > static_cast<double>(kMaxCases)) {
      throw SceneError(study.file, study.parametersWhere.line, "parameters",
                       fmt::format("every combination of these values makes {:.0f} cases, more "
                                   "than the limit of {}",
                                   count, kMaxCases));
    }
  }
  const std::vector<ParameterValues> combinations = study.combination == Combination::Grid
                                                        ? gridCombinations(study.parameters)
                                                        : zipCombinations(study);
  const int width = std::max<int>(3, static_cast<int>(std::to_string(combinations.size()).size()));
  std::vector<StudyCase> cases;
  for (std::size_t i = 0; i < combinations.size(); ++i) {
    cases.push_back(StudyCase{i, fmt::format("case-{:0{}}", i + 1, width), combinations[i]});
  }
  return cases;
}

Shard parseShard(std::string_view text) {
  const std::string message =
      "--shard " + std::string(text) + ": expected i/N with 1 <= i <= N, e.g. 2/4";
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) throw std::invalid_argument(message);
  const auto number = [&](std::string_view part) {
    int value = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (error != std::errc() || end != part.data() + part.size()) {
      throw std::invalid_argument(message);
    }
    return value;
  };
  const Shard shard{number(text.substr(0, slash)), number(text.substr(slash + 1))};
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    throw std::invalid_argument(message + (shard.index == 0 ? " (shards count from 1)" : ""));
  }
  return shard;
}

}  // namespace penumbra
