#include "radiosity/interreflection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "geometry/fnv1a_hash.hpp"
#include "geometry/tolerance.hpp"
#include "radiosity/element_transfer.hpp"
#include "radiosity/node_light.hpp"
#include "radiosity/sun_on_elements.hpp"
#include "radiosity/transfer_row_sums.hpp"
#include "scene/daylight.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {

namespace {

// Element averages of node values (the nodes' weights).
Eigen::MatrixXd elementAverage(const SurfaceMesh& mesh, const Eigen::MatrixXd& atNodes) {
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  Eigen::MatrixXd average = Eigen::MatrixXd::Zero(n, atNodes.cols());
  for (Eigen::Index i = 0; i < n; ++i)
    for (std::size_t node = mesh.nodeStart[i]; node < mesh.nodeStart[i + 1]; ++node)
      average.row(i) += mesh.weights[node] * atNodes.row(static_cast<Eigen::Index>(node));
  return average;
}

// The photometric value of each row's channels.
Eigen::VectorXd photometricRows(const Eigen::MatrixX3d& rgb) {
  Eigen::VectorXd values(rgb.rows());
  for (Eigen::Index i = 0; i < values.size(); ++i) values[i] = photometric(rgb.row(i).transpose());
  return values;
}

// The elements as unit sources, the kernel for them, and the transfer between them.
std::shared_ptr<GeometryTransfer> computeTransfer(compute::Device& device, const Scene& scene,
                                                  const SurfaceMesh& mesh,
                                                  const MeshOptions& options,
                                                  const EngineOptions& engine) {
  const auto start = Clock::now();
  auto geometry = std::make_shared<GeometryTransfer>();
  geometry->elements = elementSceneSharingCasters(scene, mesh);
  geometry->firstElement = mesh.casterBlocks.size();
  geometry->gather = std::make_unique<IlluminanceEngine>(device, geometry->elements, engine);
  const std::optional<Eigen::VectorXd> rowSums = transferRowSums(device, scene, mesh, engine);
  geometry->transfer = elementTransfer(*geometry->gather, mesh, FarFieldRule{},
                                       geometry->firstElement, rowSums ? &*rowSums : nullptr);
  if (options.linearGather &&
      mesh.elements.size() * 4 * std::max<std::size_t>(1, scene.solids.size()) <=
          options.linearGatherLimit)
    geometry->slopes = std::make_unique<SlopeGather>(device, scene, mesh, engine,
                                                     Tolerance::forSceneSize(scene.size()).length);
  geometry->seconds = secondsSince(start);
  return geometry;
}

}  // namespace

Interreflection::Interreflection(compute::Device& device, const Scene& scene,
                                 IlluminanceEngine& direct, const MeshOptions& mesh,
                                 const EngineOptions& engine, TransferCache* cache,
                                 const HostLight& host) {
  if (mesh.linkError > 0.0) {
    solveHierarchically(device, scene, direct, mesh, engine, cache, host);
    return;
  }
  auto start = Clock::now();
  // The mesh, refined where the direct light is uneven; the direct E at its nodes comes with it.
  // The faces that see a source: with a sky, those that see an opening (its whole rectangle as
  // the sky face, cut below the scene).
  mesh_ = buildSurfaceMesh(skyFacesScene(scene), mesh);
  if (mesh_.elements.size() > mesh.maxElements) {
    // More elements than the dense transfer takes before any refinement: hierarchical links at
    // the default bound, which have no element limit.
    const std::size_t denseElements = mesh_.elements.size();
    MeshOptions linked = mesh;
    linked.linkError = MeshOptions::kDefaultLinkError;
    solveHierarchically(device, scene, direct, linked, engine, cache, host);
    report_.denseElements = denseElements;
    return;
  }
  NodeLight light = nodeLight(direct, scene, mesh_, host);
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  for (int level = 0; level < mesh.refinementLevels; ++level) {
    const std::vector<char> split =
        unevenElements(mesh_, light, mesh.refinement, mesh.maxElements, report_.refinementCapped);
    if (std::find(split.begin(), split.end(), 1) == split.end()) break;
    mesh_ = refineMesh(mesh_, split, mesh.quadratureOrder, tolerance);
    light = nodeLight(direct, scene, mesh_, host);
  }
  finishMesh(scene, host, light.direct, mesh.elementSize, start);

  if (mesh_.elements.empty()) return;
  const std::uint64_t key = transferFingerprint(scene, mesh_);
  if (cache) geometry_ = cache->find(key);
  report_.transferReused = geometry_ != nullptr;
  if (!geometry_) {
    geometry_ = computeTransfer(device, scene, mesh_, mesh, engine);
    report_.transferSeconds = geometry_->seconds;
    if (cache) cache->insert(key, geometry_);
  }

  report_.linearGather = geometry_->slopes != nullptr;
  start = Clock::now();
  solution_ = solveRadiosity(geometry_->transfer, mesh_, direct_);
  report_.residual = solution_.residual;
  if (sunDirect_.size() > 0) {
    // The system is linear: the sun's part is solved alone and added, so that the daylight
    // factor can leave it out.
    const RadiositySolution sun =
        solveRadiosity(geometry_->transfer, mesh_, sunDirect_.replicate<1, 3>());
    report_.residual = std::max(report_.residual, sun.residual);
    addSun(sun.luminance);
  }
  luminance_ = photometricRows(solution_.luminance);
  if (sunLuminance_.size() > 0) luminance_ += sunLuminance_;
  report_.solveSeconds = secondsSince(start);
}

