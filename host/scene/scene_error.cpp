#include <string>

#include <fmt/format.h>

#include "scene/scene_loader.hpp"
#include "scene/scene_warning.hpp"

namespace penumbra {

std::string locatedMessage(const std::filesystem::path& file, int line, const std::string& key,
                           const std::string& message) {
  std::string text = file.string();
  if (line > 0) text += fmt::format(":{}", line);
  text += ": ";
  if (!key.empty()) text += key + ": ";
  return text + message;
}

std::string warningText(const std::filesystem::path& file, const SceneWarning& warning) {
  const std::string key = warning.key.empty() ? "" : warning.key + ": ";
  return locatedMessage(file, warning.line, "", "warning: " + key + warning.message);
}

SceneError::SceneError(std::filesystem::path file, int line, std::string key,
                       const std::string& message)
    : std::runtime_error(locatedMessage(file, line, key, message)),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)),
      message_(message) {}

}  // namespace penumbra
