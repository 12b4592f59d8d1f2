#pragma once
// The host's double-precision evaluation of the point model (docs/method.md, "Photometric
// luminaires"): at each point, from each luminaire instance's photometric centre c,
//   E = I(ω) · cos θ / d²,
// ω the direction c → point in the luminaire's frame, θ the angle between the point's normal and
// the direction towards c, d the distance, I the file's interpolated intensity times the
// luminaire's scale (flux override, maintenance factor). A point behind its own surface
// (cos θ <= 0) gets 0; so does one whose segment to c runs through a solid (Cyrus–Beck against
// each solid's planes moved inwards by the scene tolerance; the solid the point lies on never
// shades it). Shares nothing with kernels/luminaire.cl but the scene.
//
// A luminaire of the area model (scene/luminaire.hpp, LuminaireOpening) gives instead its
// opening's exact integral (opening_illuminance.hpp), or, where its fit is subdivided, the sum of
// the point model over the opening's cells, each carrying its share of the distribution.
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// E in lx at every point, summed over every instance of every luminaire of `scene`.
std::vector<double> referenceLuminaireIlluminance(const Scene& scene,
                                                  std::span<const SamplePoint> points);

}  // namespace penumbra