void Interreflection::solveHierarchically(compute::Device& device, const Scene& scene,
                                          IlluminanceEngine& direct, const MeshOptions& mesh,
                                          const EngineOptions& engine, TransferCache* cache,
                                          const HostLight& host) {
  auto start = Clock::now();
  // The element trees, their leaves refined where the direct light is uneven, as the dense
  // path refines its elements; no element limit (the links grow about linearly).
  // With a sky, the faces that see an opening are reached (as buildSurfaceMesh's are above).
  auto tree =
      std::make_unique<ElementTree>(buildElementTree(skyFacesScene(scene), mesh.elementSize));
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  mesh_ = tree->leafMesh(mesh.quadratureOrder);
  NodeLight light = nodeLight(direct, scene, mesh_, host);
  for (int level = 0; level < mesh.refinementLevels; ++level) {
    bool capped = false;
    const std::vector<char> split = unevenElements(mesh_, light, mesh.refinement,
                                                   std::numeric_limits<std::size_t>::max(), capped);
    if (std::find(split.begin(), split.end(), 1) == split.end()) break;
    for (std::size_t i = 0; i < split.size(); ++i)
      if (split[i]) tree->split(tree->leaves[i], tolerance);
    tree->numberLeaves();
    mesh_ = tree->leafMesh(mesh.quadratureOrder);
    light = nodeLight(direct, scene, mesh_, host);
  }
  finishMesh(scene, host, light.direct, mesh.elementSize, start);
  if (mesh_.elements.empty()) return;

  Fnv1a salt;
  salt.add(std::string_view("hierarchical links"));
  salt.add(mesh.linkError);
  const std::uint64_t key = transferFingerprint(scene, mesh_) ^ salt.value();
  if (cache) geometry_ = cache->find(key);
  report_.transferReused = geometry_ != nullptr;
  if (!geometry_) {
    start = Clock::now();
    geometry_ = std::make_shared<GeometryTransfer>();
    HierarchyOptions options;
    options.linkError = mesh.linkError;
    options.quadratureOrder = mesh.quadratureOrder;
    geometry_->tree = std::move(tree);
    geometry_->links =
        std::make_unique<HierarchicalTransfer>(device, scene, *geometry_->tree, options, engine);
    geometry_->seconds = secondsSince(start);
    report_.transferSeconds = geometry_->seconds;
    if (cache) cache->insert(key, geometry_);
  }
  report_.links = geometry_->links->links().source.size();
  report_.linkError = mesh.linkError;

  start = Clock::now();
  const HierarchicalSolution solved = solveHierarchical(*geometry_->links, direct_);
  solution_.indirect = solved.indirect;
  solution_.luminance = solved.luminance;
  solution_.residual = solved.residual;
  report_.residual = solved.residual;
  if (sunDirect_.size() > 0) {
    const HierarchicalSolution sun =
        solveHierarchical(*geometry_->links, sunDirect_.replicate<1, 3>());
    report_.residual = std::max(report_.residual, sun.residual);
    addSun(sun.luminance);
  }
  luminance_ = photometricRows(solution_.luminance);
  if (sunLuminance_.size() > 0) luminance_ += sunLuminance_;
  report_.solveSeconds = secondsSince(start);
}

