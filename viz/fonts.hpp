#pragma once
// The typeface of every label: DejaVu Sans (Debian's fonts-dejavu-core), which has every glyph
// the labels use; VTK's built-in Arial draws "[" as "(", which would turn "E [lx]" into "E (lx)".
#include <vtkTextProperty.h>

namespace penumbra::viz {

// Sets the font of `text` (falls back to VTK's Arial when the font file is missing).
void useLabelFont(vtkTextProperty* text, bool bold);

}  // namespace penumbra::viz
