// libFuzzer target: study text (penumbra-study: 1) → a study checked against its base scene, or
// one SceneError. The file name sits in the source tree's studies/ so that `scene:
// ../data/office.yaml` resolves as it does for the shipped studies.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "study/study_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::path(PENUMBRA_SOURCE_DIR) / "studies" / "fuzz.yaml";
  const std::string text(reinterpret_cast<const char*>(data), size);
  penumbra::fuzz::expectValueOrSceneError([&] { penumbra::parseStudy(text, file); });
  return 0;
}
