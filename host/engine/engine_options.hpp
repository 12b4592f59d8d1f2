#pragma once
// The illuminance kernel's paths (docs/method.md), chosen per engine: IlluminanceEngine for the
// Lambertian sources, and the same for the area model's openings (LuminaireEngine).

namespace penumbra {

struct EngineOptions {
  // Shadow volumes and face classes (PN_PATH_CULLING, docs/method.md): each sample tests only the
  // occluders whose penumbra volume meets its patch, umbra samples get 0 at once, lit ones the
  // plain contour integral. Off: the plain path, every sample considers every occluder; slower,
  // the same numbers to float rounding, for comparison.
  bool culling = true;
  // With culling only: a window's sky on the wall's outer plane is seen through the opening
  // (shadow/aperture.hpp), and the wall around it is skipped. Off: the reveals are occluders like
  // any other (tests compare that with the plain path).
  bool apertures = true;
  // With culling only: points in a penumbra take the eight-lane penumbra path (PN_PATH_LANES,
  // kernels/penumbra_lanes.cl). Off: the scalar path (kernels/penumbra_scalar.cl), as the plain
  // path does.
  bool vectorPenumbra = true;
};

}  // namespace penumbra
