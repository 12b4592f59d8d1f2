#pragma once
// Halos: a display map that lifts (or sinks) a region near a strong edge and lets it drift back to
// its own level away from the edge. Measured per region against what the region's own pixels far
// from the edge show at the same luminance: for a near pixel, the least-squares line log display
// = a + b log scene through the far pixels whose scene values lie within 10 % of its own (b = 1,
// a pure gain, when they are all alike), so that a region shown as any curve of its luminance
// reads 0 and only a difference between near and far at one luminance counts; each near pixel's
// display value over the value so predicted, averaged at each distance from the edge within a
// band. A near pixel counts only where at least minimumPixels far pixels lie within those 10 % (the
// relation is never extrapolated into an umbra), and only pixels above the display's black (5 %
// above the image's darkest display value) count: a black floor is no halo. A map without halos
// treats a region alike near and far (clip, linear, any global curve, a curve per region), and
// the measure is then 0 whatever the region's own gradients, which the scene value carries.
#include "image/images.hpp"

namespace penumbra {

struct HaloOptions {
  int band = 4;          // pixels from the edge (0 = the pixel beside it) counted as near
  int farDistance = 24;  // pixels from the edge beyond which a region shows its own level
  double edgeRatio = 3;  // strong edge: scene values across it differ at least this much
  // A distance from the edge counts with at least this many pixels there, a region with at least
  // this many far pixels.
  int minimumPixels = 16;
};

struct HaloMeasure {
  int regions = 0;  // region sides measured (a region beside a strong edge and large enough)
  // Largest relative excess and deficit over them: max over regions and over the distances
  // 0 … band-1 of the mean of display / predicted at that distance, minus 1 (overshoot) or 1
  // minus it (undershoot); 0 when no region shows it.
  double overshoot = 0, undershoot = 0;
  // The same deviation |display / predicted - 1| averaged over the measured regions, each
  // weighted by its near pixels.
  double meanDeviation = 0;
  double largest() const { return overshoot > undershoot ? overshoot : undershoot; }
};

// sceneValue: the linear scene quantity the display maps (Space-0 V or luminance), > 0 where it
// counts; displayValue: what the display shows for it, linear in the display's output (drive
// values of the thesis's V, or decoded display luminance). Regions are 4-connected parts of one
// face (face id 0: none); distance is counted in 4-steps inside the region from its pixels next
// to a strong edge.
HaloMeasure measureHalos(const ScalarImage& sceneValue, const FaceIdImage& faces,
                         const ScalarImage& displayValue, const HaloOptions& options = {});

}  // namespace penumbra
