#pragma once
// Interreflected illuminance: the scene's lit faces as secondary Lambertian sources. The faces
// are cut into elements (surface_mesh), the transfer between elements is the kernel's exact
// occluded contour integral averaged over each receiving element (element_transfer), the
// radiosity equations are solved per RGB channel (radiosity_solver), and the indirect E at any
// point is the kernel's exact integral over every element at its solved luminance (the final
// gather: no interpolation between points). Faces outside the room (an obstruction's, the
// room's outer faces: scene/daylight.hpp, outsideRoom) are elements too, lit by the sky, the
// ground and the sun in front of them (HostLight); their light enters through the openings'
// glazing at its transmittance τ, so their luminance is solved as the room sees it, τ times their
// own, by scaling their direct light: exact for what they send into the room and exchange among
// themselves; the light the room sends out to them counts τ⁻² times too much (none at τ = 1),
// a term small beside the sky and ground their faces see. The sun's direct light on the
// elements
// (HostLight::sun) is a right-hand side of its own, solved alone and added, so that
// its part of the indirect E is known (the daylight factor leaves it out); the mesh follows the
// other light only, so a scene's daylight factor does not depend on its sun. A scene lit by the
// sun alone (no sky, no sources) has no mesh and its sunlight is not interreflected.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "radiosity/host_light.hpp"
#include "radiosity/radiosity_solver.hpp"
#include "radiosity/surface_mesh.hpp"
#include "radiosity/transfer_cache.hpp"
#include "scene/scene.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {

// What the solver did, for summary.json and the terminal.
struct InterreflectionReport {
  std::size_t elements = 0;
  double elementSize = 0.0;              // m, the longest side an element may have
  std::size_t nodes = 0;                 // quadrature nodes, where the transfer is evaluated
  double surfaceArea = 0.0;              // m², all elements
  double residual = 0.0;                 // of the linear solve, relative
  double meshSeconds = 0.0;              // faces reached, cut into elements, direct E at nodes
  double transferSeconds = 0.0;          // element-to-element transfer (kernel); 0 when reused
  double solveSeconds = 0.0;             // the linear solve (BiCGSTAB), every channel
  bool transferReused = false;           // the geometry's transfer came from the cache
  bool refinementCapped = false;         // refinement stopped at MeshOptions::maxElements
  std::size_t links = 0;                 // hierarchical links; 0 for the dense transfer
  double linkError = 0.0;                // the links' error bound; 0 for the dense transfer
  std::vector<std::string> blackSolids;  // reached by light, no material: black
  // The final gather took each element's luminance linear across it (luminance_slopes.hpp);
  // otherwise uniform at its mean (MeshOptions::linearGather).
  bool linearGather = false;

  // Above 0: the dense transfer was asked for, but its mesh had this many elements before any
  // refinement, more than MeshOptions::maxElements; hierarchical links at the default bound
  // (MeshOptions::kDefaultLinkError) took its place.
  std::size_t denseElements = 0;
};

// Interreflected E at points, and the part of it that comes from the sun.
struct InterreflectedIlluminance {
  std::vector<double> total;    // lx
  std::vector<double> fromSun;  // lx, part of total; empty without a sun
  // lx, part of total, not of fromSun: the light that elements outside the room (an
  // obstruction's faces, scene/daylight.hpp outsideRoom) reflect straight to the point, the
  // externally reflected component's share of the interreflection; empty when no element is
  // outside.
  std::vector<double> fromOutside;
};

class Interreflection {
 public:
  // Solves the radiosity equations for `scene` (which must outlive this object). `direct`
  // answers for `scene` (its direct illuminance); its device runs the element kernels too.
  // `engine` are the options of the element kernels (the transfer and the gather). With a
  // `cache`, the transfer of a geometry met before is taken from it, a new one is put in it.
  // `host`: direct light the engine does not hold (host_light.hpp), the sky past obstructions
  // and the sun.
  Interreflection(compute::Device& device, const Scene& scene, IlluminanceEngine& direct,
                  const MeshOptions& mesh = {}, const EngineOptions& engine = {},
                  TransferCache* cache = nullptr, const HostLight& host = {});
  ~Interreflection();

