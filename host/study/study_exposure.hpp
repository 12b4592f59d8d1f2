#pragma once
// `sweep --exposure auto-all`: one white for every render of the study, chosen from all of them.
// Each case is rendered and exposed on its own first (clip, automatic); once the cases are
// written, every display PNG is made again from its case's luminance (.exr) with the study's
// white: the geometric mean of the pictures' automatic whites, each picture of each case weighed
// alike. The clip display's automatic white is the log average of a picture's lit luminance over
// 18 %, so this is the white of the log average over the whole study, and the same luminance is
// the same pixel value in every case.
#include <filesystem>

#include "study/study_layout.hpp"

namespace penumbra {

// Where the study's white is kept, beside the cases (OUT/exposure.json, as auto-first keeps its).
struct StudyExposure {
  double white = 0;  // cd/m² shown as white; 0 when the study has no renders yet
  int pictures = 0;  // the display PNGs exposed with it
};

// Whether `layout` asks for its renders exposed as one (an output "renders:... exposure=auto-all").
bool exposedAsOne(const StudyLayout& layout);

// Exposes the renders of every finished case folder under `out` (those with a render.json) with
// the study's white, rewrites their PNGs and tone map statistics, and writes OUT/exposure.json.
StudyExposure exposeStudyRenders(const std::filesystem::path& out, const StudyLayout& layout);

}  // namespace penumbra
