#include "viz/xml_files.hpp"

#include <vtkSmartPointer.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <stdexcept>

namespace penumbra::viz {

namespace {

template <typename Writer, typename Data>
void writeXml(Data* data, const std::filesystem::path& file) {
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetInputData(data);
  writer->SetFileName(file.string().c_str());
  writer->SetDataModeToAppended();
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

void writeImageDataFile(vtkImageData* data, const std::filesystem::path& file) {
  writeXml<vtkXMLImageDataWriter>(data, file);
}

void writePolyDataFile(vtkPolyData* data, const std::filesystem::path& file) {
  writeXml<vtkXMLPolyDataWriter>(data, file);
}

}  // namespace penumbra::viz