  // Interreflected E in lx at each point (the photometric sum of the channels), the sun's
  // included.
  std::vector<double> indirect(std::span<const SamplePoint> points);
  // The same with the sun's part, from one gather (the sun's light reflected by the room, solved
  // alone since the system is linear; the daylight factor leaves it out).
  InterreflectedIlluminance indirectParts(std::span<const SamplePoint> points);
  // Interreflected E per RGB channel at each point (lx; L = ρ_c·E_c/π as for a source's
  // colour), from the same gather: each element's part weighted by its solved luminance in that
  // channel, the sun's included: the photometric sum of the channels is indirect() to double
  // rounding.
  std::vector<Eigen::Vector3d> indirectChannels(std::span<const SamplePoint> points);

  const SurfaceMesh& mesh() const { return mesh_; }
  // The solution for every light but the sun.
  const RadiositySolution& solution() const { return solution_; }
  // lx, the element-average direct sunlight; empty without a sun.
  const Eigen::VectorXd& sunDirect() const { return sunDirect_; }
  // Element-average direct E per channel, lx, the sun's left out.
  const Eigen::MatrixX3d& direct() const { return direct_; }
  const InterreflectionReport& report() const { return report_; }

 private:
  // Σ_j E_j(P)·luminance(j, c) at every point P for every column c, E_j the kernel's E from
  // element j at 1 cd/m²: points × columns, lx. `luminance` as the room sees it (the elements
  // outside at τ times their own); at points outside the room each element's light comes as seen
  // from there: the elements outside at their own, those inside at τ times theirs.
  // `sunPart`: the sun's part of each column of `luminance` (the same shape), or empty where the
  // scene has no sun; the final gather's slopes take each part's own shares.
  Eigen::MatrixXd gather(std::span<const SamplePoint> points, const Eigen::MatrixXd& luminance,
                         const Eigen::MatrixXd& sunPart);
  // The same sum with no regard to the openings' glazing.
  Eigen::MatrixXd gatherElements(std::span<const SamplePoint> points,
                                 const Eigen::MatrixXd& luminance, const Eigen::MatrixXd& sunPart);
  // The element-average direct light and the mesh's part of the report, once the mesh is final.
  void finishMesh(const Scene& scene, const HostLight& host, const Eigen::MatrixX3d& nodeDirect,
                  double elementSize, Clock::time_point start);
  // Keeps the luminance of the sun's solution (solved alone), per channel and photometric.
  void addSun(const Eigen::MatrixX3d& luminance);
  // The constructor's work with hierarchical links (MeshOptions::linkError > 0).
  void solveHierarchically(compute::Device& device, const Scene& scene, IlluminanceEngine& direct,
                           const MeshOptions& mesh, const EngineOptions& engine,
                           TransferCache* cache, const HostLight& host);

  SurfaceMesh mesh_;
  std::shared_ptr<GeometryTransfer> geometry_;  // null when there are no elements
  Eigen::VectorXd luminance_;                   // cd/m² per element, photometric
  Eigen::VectorXd sunLuminance_;                // the sun's part of it; empty without a sun
  Eigen::MatrixX3d sunChannels_;                // the same per channel
  // The share of each element's slope in the final gather (SlopeGather::shares), set at the
  // first gather by the solved luminance per channel without the sun, and by the sun's; empty
  // before.
  Eigen::VectorXd slopeShare_, sunSlopeShare_;
  Eigen::VectorXd sunDirect_;  // lx, element-average direct sunlight; empty
  std::vector<char> outside_;  // per element: outside the room (outsideRoom), in a daylit scene
  bool anyOutside_ = false;    // some element is outside the room
  // τ of the openings between the elements outside and inside (scene/daylight.hpp,
  // crossingTransmittance); the room the openings are in (null without one).
  double crossing_ = 1.0;
  const Room* room_ = nullptr;
  double tolerance_ = 0.0;  // m, the scene's length tolerance
  Eigen::MatrixX3d direct_;
  RadiositySolution solution_;
  InterreflectionReport report_;
};

}  // namespace penumbra
