#include "viz/fonts.hpp"

#include <filesystem>

namespace penumbra::viz {

void useLabelFont(vtkTextProperty* text, bool bold) {
  const char* file = bold ? "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"
                          : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (std::filesystem::exists(file)) {
    text->SetFontFamily(VTK_FONT_FILE);
    text->SetFontFile(file);
  } else {
    text->SetFontFamilyToArial();
  }
  text->SetBold(bold);
}

}  // namespace penumbra::viz
