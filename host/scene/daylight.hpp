#pragma once
// The sky and the ground seen through the room's openings, as sources (docs/method.md,
// "Daylight").
//
// A receiving point P sees, through each opening, the sky above its own horizontal plane
// z = P.z and the ground below it:
//   sky     L(ω) = τ·L_z·(1 + 2ω_z)/3 (CIE overcast) or τ·E_h/π (uniform), ω the unit direction
//           from P, ω_z the sine of its altitude;
//   ground  L = τ·ρ_g·E_h/π, uniform;
// τ the opening's transmittance. On its side of z = P.z each is a polynomial of degree <= 1 in
// ω_z, which the kernel and the host references integrate exactly over the visible part of a
// face (Source::luminanceCoefficients with axis +z). So the opening's rectangle on the wall's
// outer plane (the reveals shade it, as for an `opening:` source) is cut at P's height into a
// sky face (z >= P.z) and a ground face (z <= P.z). The cut depends on P's height only, and
// only through where it falls within each opening: every point below an opening sees only sky
// through it, every point above it only ground. Points are therefore evaluated in groups that
// share the cuts (daylightGroups); an upward work plane is one group.
//
// An opening that has an `opening:` source of its own keeps that source (with the same τ) and
// gets no sky: the explicit source wins.
//
// A solid outside the room (an overhang, a fin, a building across the street) lies beyond the
// opening's rectangle, where a source's occluders cannot be. A scene with one is lit by the sky
// on the host instead (skyOnHost; illuminance/skylight.hpp), exactly in double past every solid:
// it then has no sky or ground sources here.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The openings the sky lights (those without an `opening:` source), in the room's order; none
// without a sky or a room.
std::vector<const Opening*> skyOpenings(const Scene& scene);

// Whether the sky of `scene` is computed on the host (illuminance/skylight.hpp) rather than as
// the kernel's sources below: a sky and a room, and either a solid that reaches out of the room's
// outer box (the interior box grown by the wall's thickness) or a `cie-general` sky (patches).
bool skyOnHost(const Scene& scene);

// Whether a solid of `scene` reaches out of its room's outer box (the interior box grown by the
// wall's thickness): an obstruction, an overhang, a fin. False without a room.
bool solidReachesOutsideRoom(const Scene& scene);

// Whether `p` lies outside `room`: not strictly inside its outer box (the interior box grown by
// the wall's thickness, less `tolerance`). The walls' outer faces and every solid beyond them
// (an obstruction) are outside; the reveals of an opening and the room's interior are not.
bool outsideRoom(const Room& room, const Vec3& p, double tolerance);

// `scene` with two sources per sky-lit opening, its whole outer rectangle at the sky's zenith
// luminance facing into the room and the same rectangle facing out: what the interreflection's
// mesh takes to find the faces that see an opening, from the room and from outside it (the
// faces of obstructions that the room sees through its openings), wherever the sky itself is
// computed.
Scene skyFacesScene(const Scene& scene);

// The transmittance with which light crosses the openings between the faces outside the room and
// those inside it (radiosity/interreflection.hpp): the sky-lit openings' τ, their mean weighted
// by area where they differ; 1 without any.
double crossingTransmittance(const Scene& scene);

// `scene` with, appended to its sources, a sky source and a ground source per opening lit by
// the sky (named "<opening>.sky" and "<opening>.ground"), cut at `height` (m). Every height gives
// the same sources in the same order; one whose part of the opening is empty (thinner than the
// scene's length tolerance) has no faces. Without a sky, or with skyOnHost: `scene` unchanged.
Scene daylightScene(const Scene& scene, double height);

// Points that share one daylightScene: their indices, and a height that gives it.
struct DaylightGroup {
  double height = 0.0;  // m
  std::vector<std::size_t> points;
};

// The groups of `points` (each point in exactly one, groups in order of their first point).
// Without a sky, or with skyOnHost: one group of all points.
std::vector<DaylightGroup> daylightGroups(const Scene& scene, std::span<const SamplePoint> points);

// The points of one group, in its order.
std::vector<SamplePoint> groupPoints(const DaylightGroup& group,
                                     std::span<const SamplePoint> points);

// A value per point from an estimator that takes a scene without a sky (the host references):
// `estimate(daylightScene(scene, group height), the group's points)` for each group, put back in
// the points' order. Without a sky: estimate(scene, points).
using SceneEstimate =
    std::function<std::vector<double>(const Scene&, std::span<const SamplePoint>)>;
std::vector<double> estimateByGroup(const Scene& scene, std::span<const SamplePoint> points,
                                    const SceneEstimate& estimate);

}  // namespace penumbra
