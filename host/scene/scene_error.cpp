#include <string>

#include <fmt/format.h>

#include "scene/scene_loader.hpp"

namespace penumbra {
namespace {

// "office.yaml:12: sources[1].flux: must not be negative": the form compilers use, which
// editors and terminals turn into a link to the line.
std::string describe(const std::filesystem::path& file, int line, const std::string& key,
                     const std::string& message) {
  std::string text = file.string();
  if (line > 0) text += fmt::format(":{}", line);
  text += ": ";
  if (!key.empty()) text += key + ": ";
  return text + message;
}

}  // namespace

SceneError::SceneError(std::filesystem::path file, int line, std::string key,
                       const std::string& message)
    : std::runtime_error(describe(file, line, key, message)),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)),
      message_(message) {}

}  // namespace penumbra
