#pragma once
// The per-case plots of a sweep (`plots: true` in a study file): the pictures and ParaView files
// `penumbra grid --plot` draws, drawn into each case's staged folder through the sweep runner's
// output hook (output/case_output.hpp). main.cpp hands one to `penumbra sweep`.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "illuminance/estimator.hpp"
#include "output/case_output.hpp"
#include "viz/plot_options.hpp"

namespace penumbra::viz {

class CasePlots : public CaseOutputWriter {
 public:
  // `options` as for `penumbra plot` (the defaults: each case's legend from its own values). The
  // device is options.device.
  explicit CasePlots(PlotOptions options);
  ~CasePlots() override;

  std::string name() const override { return "plots"; }
  // Without a display VTK aborts: then the sweep runs without plots and says how to get them.
  std::string unavailable() const override;
  // Writes the .vti/.vtp (and .svg) files; returns the images: <grid>.svg where asked for, and
  // the PNGs drawPictures draws (<grid>.png per planar grid, surfaces.png).
  std::vector<std::string> write(const Scene& scene, const RunReport& report,
                                 const std::filesystem::path& directory) override;
  // The PNGs, in a child process (drawPlotPictures).
  PicturesWritten drawPictures(const Scene& scene, const std::filesystem::path& directory) override;

 private:
  PlotOptions options_;
  // Opened at the first case that needs it and kept: the program is built once per sweep, as the
  // runner does for the grids, and a case that keeps the geometry reuses the interreflection's
  // transfer; each case's scene replaces the previous one on it.
  std::unique_ptr<Estimator> estimator_;
};

}  // namespace penumbra::viz
