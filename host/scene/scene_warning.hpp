#pragma once
// A scene that loads but is probably not what its author meant (a source whose light reaches
// nothing, a grid outside the room): loading goes on, and every command shows the warning.
#include <filesystem>
#include <string>

namespace penumbra {

struct SceneWarning {
  int line = 0;     // 1-based line in the scene file, 0 when unknown
  std::string key;  // the entry it is about, e.g. "sources[2]"
  std::string message;
};

// "office.yaml:31: sources[1]: message": the located form of every scene message, which editors
// and terminals turn into a link to the line.
std::string locatedMessage(const std::filesystem::path& file, int line, const std::string& key,
                           const std::string& message);

// "office.yaml:31: warning: sources[1]: source 'panel-1' ...".
std::string warningText(const std::filesystem::path& file, const SceneWarning& warning);

}  // namespace penumbra
