/* Structs that cross the host/kernel boundary, declared once (docs/architecture.md). Plain C with
 * explicit 16-byte-aligned layout; the host static_asserts the sizes. Included by the host (C++)
 * and by kernel files by name (`#include "shared_types.h"`, resolved by cmake/EmbedKernels.cmake).
 */
#ifndef PENUMBRA_SHARED_TYPES_H
#define PENUMBRA_SHARED_TYPES_H

#ifdef __OPENCL_C_VERSION__
typedef float4 pn_float4;
typedef int pn_int;
typedef int4 pn_int4;
#else
#include <CL/cl_platform.h>
typedef cl_float4 pn_float4;
typedef cl_int pn_int;
typedef cl_int4 pn_int4;
#endif

/* Limits the kernel's private arrays are sized for; the host refuses scenes beyond them. */
#define PN_MAX_SOURCE_VERTICES 256 /* vertices of one emitting face */
#define PN_MAX_OCCLUDER_FACES 4096 /* faces of one occluder (a sanity bound) */
#define PN_MAX_ACTIVE_OCCLUDERS 64 /* occluders that can shade one point from one face */
#define PN_MAX_VISIBLE_PIECES 32   /* visible parameter intervals on one edge */
#define PN_MAX_CONTACTS 8          /* solids whose surface one point touches (besides its own) */
#define PN_MAX_WEDGES 2            /* contact solids whose edge or corner one point lies on */
#define PN_MAX_WEDGE_FACES 4       /* faces of such a solid that limit the point's view */
#define PN_MAX_CONTOUR_EDGES 256   /* contour edges of all occluders active at one point */
#define PN_LANES 8                 /* points per work-item, one per float8 lane */

/* Error bits the kernel reports per point (host turns them into an exception). */
#define PN_ERROR_TOO_MANY_OCCLUDERS 1
#define PN_ERROR_TOO_MANY_PIECES 2
#define PN_ERROR_TOO_MANY_CONTACTS 4
#define PN_ERROR_TOO_MANY_CONTOUR_EDGES 8

/* A position relative to the kernel's origin as a pair of floats (double-float): hi is the
 * position rounded to float, lo what that rounding left, rounded to float, so hi + lo carries it to
 * about 2^-48 of its size. Receiving points and the vertices of sources and occluders come this
 * way: a difference q − p is formed as (q.hi − p.hi) + (q.lo − p.lo), where the first difference
 * is exact whenever q and p are within a factor 2 of each other (Sterbenz), so a point 1 mm from a
 * shelf's edge 30 m from the origin sees that edge to float's precision of the 1 mm, not of the
 * 30 m. Plane tests read hi alone (their tolerance covers it, prelude.cl). */
typedef struct {
  pn_float4 hi; /* xyz; w 0 */
  pn_float4 lo; /* xyz; w 0 */
} PnPosition;

/* One emitting convex polygon: a polygon source, or one face of a polyhedron source. Its
 * vertices run counter-clockwise about the emission direction. */
typedef struct {
  pn_float4 plane; /* xyz: unit emission direction, w: offset (direction·x on the face) */
  pn_int firstVertex, vertexCount;
  pn_int firstOccluder, occluderCount;
  float halfLuminance; /* L/2 in cd/m²: the factor in front of Lambert's contour integral; for a
                        * polynomial luminance, half the scale of its coefficients */
  pn_int source;       /* index of the scene source */
  pn_int aperture;     /* index into the apertures, -1 for none */
  pn_int luminance;    /* index into the luminance polynomials, -1 for a uniform luminance */
} PnSourceFace;

/* A face whose luminance depends on the direction ω from the receiving point towards it as a
 * polynomial in g = w·ω, w the polynomial's unit axis (kernels/luminance_moments.cl):
 * L = 2 · halfLuminance · Σ_k coefficient[k] g^k, k = 0..order. A photometric luminaire's opening
 * has w = −N, N its emission direction (g = cos φ of the emitted direction); the CIE overcast sky
 * through an opening has w = +z (g = sin of the altitude). */
