#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>

#include "scene/scene.hpp"

namespace penumbra {

// Bad input: names the file, the line (1-based, 0 when unknown) and the key path
// (e.g. "sources[1].flux"), with a message a person can act on.
class SceneError : public std::runtime_error {
 public:
  SceneError(std::filesystem::path file, int line, std::string key, const std::string& message);
  const std::filesystem::path& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }  // without file, line and key

 private:
  std::filesystem::path file_;
  int line_;
  std::string key_;
  std::string message_;
};

// Reads and validates a scene file (format v1, docs/scene-format.md). Throws SceneError.
// `parameters` replace the defaults of the scene's `parameters:` by name; naming one the scene
// does not declare is a SceneError.
Scene loadScene(const std::filesystem::path& file, const ParameterValues& parameters = {});
// The same from text; `file` is used for messages and to resolve relative paths (`.pts`).
Scene parseScene(const std::string& yamlText, const std::filesystem::path& file,
                 const ParameterValues& parameters = {});

// The parameters a scene file declares, with their defaults, without building it. Throws
// SceneError (unreadable file, invalid YAML, invalid `parameters:`).
ParameterValues loadSceneParameters(const std::filesystem::path& file);

}  // namespace penumbra
