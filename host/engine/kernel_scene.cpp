#include "engine/kernel_scene.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/nishita.hpp"
#include "memory/page_prefault.hpp"
#include "photometry/luminance_fit.hpp"

static_assert(sizeof(PnSourceFace) == 48, "PnSourceFace layout must match kernels/shared_types.h");
static_assert(sizeof(PnLuminancePolynomial) == 224,
              "PnLuminancePolynomial layout must match kernels/shared_types.h");
static_assert(penumbra::photometry::kLuminanceFitMaxPower < PN_MAX_LUMINANCE_TERMS &&
                  penumbra::photometry::kLuminanceFitMaxOrder < PN_MAX_LUMINANCE_TERMS,
              "the luminance fits must fit the kernel's PnLuminancePolynomial");
static_assert(sizeof(PnOccluder) == 80, "PnOccluder layout must match kernels/shared_types.h");
static_assert(sizeof(PnAperture) == 128, "PnAperture layout must match kernels/shared_types.h");
static_assert(sizeof(PnPosition) == 32, "PnPosition layout must match kernels/shared_types.h");
static_assert(sizeof(PnPatchFace) == 16, "PnPatchFace layout must match kernels/shared_types.h");
static_assert(sizeof(PnLaunchParams) == 32,
              "PnLaunchParams layout must match kernels/shared_types.h");