void Interreflection::finishMesh(const Scene& scene, const HostLight& host,
                                 const Eigen::MatrixX3d& nodeDirect, double elementSize,
                                 Clock::time_point start) {
  direct_ = elementAverage(mesh_, nodeDirect);
  sunDirect_ = Eigen::VectorXd();
  if (host.sun && !mesh_.nodes.empty()) {
    const std::vector<double> e = host.sun(mesh_.nodes);
    const Eigen::Map<const Eigen::VectorXd> nodeSun(e.data(), static_cast<Eigen::Index>(e.size()));
    sunDirect_ = sunElementAverage(scene, host.sun, mesh_, nodeSun);
  }
  outside_.assign(mesh_.elements.size(), 0);
  room_ = scene.room ? &*scene.room : nullptr;
  tolerance_ = Tolerance::forSceneSize(scene.size()).length;
  if (room_ && scene.sky)  // the externally reflected component is the daylight's
    for (std::size_t i = 0; i < mesh_.elements.size(); ++i)
      outside_[i] = outsideRoom(*room_, mesh_.elements[i].polygon.centroid(), tolerance_);
  anyOutside_ = std::find(outside_.begin(), outside_.end(), 1) != outside_.end();
  crossing_ = anyOutside_ ? crossingTransmittance(scene) : 1.0;
  // The elements outside as the room sees them through the glazing: τ times their own light.
  for (std::size_t i = 0; i < outside_.size(); ++i) {
    if (!outside_[i]) continue;
    direct_.row(static_cast<Eigen::Index>(i)) *= crossing_;
    if (sunDirect_.size() > 0) sunDirect_[static_cast<Eigen::Index>(i)] *= crossing_;
  }
  report_.elements = mesh_.elements.size();
  report_.elementSize = elementSize;
  report_.nodes = mesh_.nodes.size();
  report_.surfaceArea = mesh_.area();
  report_.blackSolids = mesh_.blackSolids;
  report_.meshSeconds = secondsSince(start);
}

void Interreflection::addSun(const Eigen::MatrixX3d& luminance) {
  sunChannels_ = luminance;
  sunLuminance_ = photometricRows(luminance);
}

Interreflection::~Interreflection() = default;

Eigen::MatrixXd Interreflection::gather(std::span<const SamplePoint> points,
                                        const Eigen::MatrixXd& luminance,
                                        const Eigen::MatrixXd& sunPart) {
  if (crossing_ == 1.0 || !room_) return gatherElements(points, luminance, sunPart);
  std::vector<SamplePoint> inside, outside;
  std::vector<std::size_t> insideAt, outsideAt;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const bool out = outsideRoom(*room_, points[p].position, tolerance_);
    (out ? outside : inside).push_back(points[p]);
    (out ? outsideAt : insideAt).push_back(p);
  }
  Eigen::MatrixXd e(static_cast<Eigen::Index>(points.size()), luminance.cols());
  const auto place = [&](const Eigen::MatrixXd& part, const std::vector<std::size_t>& at) {
    for (std::size_t k = 0; k < at.size(); ++k)
      e.row(static_cast<Eigen::Index>(at[k])) = part.row(static_cast<Eigen::Index>(k));
  };
  if (!inside.empty()) place(gatherElements(inside, luminance, sunPart), insideAt);
  if (!outside.empty()) {
    Eigen::MatrixXd seenOutside = luminance, sunSeenOutside = sunPart;
    for (Eigen::Index i = 0; i < seenOutside.rows(); ++i) {
      const double seen = outside_[static_cast<std::size_t>(i)]
                              ? (crossing_ > 0.0 ? 1.0 / crossing_ : 0.0)
                              : crossing_;
      seenOutside.row(i) *= seen;
      if (sunSeenOutside.size() > 0) sunSeenOutside.row(i) *= seen;
    }
    place(gatherElements(outside, seenOutside, sunSeenOutside), outsideAt);
  }
  return e;
}

