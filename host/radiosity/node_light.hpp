#pragma once
// The direct light at a surface mesh's quadrature nodes, and the elements where it is uneven:
// what the mesh's refinement reads (Interreflection). The light is evaluated per light group in
// chunks of whole elements, so that no array holds a value per node and group: a hall lit by one
// panel per bay has as many groups as bays, and such an array would grow with the square of its
// floor area.
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "engine/illuminance_engine.hpp"
#include "radiosity/host_light.hpp"
#include "radiosity/surface_mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The light groups are each Lambertian source alone, then the photometric luminaires together,
// then the host's sky. The sun is left out: the mesh does not follow it, so that a scene's
// daylight factor is the same with any sun or none, and its light is taken once on the final
// mesh (Interreflection::finishMesh).
struct NodeLight {
  // lx, [node][channel]: each source's E split into channels by its colour relative to the
  // colour's luminance (a source's `color` keeps its photometric luminance), the luminaires and
  // the sky white.
  Eigen::MatrixX3d direct;
  // 1/m², [node]: each group's E scaled to unit flux onto the elements (Σ over the elements of
  // their node-weighted average E times their area), summed over the groups; neither the
  // reflectances nor the sources' output enter, only where the sources are and what they see.
  Eigen::VectorXd balanced;
  double litGroups = 0.0;  // the groups whose flux onto the elements is above 0
};

// How many values per node and light group (doubles) are held at once: those of one chunk of
// elements evaluated together (one element at least), and those of the first chunks kept from
// the first pass for the second (the groups' fluxes are known only after the first pass; the
// chunks past these are evaluated again). The defaults: 32 MB per chunk, about five times that
// inside the engine while it evaluates one, and 256 MB kept.
struct NodeLightChunks {
  std::size_t chunkValues = std::size_t{1} << 22;
  std::size_t keptValues = std::size_t{1} << 25;
};

NodeLight nodeLight(IlluminanceEngine& engine, const Scene& scene, const SurfaceMesh& mesh,
                    const HostLight& host, const NodeLightChunks& chunks = {});

// Elements where the direct light is uneven: an element is split when (max − min) of
// NodeLight::balanced over its nodes, times its area, exceeds `fraction` times the number of lit
// groups. A study varying reflectances or fluxes keeps its mesh and reuses the transfer
// (transfer_cache.hpp). When splitting them all would take the mesh past `maxElements`, the most
// uneven are split (a split adds up to three elements) and `capped` is set.
std::vector<char> unevenElements(const SurfaceMesh& mesh, const NodeLight& light, double fraction,
                                 std::size_t maxElements, bool& capped);

}  // namespace penumbra