#define PN_MAX_LUMINANCE_TERMS 49 /* powers 0..48 (host/photometry/luminance_fit.hpp) */
typedef struct {
  pn_float4 axis;                            /* xyz: the unit axis w; w 0 */
  float coefficient[PN_MAX_LUMINANCE_TERMS]; /* cd/m² */
  pn_int order;
  pn_int pad1, pad2;
} PnLuminancePolynomial;

/* A face that fills an opening of the room, seen through the opening's room-side rectangle A
 * (host/shadow/aperture.hpp). A lane strictly in front of A's plane (by more than the length
 * tolerance) and inside the closed room box sees only face ∩ cone(P, A), and skips the occluders
 * flagged behindAperture. Rectangles are (u0, u1, v0, v1) in the frame u = x·axisU,
 * v = x·axisV, with axisU × axisV the emission direction. */
typedef struct {
  pn_float4 plane;          /* A's plane: xyz the emission direction, w offset */
  pn_float4 roomLo, roomHi; /* the room's box, rounded inwards to float */
  pn_float4 axisU, axisV;
  pn_float4 sourceRect, openingRect;
  pn_float4 thickness; /* x: A's offset minus the face's (the wall's thickness); yzw 0 */
} PnAperture;

/* A solid clipped to one source face's front half-space. Planes are outward; edges are
 * (from, to, left face, right face), local to this occluder: `left` is the face whose
 * counter-clockwise loop runs from -> to. The separating planes are the faces whose closed
 * outside holds the whole source face: a point in the closed outside of one of them cannot be
 * shaded by this occluder. The penumbra and umbra planes bound its shadow volumes for this
 * face (host/shadow/shadow_volume.hpp): closed insides, umbraCount 0 when none is claimed. */
typedef struct {
  pn_float4 bound; /* bounding sphere: xyz centre, w radius */
  pn_int firstPlane, planeCount;
  pn_int firstEdge, edgeCount;
  pn_int firstVertex, vertexCount;
  pn_int firstSeparating, separatingCount;
  pn_int firstPenumbra, penumbraCount;
  pn_int firstUmbra, umbraCount;
  pn_int solid;          /* scene solid it was clipped from */
  pn_int behindAperture; /* 1: cannot shade lanes that see the face through its aperture */
  pn_int pad1, pad2;
} PnOccluder;

/* Per work-item (a patch of PN_LANES points) and source face: where its candidate occluders
 * are in the candidate list, and the patch's face class. count < 0: every occluder of the face
 * (the plain path, --no-culling). */
typedef struct {
  pn_int firstCandidate, candidateCount;
  pn_int faceClass;   /* PN_CLASS_* */
  pn_int facingLanes; /* PN_CLASS_UMBRA: bit l set when lane l faces the source (class Umbra) */
} PnPatchFace;

/* The patch classes the host's patch table writes. Nishita's class A (every point sees the whole
 * face above its horizon) has no value: whether a horizon cuts the face the kernel tests itself,
 * in float, the way it clips (below_horizon8), so such patches are class B too. */
#define PN_CLASS_B 1     /* some point may receive light from the face */
#define PN_CLASS_C 2     /* no point of the patch receives anything from the face */
#define PN_CLASS_UMBRA 3 /* every point of the patch is in one occluder's umbra: E = 0 */

/* The scalar launch parameters of the illuminance kernel (kernels/illuminance.cl), passed by
 * value: OpenCL C 1.2 takes a struct kernel argument only when it holds no pointer, so the
 * buffers are arguments of their own (engine/kernel_scene.hpp binds both in one place). */
