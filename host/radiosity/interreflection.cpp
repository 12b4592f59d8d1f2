#include "radiosity/interreflection.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/tolerance.hpp"
#include "radiosity/element_transfer.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {

namespace {

// Direct E per channel at every node: each source's E split into channels by its colour
// relative to the colour's luminance (a source's `color` keeps its photometric luminance), and
// the photometric luminaires' E in every channel.
Eigen::MatrixX3d nodeDirect(IlluminanceEngine& engine, const Scene& scene,
                            const SurfaceMesh& mesh) {
  const std::size_t sources = scene.sources.size();
  std::vector<Eigen::Vector3d> channel(sources);
  for (std::size_t s = 0; s < sources; ++s) {
    const Vec3& color = scene.sources[s].color;
    channel[s] = color / photometric(color);
  }
  const auto n = static_cast<Eigen::Index>(mesh.nodes.size());
  Eigen::MatrixX3d direct = Eigen::MatrixX3d::Zero(n, 3);
  if (n == 0) return direct;
  const IlluminanceResult result = engine.evaluate(mesh.nodes, true);
  for (Eigen::Index node = 0; node < n; ++node) {
    for (std::size_t s = 0; s < sources; ++s) {
      direct.row(node) +=
          result.bySource[static_cast<std::size_t>(node) * sources + s] * channel[s].transpose();
    }
    // Photometric luminaires are white.
    if (!result.luminaires.empty())
      direct.row(node).array() += result.luminaires[static_cast<std::size_t>(node)];
  }
  return direct;
}

// Element averages of node values (the nodes' weights).
Eigen::MatrixX3d elementAverage(const SurfaceMesh& mesh, const Eigen::MatrixX3d& atNodes) {
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  Eigen::MatrixX3d average = Eigen::MatrixX3d::Zero(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    for (std::size_t node = mesh.nodeStart[i]; node < mesh.nodeStart[i + 1]; ++node)
      average.row(i) += mesh.weights[node] * atNodes.row(static_cast<Eigen::Index>(node));
  return average;
}

// Elements whose first reflection is uneven: ρ·(Emax - Emin)·A over the element's nodes (lm)
// above `fraction` of the whole first reflected flux Σ ρ·E·A.
std::vector<char> unevenElements(const SurfaceMesh& mesh, const Eigen::MatrixX3d& atNodes,
                                 double fraction) {
  const std::size_t n = mesh.elements.size();
  std::vector<double> spread(n, 0.0);
  double reflected = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = photometric(mesh.elements[i].reflectance);
    double lo = INFINITY, hi = -INFINITY, mean = 0.0;
    for (std::size_t node = mesh.nodeStart[i]; node < mesh.nodeStart[i + 1]; ++node) {
      const double e = photometric(atNodes.row(static_cast<Eigen::Index>(node)).transpose());
      lo = std::min(lo, e), hi = std::max(hi, e);
      mean += mesh.weights[node] * e;
    }
    spread[i] = rho * (hi - lo) * mesh.elements[i].area;
    reflected += rho * mean * mesh.elements[i].area;
  }
  std::vector<char> split(n, 0);
  for (std::size_t i = 0; i < n; ++i) split[i] = spread[i] > fraction * reflected;
  return split;
}

}  // namespace

Interreflection::Interreflection(compute::Device& device, const Scene& scene,
                                 IlluminanceEngine& direct, const MeshOptions& mesh,
                                 const EngineOptions& engine) {
  auto start = Clock::now();
  // The mesh, refined where the direct light is uneven; the direct E at its nodes comes with it.
  mesh_ = buildSurfaceMesh(scene, mesh);
  Eigen::MatrixX3d atNodes = nodeDirect(direct, scene, mesh_);
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  for (int level = 0; level < mesh.refinementLevels; ++level) {
    const std::vector<char> split = unevenElements(mesh_, atNodes, mesh.refinement);
    if (std::find(split.begin(), split.end(), 1) == split.end()) break;
    mesh_ = refineMesh(mesh_, split, mesh.quadratureOrder, tolerance);
    atNodes = nodeDirect(direct, scene, mesh_);
  }
  direct_ = elementAverage(mesh_, atNodes);
  report_.elements = mesh_.elements.size();
  report_.elementSize = mesh.elementSize;
  report_.nodes = mesh_.nodes.size();
  report_.surfaceArea = mesh_.area();
  report_.blackSolids = mesh_.blackSolids;
  report_.meshSeconds = secondsSince(start);

  start = Clock::now();
  elements_ = elementScene(scene, mesh_);
  gather_ = std::make_unique<IlluminanceEngine>(device, elements_, engine);
  const Eigen::MatrixXd transfer = elementTransfer(*gather_, mesh_);
  report_.transferSeconds = secondsSince(start);

  start = Clock::now();
  solution_ = solveRadiosity(transfer, mesh_, direct_);
  report_.residual = solution_.residual;
  report_.solveSeconds = secondsSince(start);

  start = Clock::now();
  Eigen::VectorXd luminance(solution_.luminance.rows());
  for (Eigen::Index i = 0; i < luminance.size(); ++i)
    luminance[i] = photometric(solution_.luminance.row(i).transpose());
  setElementLuminance(elements_, luminance);
  gather_->setScene(elements_);
  report_.setupSeconds = secondsSince(start);
}

Interreflection::~Interreflection() = default;

std::vector<double> Interreflection::indirect(std::span<const SamplePoint> points) {
  if (mesh_.elements.empty()) return std::vector<double>(points.size(), 0.0);
  return gather_->illuminance(points);
}

std::vector<Eigen::Vector3d> Interreflection::indirectChannels(
    std::span<const SamplePoint> points) {
  std::vector<Eigen::Vector3d> out(points.size(), Eigen::Vector3d::Zero());
  const std::size_t n = mesh_.elements.size();
  if (n == 0) return out;
  // Each element's E at its photometric luminance, split into channels by its luminance's
  // colour; about 2^22 point·element values (16 MB of float) at a time.
  std::vector<Eigen::Vector3d> colour(n, Eigen::Vector3d::Zero());
  for (std::size_t j = 0; j < n; ++j) {
    const Eigen::Vector3d l = solution_.luminance.row(static_cast<Eigen::Index>(j)).transpose();
    const double y = photometric(l);
    if (y > 0.0) colour[j] = l / y;
  }
  const std::size_t batch = std::max<std::size_t>(1, (std::size_t{1} << 22) / n);
  for (std::size_t first = 0; first < points.size(); first += batch) {
    const std::size_t count = std::min(batch, points.size() - first);
    std::size_t stride = 0;
    const std::vector<float> e = gather_->illuminanceBySource(points.subspan(first, count), stride);
    for (std::size_t j = 0; j < n; ++j) {
      if (colour[j].isZero()) continue;
      const float* row = e.data() + j * stride;
      for (std::size_t i = 0; i < count; ++i) out[first + i] += double(row[i]) * colour[j];
    }
  }
  return out;
}

}  // namespace penumbra
