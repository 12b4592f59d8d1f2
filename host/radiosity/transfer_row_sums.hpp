#pragma once
// What a row of the element transfer sums to, found without the transfer. Each node of an element
// sees a whole hemisphere, π in lx at unit luminance; in a room the elements cover all of it but
// the world past the room's openings and the faces that reflect nothing (solids without a
// material or of reflectance 0). Those are few faces, so their E at every node costs a small
// fraction of the transfer, and π less it is the row sum to the kernel's tolerance. Without a
// room the scene does not say where the world begins, and there are no row sums.
#include <optional>

#include <Eigen/Dense>

#include "cl/device.hpp"
#include "engine/engine_options.hpp"
#include "radiosity/surface_mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The scene's solids with, as unit-luminance sources, every face of every solid that reflects
// nothing and, when no solid stands outside the room, each opening's outer rectangle facing into
// the room (as the sky's source, scene/daylight.hpp: past it nothing is an element). None
// without a room.
std::optional<Scene> unseenByElements(const Scene& scene);

// The scene's solids and room, its openings bare, under a sky and a ground of 1 cd/m² each: the
// world past the room, whose E the host computes past every solid (surfaceSkylight) where a
// solid stands outside the room. None without a room.
std::optional<Scene> worldBeyond(const Scene& scene);

// Row i of the node-average transfer (elementTransfer) sums to π less the mean over element i's
// nodes (by their weights) of E from unseenByElements(scene), and from worldBeyond(scene) where
// a solid stands outside the room: the returned vector. None without a room.
std::optional<Eigen::VectorXd> transferRowSums(compute::Device& device, const Scene& scene,
                                               const SurfaceMesh& mesh,
                                               const EngineOptions& options = {});

}  // namespace penumbra