typedef struct {
  pn_int faceCount;    /* source faces in the faces table */
  float epsLength;     /* the length tolerance near the origin (m); at a point, prelude.cl */
  pn_int paths;        /* PN_PATH_* bits; none: the plain path */
  pn_int bySource;     /* 1: E per source, [source][padded point]; 0: E summed per point */
  pn_int sourceStride; /* the padded point count: the row length of per-source outputs */
  pn_int linked;       /* 1: each work-item takes its own list of faces (kernels/illuminance.cl) */
  pn_int pad2, pad3;
} PnLaunchParams;

/* The paths of a launch. Without PN_PATH_CULLING, the plain path: every occluder at every
 * point, separating planes, the scalar penumbra path. */
#define PN_PATH_CULLING 1 /* face classes, candidates, shadow volumes, apertures */
#define PN_PATH_LANES 2   /* with culling: shaded lanes take the eight-lane penumbra path */

/* Something a camera ray can hit (kernels/visibility.cl). A solid is the intersection of its
 * planes' closed insides (n·x <= w), plane i being face i, whose face id is firstFaceId + i. A
 * polygon (an area source) is its first plane, the emitting side facing +n, cut by the
 * following side planes; it is seen from its emitting side only and has one face id. A
 * polyhedron source is a solid whose faces emit; sources (polygons and polyhedra) win depth
 * ties with the solids' faces they lie on. */
typedef struct {
  pn_int firstPlane, planeCount;
  pn_int firstFaceId;
  pn_int kind; /* PN_VISIBLE_* */
} PnVisibleObject;

#define PN_VISIBLE_SOLID 0
#define PN_VISIBLE_POLYGON 1
#define PN_VISIBLE_SOURCE_SOLID 2
#define PN_VISIBILITY_TILE 16 /* screen tiles are 16 × 16 samples */

/* The point model of photometric luminaires (kernels/luminaire.cl, engine/luminaire_scene.hpp).
 * One candela table per luminaire, shared by its instances: the planes (C for type C, V for
 * type B, H for type A) and the angles within them, in degrees, increasing, at
 * angles[firstAngle ...] (planeCount plane angles, then inPlaneCount in-plane angles); the
 * intensities in cd, already times the luminaire's scale (flux override, maintenance factor), at
 * candela[firstCandela + plane * inPlaneCount + inPlane]. Type C planes are periodic over 360°. */
typedef struct {
  pn_int firstAngle, planeCount, inPlaneCount;
  pn_int firstCandela;
  pn_int type; /* PN_PHOTOMETRIC_C, _B or _A */
  pn_int pad1, pad2, pad3;
} PnCandelaTable;

#define PN_PHOTOMETRIC_C 0
#define PN_PHOTOMETRIC_B 1
#define PN_PHOTOMETRIC_A 2

/* One point source of the point model: a placed luminaire's photometric centre, or the centre of
 * a cell of its opening (relative to the kernel's origin), and the rows of the rotation from the
 * scene to the luminaire's local frame (local = R · scene). */
typedef struct {
  pn_float4 centre;
  pn_float4 toLocal0, toLocal1, toLocal2;
  pn_int table; /* index into the PnCandelaTable list */
  float share;  /* the part of the table it emits: 1, or 1/cells for a cell of an opening */
  pn_int pad2, pad3;
} PnLuminaire;

/* A solid as the point model's shadow test reads it: the intersection of its planes' closed
 * insides (n·x <= w), planes at firstPlane ..., and its bounding box. */
typedef struct {
  pn_float4 lo, hi;
  pn_int firstPlane, planeCount;
  pn_int solid; /* scene solid index: a point on it is never shaded by it */
  pn_int pad1;
} PnShadowSolid;

/* The scalar launch parameters of kernels/luminaire.cl, passed by value. */
typedef struct {
  pn_int pointCount;     /* points in the batch (the buffers may be longer) */
  pn_int luminaireCount; /* placed luminaires */
  pn_int solidCount;
  float epsLength;    /* the length tolerance near the origin (m), as for the illuminance kernel */
  pn_int pointStride; /* the row length of the per-luminaire output `seen` */
  pn_int pad1, pad2, pad3;
} PnLuminaireParams;

#endif
