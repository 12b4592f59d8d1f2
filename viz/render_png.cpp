#include "viz/render_png.hpp"

#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <stdexcept>

namespace penumbra::viz {

std::string displayUnavailable() {
  const char* display = std::getenv("DISPLAY");
  if (display != nullptr && *display != '\0') return "";
  return "plots are rendered through X and no display is set ($DISPLAY is empty); on a machine "
         "without one, run the command under a virtual X server:\n"
         "  xvfb-run -a -s \"-screen 0 1920x1080x24 -noreset\" penumbra ...";
}

void requireDisplay() {
  if (const std::string why = displayUnavailable(); !why.empty()) throw std::runtime_error(why);
}

void renderToPng(vtkRenderer* renderer, int width, int height, const std::filesystem::path& png) {
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  window->Render();

  auto capture = vtkSmartPointer<vtkWindowToImageFilter>::New();
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  capture->Update();

  auto writer = vtkSmartPointer<vtkPNGWriter>::New();
  writer->SetFileName(png.string().c_str());
  writer->SetInputConnection(capture->GetOutputPort());
  writer->Write();
  // The renderer may be rendered again into another window; let this one go first.
  window->RemoveRenderer(renderer);
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(png)) {
    throw std::runtime_error("cannot write " + png.string());
  }
}

}  // namespace penumbra::viz
