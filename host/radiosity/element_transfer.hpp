#pragma once
// The transfer between elements: how much illuminance each element's light gives each other
// element, by the kernel's exact occluded contour integral at the receiving element's
// quadrature nodes. It depends on the geometry only (not on reflectances or sources).
#include <Eigen/Dense>

#include "engine/illuminance_engine.hpp"
#include "radiosity/surface_mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The scene's solids with every element as a Lambertian source of 1 cd/m² emitting from its
// face: what the kernel integrates over for the transfer and for the final gather. Sources,
// grids and views of `scene` are left out.
Scene elementScene(const Scene& scene, const SurfaceMesh& mesh);

// elementScene with the mesh's caster blocks first, as sources that only hold shadow casters
// (Source::castersOnly), each element sharing its block's (Source::castersOf): element j is
// source mesh.casterBlocks.size() + j. The same transfer as elementScene's (a block's volumes
// only cull less tightly), at a fraction of the casters' memory and set-up.
Scene elementSceneSharingCasters(const Scene& scene, const SurfaceMesh& mesh);

// t(i, j): the mean over element i's nodes (by their weights) of the illuminance in lx that
// element j gives at 1 cd/m². `engine` must hold elementScene(scene, mesh) with unit
// luminances. Within the quadrature's error, area(i)·t(i, j) = area(j)·t(j, i) (reciprocity),
// and in a closed room every row sums to π (each node sees a whole hemisphere of elements).
// `firstElement`: element j is the engine's source firstElement + j (elementSceneSharingCasters'
// mesh.casterBlocks.size()).
Eigen::MatrixXd elementTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh,
                                std::size_t firstElement = 0);

// Which senders of a receiving element are far: those whose bounding ball lies a gap g from the
// receiver's, of diameter d, with (d/g)² ≤ `farRatio`. Their light varies across the receiver
// by about d/g of itself, and a 2 × 2 Gauss-Legendre rule averages it to about (d/g)⁴ of it.
// 0.1 holds a furnished closed room's energy balance as well as every sender at the nodes does
// (docs/method.md, "Far senders").
// With row sums known (elementTransfer below), a far pair whose elements are both small against
// their gap, (d/g)² ≤ reciprocalRatio for the larger one's d, is computed at one element's far
// points and taken the other way by reciprocity. A row's factor takes out the error its own far
// points make, about (d/g)⁴ of each value and of one sign where the light falls off smoothly;
// a value borrowed from the other element's points carries that element's error instead, and
// at 0.025 that stays below what the factor leaves (open office: the work plane's E within
// 2.6e-4 of every sender at every node; docs/method.md, "Far senders").
struct FarFieldRule {
  double farRatio = 0.1;
  double reciprocalRatio = 0.025;
};

// elementTransfer's matrix with the far senders of each receiver taken at its four far points
// (2 × 2 Gauss-Legendre points on a parallelogram, else the centroid): the near senders (every
// sender where farRatio is 0) are averaged over the receiver's nodes as above; the far ones'
// values are scaled by one factor per receiver so that the row keeps a sum known exactly. The
// row sum is what the energy balance hangs on: in a closed room it is π at every point; the far
// field's share, the whole row less the near field's node average, is spread over the far
// senders in proportion to their values. A receiver whose factor would leave [0.5, 2] (a far
// field too weak against the near field's change across the receiver) has all its senders
// averaged over its nodes.
// Without `rowSums`, every sender is computed at the far points and a row keeps its sum over
// them. With `rowSums` (transferRowSums: the node-average transfer's row sums), row i sums to
// rowSums[i]; a far pair is computed at the far points of the receiver in the earlier batch of
// receivers, and the other way follows by reciprocity, A_i t(i, j) = A_j t(j, i), where
// rule.reciprocalRatio allows, else it is computed at that receiver's own points too: about half
// of the far field's work, which is most of the transfer's.
Eigen::MatrixXd elementTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh,
                                const FarFieldRule& rule, std::size_t firstElement = 0,
                                const Eigen::VectorXd* rowSums = nullptr);

}  // namespace penumbra
