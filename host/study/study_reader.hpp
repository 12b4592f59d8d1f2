#pragma once
// Reading a study file (format in docs/sweeps.md). Errors are SceneErrors naming the study file,
// the line and the key, like a scene's.
#include <filesystem>
#include <string>

#include "study/study.hpp"

namespace penumbra {

// The study format version this reader understands (`penumbra-study: 1`).
inline constexpr int kStudyFormatVersion = 1;

// Reads the study and checks it against its base scene's declared parameters (an unknown name is
// an error that lists the declared ones). Throws SceneError.
Study loadStudy(const std::filesystem::path& file);
// The same from text; `file` names it in messages and anchors the relative scene path.
Study parseStudy(const std::string& yamlText, const std::filesystem::path& file);

}  // namespace penumbra
