#pragma once
// What a sample sees of one source, for later stages (the render's interval sampling re-samples
// wherever it changes). Two bits: bit 0 "some of the source's light arrives", bit 1 "an occluder
// may block part of it" (the sample is in some occluder's penumbra volume, so this errs towards
// Penumbra near shadow edges, never towards Lit).
#include <cstdint>

namespace penumbra {

enum class ShadowClass : std::uint8_t {
  Unlit = 0,     // the source is behind the sample's surface or the sample behind the source
  Lit = 1,       // the whole visible source, no occluder in the way
  Umbra = 2,     // an occluder hides the whole source
  Penumbra = 3,  // partly hidden (or near enough to an occluder's shadow to be computed so)
};

}  // namespace penumbra
