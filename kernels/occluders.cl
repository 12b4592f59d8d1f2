/* Occluder culling shared by both paths, and the shadow tests of one face. An occluder cannot shade
 * P from the face when
 *  - P lies on it (the solid P belongs to), or
 *  - one of its separating planes (faces whose closed outside holds the whole source face) has
 *    P in its closed outside too: every segment P→source then stays in that half-space, or
 *  - it misses the pyramid P + cone(S'), S' the visible part of the face before occlusion:
 *    its bounding sphere outside one side plane or wholly below the horizon, or (through an
 *    aperture) all its vertices outside one side plane (outside_source_pyramid). */

#include "aperture.cl"

/* The plane tests of an occluder, written once for one point (T float, names ending in 1) and
 * eight lanes (float8, 8), M the mask type; each narrows `lanes` (or, face_sees, tests face j):
 *  - face_sees: face j of the occluder sees P (P in front of it by more than eps_length);
 *  - not_separated: no separating plane has P in its closed outside (within eps_length);
 *  - in_penumbra_volume: P inside the penumbra volume grown by eps_length, where the occluder
 *    may shade it;
 *  - in_umbra_volume: P deeper than eps_length inside the umbra volume, where the occluder hides
 *    the whole face (no lane where it claims no umbra).
 * Both volumes err on the safe side: the penumbra path decides. */
#define PN_DEFINE_OCCLUDER_TESTS(T, M, S)                                                        \
  inline M face_sees##S(PnOccluder o, int j, const PnSceneTables* tables, T px, T py, T pz,      \
                        T eps_length) {                                                          \
    return plane_height##S(tables->planes[o.firstPlane + j], px, py, pz) > eps_length;           \
  }                                                                                              \
  inline M not_separated##S(PnOccluder o, const PnSceneTables* tables, T px, T py, T pz,         \
                            T eps_length, M lanes) {                                             \
    for (int j = 0; j < o.separatingCount && pn_any(lanes); ++j)                                 \
      lanes &= plane_height##S(tables->planes[o.firstSeparating + j], px, py, pz) < -eps_length; \
    return lanes;                                                                                \
  }                                                                                              \
  inline M in_penumbra_volume##S(PnOccluder o, const PnSceneTables* tables, T px, T py, T pz,    \
                                 T eps_length, M lanes) {                                        \
    for (int j = 0; j < o.penumbraCount && pn_any(lanes); ++j)                                   \
      lanes &= plane_height##S(tables->planes[o.firstPenumbra + j], px, py, pz) <= eps_length;   \
    return lanes;                                                                                \
  }                                                                                              \
  inline M in_umbra_volume##S(PnOccluder o, const PnSceneTables* tables, T px, T py, T pz,       \
                              T eps_length, M lanes) {                                           \
    if (o.umbraCount == 0) return (M)(0);                                                        \
    for (int j = 0; j < o.umbraCount && pn_any(lanes); ++j)                                      \
      lanes &= plane_height##S(tables->planes[o.firstUmbra + j], px, py, pz) < -eps_length;      \
    return lanes;                                                                                \
  }
PN_DEFINE_OCCLUDER_TESTS(float, int, 1)
PN_DEFINE_OCCLUDER_TESTS(float8, int8, 8)
#undef PN_DEFINE_OCCLUDER_TESTS

/* The occluders a patch considers for one face: its candidate list, or (count < 0, the plain
 * path) every occluder of the face. */
inline int occluder_count(PnPatchFace pf, PnSourceFace face) {
  return pf.candidateCount < 0 ? face.occluderCount : pf.candidateCount;
}
inline int occluder_index(int i, PnPatchFace pf, PnSourceFace face, const PnSceneTables* tables) {
  return pf.candidateCount < 0 ? face.firstOccluder + i : tables->candidates[pf.firstCandidate + i];
}

/* Shadow tests of one face for eight lanes (docs/method.md, "Shadow volumes and culling"). With
 * culling: a lane deeper than eps inside an umbra volume gets 0; one inside a penumbra volume
 * (grown by eps) takes the penumbra path; the rest keep the unoccluded value. Without (the plain
 * path): a lane takes the penumbra path unless every occluder is its own solid or separated from
 * the face. */

#define PN_VEC_MASKS 64 /* candidates whose shadow-test lane masks are kept for the lane path */

typedef struct {
  int8 umbra;  /* some occluder hides the whole face */
  int8 shaded; /* some occluder may block part of it: the penumbra path */
} ShadowTests;

ShadowTests shadow_tests8(float8 px, float8 py, float8 pz, int8 own, PnSourceFace face,
                          PnPatchFace pf, bool culling, ApertureView8 view, PnAperture ap,
                          const PnSceneTables* tables, float8 eps_length, int8* inside_out) {
  const int8 aperture = view.use;
  ShadowTests tests;
  tests.umbra = 0;
  tests.shaded = 0;
  const int count = occluder_count(pf, face);
  for (int i = 0; i < count; ++i) {
    PnOccluder o = tables->occluders[occluder_index(i, pf, face, tables)];
    int8 inside = own != (int8)(o.solid);
    if (o.behindAperture) inside &= ~aperture; /* lanes that see the face through A */
    if (culling) {
      if (i < PN_VEC_MASKS) inside_out[i] = 0;
      inside = in_penumbra_volume8(o, tables, px, py, pz, eps_length, inside);
      if (!pn_any(inside)) continue;
      /* The volume is the occluder's against the whole face; lanes that see only a rectangle of
       * it through an aperture drop the occluder when it misses the pyramid to that rectangle. */
      if (pn_any(inside & aperture)) {
        inside &= ~(aperture &
                    misses_aperture_view8(px, py, pz, view, ap, face.plane, o, tables, eps_length));
        if (!pn_any(inside)) continue;
      }
      if (i < PN_VEC_MASKS) inside_out[i] = inside;
      tests.shaded |= inside;
      tests.umbra |= in_umbra_volume8(o, tables, px, py, pz, eps_length, inside);
    } else {
      tests.shaded |= not_separated8(o, tables, px, py, pz, eps_length, inside);
    }
  }
  tests.shaded &= ~tests.umbra;
  return tests;
}