Eigen::MatrixXd Interreflection::gatherElements(std::span<const SamplePoint> points,
                                                const Eigen::MatrixXd& luminance,
                                                const Eigen::MatrixXd& sunPart) {
  Eigen::MatrixXd e =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(points.size()), luminance.cols());
  if (!geometry_) return e;
  if (geometry_->links)
    return geometry_->links->gather(points, geometry_->links->nodeAverages(luminance));
  // Each element's E at unit luminance, weighted by its luminance; about 2^22 point·element
  // values (16 MB of float) at a time.
  const std::size_t elements = mesh_.elements.size();
  const std::size_t batch = std::max<std::size_t>(1, (std::size_t{1} << 22) / elements);
  for (std::size_t first = 0; first < points.size(); first += batch) {
    const std::size_t count = std::min(batch, points.size() - first);
    std::size_t stride = 0;
    const std::vector<float> unit =
        geometry_->gather->illuminanceBySource(points.subspan(first, count), stride);
    for (std::size_t j = 0; j < elements; ++j) {
      const float* row = unit.data() + (geometry_->firstElement + j) * stride;
      for (Eigen::Index c = 0; c < luminance.cols(); ++c) {
        const double l = luminance(static_cast<Eigen::Index>(j), c);
        if (l == 0.0) continue;
        for (std::size_t p = 0; p < count; ++p)
          e(static_cast<Eigen::Index>(first + p), c) += l * row[p];
      }
    }
  }
  if (geometry_->slopes) {
    // Each solved part of the light (the sources' and sky's, the sun's, which is solved alone)
    // takes one share of each element's slope, set by that part's luminance in all three
    // channels, for every column gathered: so the gather stays linear within a part, the parts
    // sum to the whole, and a part's light is the same whether or not the other is there.
    if (slopeShare_.size() == 0) {
      slopeShare_ = geometry_->slopes->shares(solution_.luminance);
      if (sunChannels_.rows() > 0) sunSlopeShare_ = geometry_->slopes->shares(sunChannels_);
    }
    const Eigen::Index n = luminance.cols();
    const bool sun = sunPart.size() > 0;
    Eigen::MatrixXd parts(luminance.rows(), sun ? 2 * n : n), share(luminance.rows(), parts.cols());
    parts.leftCols(n) = sun ? Eigen::MatrixXd(luminance - sunPart) : luminance;
    share.leftCols(n) = slopeShare_.replicate(1, n);
    if (sun) {
      parts.rightCols(n) = sunPart;
      share.rightCols(n) = sunSlopeShare_.replicate(1, n);
    }
    const Eigen::MatrixXd correction = geometry_->slopes->correction(points, parts, share);
    e += correction.leftCols(n);
    if (sun) e += correction.rightCols(n);
  }
  return e;
}

std::vector<double> Interreflection::indirect(std::span<const SamplePoint> points) {
  Eigen::MatrixXd sunPart;
  if (sunLuminance_.size() > 0) sunPart = sunLuminance_;
  const Eigen::MatrixXd e = gather(points, luminance_, sunPart);
  return std::vector<double>(e.data(), e.data() + e.size());
}

InterreflectedIlluminance Interreflection::indirectParts(std::span<const SamplePoint> points) {
  InterreflectedIlluminance parts;
  const bool outside = anyOutside_;
  if (sunLuminance_.size() == 0 && !outside) {
    parts.total = indirect(points);
    return parts;
  }
  // Columns: every element's luminance, the sun's part of it, the part of the elements outside
  // the room without the sun's; one gather.
  const bool sun = sunLuminance_.size() > 0;
  Eigen::MatrixXd luminance(luminance_.size(), 1 + int(sun) + int(outside));
  luminance.col(0) = luminance_;
  if (sun) luminance.col(1) = sunLuminance_;
  if (outside) {
    Eigen::VectorXd fromOutside = photometricRows(solution_.luminance);
    for (Eigen::Index i = 0; i < fromOutside.size(); ++i)
      if (!outside_[static_cast<std::size_t>(i)]) fromOutside[i] = 0.0;
    luminance.col(luminance.cols() - 1) = fromOutside;
  }
  // The sun's part of each column: all of the sun's column, none of the outside's.
  Eigen::MatrixXd sunPart;
  if (sun) {
    sunPart = Eigen::MatrixXd::Zero(luminance.rows(), luminance.cols());
    sunPart.col(0) = sunLuminance_;
    sunPart.col(1) = sunLuminance_;
  }
  const Eigen::MatrixXd e = gather(points, luminance, sunPart);
  const auto column = [&](Eigen::Index c) {
    return std::vector<double>(e.col(c).data(), e.col(c).data() + e.rows());
  };
  parts.total = column(0);
  if (sun) parts.fromSun = column(1);
  if (outside) parts.fromOutside = column(luminance.cols() - 1);
  return parts;
}

std::vector<Eigen::Vector3d> Interreflection::indirectChannels(
    std::span<const SamplePoint> points) {
  Eigen::MatrixXd luminance = solution_.luminance, sunPart;
  if (sunChannels_.rows() > 0) {
    luminance += sunChannels_;
    sunPart = sunChannels_;
  }
  const Eigen::MatrixXd e = gather(points, luminance, sunPart);
  std::vector<Eigen::Vector3d> channels(points.size());
  for (std::size_t p = 0; p < points.size(); ++p)
    channels[p] = e.row(static_cast<Eigen::Index>(p)).transpose();
  return channels;
}

}  // namespace penumbra
