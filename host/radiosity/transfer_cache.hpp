#pragma once
// The part of the interreflection that depends on the geometry only: the elements as unit
// sources (and the kernel set up for them, for the final gather) and the element-to-element
// transfer. Reflectances and sources do not enter it, so a study whose cases differ only in
// reflectances or in the sources' output (not in where the sources are: the mesh follows the
// direct light) re-solves the radiosity equations with the transfer it already has.
#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>

#include <Eigen/Dense>

#include "engine/illuminance_engine.hpp"
#include "radiosity/element_tree.hpp"
#include "radiosity/hierarchical_transfer.hpp"
#include "radiosity/luminance_slopes.hpp"
#include "radiosity/surface_mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct GeometryTransfer {
  // Dense (MeshOptions::linkError 0): the elements as unit sources, the kernel on them, and the
  // element-to-element matrix.
  Scene elements;  // elementSceneSharingCasters: every element at 1 cd/m², after its blocks
  std::size_t firstElement = 0;               // element j is source firstElement + j
  std::unique_ptr<IlluminanceEngine> gather;  // the kernel on `elements`
  Eigen::MatrixXd transfer;                   // elementTransfer
  // The final gather's slopes within the elements (luminance_slopes.hpp).
  std::unique_ptr<SlopeGather> slopes;
  // Hierarchical: the element trees (whose leaves are the mesh) and the links between them.
  std::unique_ptr<ElementTree> tree;
  std::unique_ptr<HierarchicalTransfer> links;
  double seconds = 0.0;  // to compute all of it

  std::size_t bytes() const {
    std::size_t b = static_cast<std::size_t>(transfer.size()) * sizeof(double);
    if (links) b += links->links().source.size() * (sizeof(int) + sizeof(double));
    return b;
  }
};

// 64-bit fingerprint of everything the transfer depends on: the elements (polygons, solid and
// face, quadrature nodes and weights) and every solid and opening that can block light between
// them. Reflectances, sources, grids and views are left out.
std::uint64_t transferFingerprint(const Scene& scene, const SurfaceMesh& mesh);

// The transfers of the geometries met last, most recent first, within a memory budget (the
// newest is always kept). Kept by a run's estimator across the cases of a sweep; each process
// (a shard, a resumed sweep) starts empty, so nothing stale is ever read.
class TransferCache {
 public:
  explicit TransferCache(std::size_t byteBudget = std::size_t{1} << 30) : budget_(byteBudget) {}

  // The transfer for `key`, or null.
  std::shared_ptr<GeometryTransfer> find(std::uint64_t key);
  void insert(std::uint64_t key, std::shared_ptr<GeometryTransfer> transfer);

 private:
  struct Entry {
    std::uint64_t key;
    std::shared_ptr<GeometryTransfer> transfer;
  };
  std::size_t budget_;
  std::list<Entry> entries_;
};

}  // namespace penumbra