namespace penumbra {

namespace {

cl_float4 toFloat4(const Vec3& v, double w = 0.0) {
  cl_float4 f;
  f.s[0] = static_cast<float>(v.x());
  f.s[1] = static_cast<float>(v.y());
  f.s[2] = static_cast<float>(v.z());
  f.s[3] = static_cast<float>(w);
  return f;
}

// Positions and planes relative to the kernel's origin c: x − c, and n·x = w becomes
// n·(x − c) = w − n·c.
struct Relative {
  Vec3 origin;
  cl_float4 point(const Vec3& x, double w = 0.0) const { return toFloat4(x - origin, w); }
  PnPosition position(const Vec3& x) const { return toPosition(x, origin); }
  cl_float4 plane(const Plane& p) const {
    return toFloat4(p.normal, p.offset - p.normal.dot(origin));
  }
};

cl_float4 toFloat4(const std::array<double, 4>& r) {
  cl_float4 f;
  for (int i = 0; i < 4; ++i) f.s[i] = static_cast<float>(r[i]);
  return f;
}

// The box's corners rounded inwards to float, so that a float point the kernel finds inside is
// inside the box.
void roomBox(const BoundingBox& room, const Relative& r, cl_float4& lo, cl_float4& hi) {
  const BoundingBox box{room.lo - r.origin, room.hi - r.origin};
  for (int i = 0; i < 3; ++i) {
    float l = static_cast<float>(box.lo[i]), h = static_cast<float>(box.hi[i]);
    if (l < box.lo[i]) l = std::nextafter(l, std::numeric_limits<float>::infinity());
    if (h > box.hi[i]) h = std::nextafter(h, -std::numeric_limits<float>::infinity());
    lo.s[i] = l;
    hi.s[i] = h;
  }
  lo.s[3] = hi.s[3] = 0.0f;
}

// Rectangles (u0, u1, v0, v1) in coordinates u = x·axisU, v = x·axisV, made relative.
std::array<double, 4> relativeRect(const std::array<double, 4>& rect, const Aperture& a,
                                   const Relative& r) {
  const double u = a.axisU.dot(r.origin), v = a.axisV.dot(r.origin);
  return {rect[0] - u, rect[1] - u, rect[2] - v, rect[3] - v};
}

// The index of the luminance polynomial of `source`'s `face` in packed.luminances (appended), or
// -1 for a uniform luminance (a polynomial of order 0 is one: halfLuminanceOf folds its
// coefficient in). Throws std::runtime_error beyond the kernel's order.
int packLuminance(const Source& source, const ConvexPolygon& face, KernelScene& packed) {
  const std::vector<double>& c = source.luminanceCoefficients;
  if (c.size() <= 1) return -1;
  if (c.size() > PN_MAX_LUMINANCE_TERMS)
    throw std::runtime_error(fmt::format(
        "source '{}': a luminance polynomial of order {}; the kernel handles at most {}",
        source.name, c.size() - 1, PN_MAX_LUMINANCE_TERMS - 1));
  PnLuminancePolynomial poly{};
  poly.order = static_cast<int>(c.size()) - 1;
  poly.axis = toFloat4(source.polynomialAxis(face));
  for (std::size_t k = 0; k < c.size(); ++k) poly.coefficient[k] = static_cast<float>(c[k]);
  packed.luminances.push_back(poly);
  return static_cast<int>(packed.luminances.size()) - 1;
}

// The factor in front of the face's contour sum: L/2, times the constant of a polynomial of
// order 0, which is then Lambert's sum bit for bit.
float halfLuminanceOf(const Source& source) {
  const std::vector<double>& c = source.luminanceCoefficients;
  return static_cast<float>(0.5 * source.luminance * (c.size() == 1 ? c[0] : 1.0));
}

PnAperture packAperture(const Aperture& a, const Relative& r) {
  PnAperture p{};
  p.plane = r.plane(a.plane);
  roomBox(a.room, r, p.roomLo, p.roomHi);
  p.axisU = toFloat4(a.axisU);
  p.axisV = toFloat4(a.axisV);
  p.sourceRect = toFloat4(relativeRect(a.sourceRect, a, r));
  p.openingRect = toFloat4(relativeRect(a.openingRect, a, r));
  p.thickness.s[0] = static_cast<float>(a.plane.offset - a.sourceDepth);
  return p;
}

int appendPlanes(KernelScene& packed, const std::vector<Plane>& planes, const Relative& r) {
  for (const Plane& p : planes) packed.planes.push_back(r.plane(p));
  return static_cast<int>(planes.size());
}

void appendOccluder(KernelScene& packed, const ShadowCaster& caster, const ConvexPolygon& face,
                    const Tolerance& tolerance, const Relative& r) {
  const ConvexPolyhedron& shape = caster.shape;
  if (shape.faces().size() > PN_MAX_OCCLUDER_FACES)
    throw std::runtime_error(fmt::format("a solid has {} faces; the kernel handles at most {}",
                                         shape.faces().size(), PN_MAX_OCCLUDER_FACES));
  // The scene's tables grow to hundreds of MB with thousands of element faces (interreflection):
  // their pages are mapped as they grow (memory/page_prefault.hpp).
  const std::size_t faces = shape.faces().size();
  reservePopulated(packed.planes,
                   2 * faces + caster.volume.penumbra.size() + caster.volume.umbra.size());
  reservePopulated(packed.edges, shape.edges().size());
  reservePopulated(packed.occluderVertices, shape.vertices().size());
  reservePopulated(packed.occluders, 1);
  PnOccluder o{};
  o.solid = caster.solid;
  o.behindAperture = caster.behindAperture ? 1 : 0;
  o.firstPlane = static_cast<int>(packed.planes.size());
  o.planeCount = static_cast<int>(shape.faces().size());
  for (const auto& f : shape.faces()) packed.planes.push_back(r.plane(f.plane));
  o.firstSeparating = static_cast<int>(packed.planes.size());
  for (const auto& f : shape.faces())
    if (nishitaH(f.plane, face, tolerance.length) == Side::Positive)
      packed.planes.push_back(r.plane(f.plane));
  o.separatingCount = static_cast<int>(packed.planes.size()) - o.firstSeparating;
  o.firstPenumbra = static_cast<int>(packed.planes.size());
  o.penumbraCount = appendPlanes(packed, caster.volume.penumbra, r);
  o.firstUmbra = static_cast<int>(packed.planes.size());
  o.umbraCount = appendPlanes(packed, caster.volume.umbra, r);
  o.firstEdge = static_cast<int>(packed.edges.size());
  o.edgeCount = static_cast<int>(shape.edges().size());
  for (const auto& e : shape.edges())
    packed.edges.push_back(cl_int4{{e.from, e.to, e.left, e.right}});
  o.firstVertex = static_cast<int>(packed.occluderVertices.size());
  o.vertexCount = static_cast<int>(shape.vertices().size());
  const Vec3 centre = shape.centroid();
  double radius = 0.0;
  for (const Vec3& v : shape.vertices()) {
    packed.occluderVertices.push_back(r.position(v));
    radius = std::max(radius, (v - centre).norm());
  }
  // The sphere is a culling bound: grow it by the kernel's tolerance where its farthest point
  // lies, so that float rounding of the centre never makes it miss a corner.
  const double reach = (centre - r.origin).cwiseAbs().maxCoeff() + radius;
  o.bound = r.point(centre, radius + Tolerance::kernelLength(reach));
  packed.occluders.push_back(o);
}

// The kernel's __global arguments after `params`, in its order: the name it gives each and the
// IlluminanceBuffers field bound to it. The one list of the binding (bindIlluminanceArguments and
// illuminanceArgumentNames read it).
struct BufferArgument {
  const char* name;
  const compute::DeviceBuffer* IlluminanceBuffers::*buffer;
};
constexpr BufferArgument kBufferArguments[] = {
    {"point_x", &IlluminanceBuffers::pointX},
    {"point_y", &IlluminanceBuffers::pointY},
    {"point_z", &IlluminanceBuffers::pointZ},
    {"point_x_lo", &IlluminanceBuffers::pointXLo},
    {"point_y_lo", &IlluminanceBuffers::pointYLo},
    {"point_z_lo", &IlluminanceBuffers::pointZLo},
    {"normal_x", &IlluminanceBuffers::normalX},
    {"normal_y", &IlluminanceBuffers::normalY},
    {"normal_z", &IlluminanceBuffers::normalZ},
    {"point_solid", &IlluminanceBuffers::pointSolid},
    {"faces", &IlluminanceBuffers::faces},
    {"source_vertices", &IlluminanceBuffers::sourceVertices},
    {"luminances", &IlluminanceBuffers::luminances},
    {"occluders", &IlluminanceBuffers::occluders},
    {"planes", &IlluminanceBuffers::planes},
    {"edges", &IlluminanceBuffers::edges},
    {"occluder_vertices", &IlluminanceBuffers::occluderVertices},
    {"apertures", &IlluminanceBuffers::apertures},
    {"patch_faces", &IlluminanceBuffers::patchFaces},
    {"candidates", &IlluminanceBuffers::candidates},
    {"link_start", &IlluminanceBuffers::linkStart},
    {"link_faces", &IlluminanceBuffers::linkFaces},
    {"illuminance_lx", &IlluminanceBuffers::illuminance},
    {"errors", &IlluminanceBuffers::errors},
    {"classes", &IlluminanceBuffers::classes},
};
constexpr const char* kParamsArgument = "params";

}  // namespace

PnPosition toPosition(const Vec3& x, const Vec3& origin) {
  const Vec3 d = x - origin;
  PnPosition p{};
  for (int k = 0; k < 3; ++k) {
    // hi is read back through a volatile: GCC 12 at -O2 and -O3 may fold the round trip
    // double → float → double of vectorised code into nothing, which would leave lo = 0.
    const volatile float hi = static_cast<float>(d[k]);
    p.hi.s[k] = hi;
    p.lo.s[k] = static_cast<float>(d[k] - static_cast<double>(p.hi.s[k]));
  }
  return p;
}

std::string illuminanceBuildOptions() {
  return fmt::format(
      "-cl-std=CL1.2 -DPN_EPS_REL={:.9g}f -DPN_EPS_LENGTH_REL={:.9g}f -DPN_TIE_REL={:.9g}f",
      Tolerance::kKernelRelative, Tolerance::kKernelLengthRelative, Tolerance::kKernelTie);
}

std::vector<std::string> illuminanceArgumentNames() {
  std::vector<std::string> names = {kParamsArgument};
  for (const BufferArgument& argument : kBufferArguments) names.emplace_back(argument.name);
  return names;
}

void bindIlluminanceArguments(compute::KernelLaunch& launch, const PnLaunchParams& params,
                              const IlluminanceBuffers& buffers) {
  unsigned index = 0;
  launch.arg(index++, &params, sizeof params);
  for (const BufferArgument& argument : kBufferArguments) {
    const compute::DeviceBuffer* buffer = buffers.*argument.buffer;
    if (buffer == nullptr)
      throw std::logic_error(
          fmt::format("the illuminance kernel's argument {} has no buffer", argument.name));
    launch.arg(index++, *buffer);
  }
}

double kernelLengthAt(const KernelScene& packed, std::span<const SamplePoint> points) {
  double reach = 0.0;
  for (const SamplePoint& p : points)
    reach = std::max(reach, (p.position - packed.origin).cwiseAbs().maxCoeff());
  return Tolerance::kernelLength(reach);
}

KernelScene packSceneFrame(const Scene& scene) {
  KernelScene packed;
  packed.origin = scene.kernelOrigin();
  packed.epsLength = static_cast<float>(Tolerance::kernelLength(0.0));
  packed.sourceCount = static_cast<int>(scene.sources.size());
  return packed;
}

void packFace(KernelScene& packed, const Scene& scene, const EmittingFaceShadows& emitting,
              const Tolerance& tolerance) {
  const Relative r{packed.origin};
  const Source& source = scene.sources[emitting.source];
  const ConvexPolygon& face = emitting.face;
  if (face.size() > PN_MAX_SOURCE_VERTICES)
    throw std::runtime_error(
        fmt::format("source '{}' has a face with {} vertices; the kernel handles at most {}",
                    source.name, face.size(), PN_MAX_SOURCE_VERTICES));
  PnSourceFace f{};
  f.plane = r.plane(face.plane());
  f.firstVertex = static_cast<int>(packed.sourceVertices.size());
  f.vertexCount = face.size();
  for (const Vec3& v : face.vertices()) packed.sourceVertices.push_back(r.position(v));
  f.halfLuminance = halfLuminanceOf(source);
  f.luminance = packLuminance(source, face, packed);
  f.source = emitting.source;
  f.aperture = -1;
  if (emitting.aperture) {
    f.aperture = static_cast<int>(packed.apertures.size());
    packed.apertures.push_back(packAperture(*emitting.aperture, r));
  }
  if (emitting.casterOwner >= 0) {
    // The owner was packed before: its occluders serve this face too.
    const PnSourceFace& owner = packed.faces[static_cast<std::size_t>(emitting.casterOwner)];
    f.firstOccluder = owner.firstOccluder;
    f.occluderCount = owner.occluderCount;
  } else {
    f.firstOccluder = static_cast<int>(packed.occluders.size());
    for (const ShadowCaster& caster : emitting.casters)
      appendOccluder(packed, caster, face, tolerance, r);
    f.occluderCount = static_cast<int>(packed.occluders.size()) - f.firstOccluder;
  }
  packed.faces.push_back(f);
}

KernelScene packScene(const Scene& scene, const SceneShadows& shadows) {
  KernelScene packed = packSceneFrame(scene);
  for (const EmittingFaceShadows& emitting : shadows.faces)
    packFace(packed, scene, emitting, shadows.tolerance);
  return packed;
}

}  // namespace penumbra
