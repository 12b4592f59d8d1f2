#pragma once
// VTK XML files (what ParaView opens): binary, appended, zlib-compressed; lossless, so that
// doubles read back bit for bit.
#include <filesystem>

#include <vtkImageData.h>
#include <vtkPolyData.h>

namespace penumbra::viz {

// Throw std::runtime_error naming the file when it cannot be written.
void writeImageDataFile(vtkImageData* data, const std::filesystem::path& file);
void writePolyDataFile(vtkPolyData* data, const std::filesystem::path& file);

}  // namespace penumbra::viz
