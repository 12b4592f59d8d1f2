#pragma once
// What one `penumbra grid` run produced, in the form the output layer writes: self-contained (no
// Scene needed), so that it can be written, printed and tested on its own.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/sample_point.hpp"
#include "grid/grid_evaluation.hpp"
#include "grid/grid_metrics.hpp"
#include "radiosity/interreflection.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct GridReport {
  std::string name;
  // The layout, so that plots (viz/) can rebuild the grid from the files: planar grids are
  // row-major, `columns` along u, `rows` along v; 0 × 0 for point lists.
  GridKind kind = GridKind::Points;
  int columns = 0, rows = 0;
  // Planar grids: the distance between neighbouring points along u and along v, m (the cells of
  // |u| / columns × |v| / rows; the scene's spacing is the largest either may be). 0 for point
  // lists.
  double spacingU = 0.0, spacingV = 0.0;
  // Per point, in the grid's order. Empty when the points went to the files batch by batch
  // (`penumbra grid`, streamGrid): summary.json and the table need only the rest.
  std::vector<SamplePoint> points;
  std::vector<std::string> insideSolids;  // the containing solid's name, "" for none
  std::vector<double> illuminance;        // lx, total; 0 inside solids
  std::vector<double> direct;             // lx, its direct part; empty for a direct-only run
  std::vector<double> sun;                // lx, the direct sunlight in E; empty without a sun
  std::vector<double> sunReflected;       // lx, the sun's light reflected, in E; empty without
  // lx, the sky and the externally reflected components (GridBatch); empty without them
  std::vector<double> skyComponent, externalComponent;
  GridMetrics metrics;                       // of the total
  std::optional<GridMetrics> directMetrics;  // of the direct part, when interreflection is on
  std::optional<DaylightMetrics> daylight;   // when the scene has a sky; excludes the sun
  std::optional<SunMetrics> sunMetrics;      // when the scene has a sun
  // Read back from a CSV with a sky (readResults): DF_pct per point, %, and DF_direct_pct with
  // interreflection; empty otherwise. The run itself writes them from E.
  std::vector<double> daylightFactor, daylightFactorDirect;
  // Read back with interreflection: SC_pct and ERC_pct per point, %.
  std::vector<double> skyComponentFactor, externalComponentFactor;
  double seconds = 0.0;  // time spent computing E for this grid
};

// The scene's sun as the run places it (scene.hpp, Sun).
struct SunReport {
  double azimuthDegrees = 0.0;           // ° from north towards east
  double elevationDegrees = 0.0;         // °, apparent
  double directNormalIlluminance = 0.0;  // lx: E_dn
  bool aboveHorizon = true;              // below it the sun gives no light
};

// The scene's sky as the run takes it (scene.hpp, Sky).
struct SkyReport {
  std::string model;                   // "uniform", "cie-overcast", "cie-general"
  double horizontalIlluminance = 0.0;  // lx: E_h, unobstructed, the daylight factor's base
  double groundReflectance = 0.0;      // ρ_g
  // cie-general: the CIE standard general sky type (1..15), the subdivision m and the number of
  // patches the sky is divided into (144 m² + 1; Tregenza's 145 for m = 1); 0 for the others.
  int cieType = 0, subdivision = 0, patches = 0;
};

// A photometric luminaire of the scene as summary.json lists it.
struct LuminaireReport {
  std::string name;
  std::string file;          // as resolved against the scene file
  std::string format;        // "IES LM-63", "EULUMDAT"
  int instances = 1;         // placed copies (an array's count)
  double lampLumens = 0.0;   // lm per instance, after the flux override (0: absolute photometry)
  double zonalFluxLm = 0.0;  // lm per instance from the table, before the maintenance factor
  double maintenanceFactor = 1.0;
  std::string model;  // "point", "area"
  // The area model's luminance fit (photometry/luminance_fit.hpp): its order, its error at the
  // table's nodes relative to the peak, and the opening's cells along its length and width
  // (1 × 1: the fit integrated exactly; more: point sources over the opening, the fit's error
  // being too large).
  int fitOrder = -1;  // -1: the point model, no fit
  double fitError = 0.0;
  int partsAlongLength = 1, partsAlongWidth = 1;
};

struct RunReport {
  std::string version;              // penumbra's
  std::filesystem::path sceneFile;  // as given on the command line
  ParameterValues parameters;       // the scene's parameters as computed (defaults or --set)
  std::string estimator;            // "kernel" or "reference"
  int referenceN = 0;               // the reference's n (sub-elements per face ~ n²); 0 for kernel
  std::string device;               // what computed it, in words
  double loadSeconds = 0.0;         // reading and validating the scene
  double setupSeconds = 0.0;        // device selection, program build, scene upload
  double totalSeconds = 0.0;        // the whole run before writing
  // The interreflection solver's report; empty when the run is direct light only.
  std::optional<InterreflectionReport> interreflection;
  // The scene's warnings, each as printed ("office.yaml:31: warning: sources[1]: ...").
  std::vector<std::string> warnings;
  std::vector<LuminaireReport> luminaires;
  std::optional<SkyReport> sky;  // when the scene has a sky
  std::optional<SunReport> sun;  // when the scene has a sun
  std::vector<GridReport> grids;
};

// The report of a streamed grid: its layout, metrics and time, no per-point data.
GridReport streamedGridReport(const CalculationGrid& grid, const GridRun& run);

}  // namespace penumbra
