/* Occluder culling shared by both paths, and the shadow tests of one face. An occluder cannot shade
 * P from the face when
 *  - P lies on it (the solid P belongs to), or
 *  - one of its separating planes (faces whose closed outside holds the whole source face) has
 *    P in its closed outside too: every segment P→source then stays in that half-space, or
 *  - it misses the pyramid P + cone(S'), S' the visible part of the face before occlusion:
 *    its bounding sphere outside one side plane or wholly below the horizon, or (through an
 *    aperture) all its vertices outside one side plane (outside_source_pyramid). */

#include "aperture.cl"

inline bool occluder_separated(float3 p, PnOccluder o, const PnSceneTables* tables,
                               float eps_length) {
  for (int j = 0; j < o.separatingCount; ++j) {
    float4 pl = tables->planes[o.firstSeparating + j];
    if (dot(pl.xyz, p) - pl.w >= -eps_length) return true;
  }
  return false;
}

/* The shadow volumes of an occluder for this face (host/shadow/shadow_volume.hpp): inside the
 * penumbra volume grown by eps the occluder may shade P; deeper than eps inside the umbra
 * volume it hides the whole face. Both err on the safe side (the exact path decides). */
inline bool in_penumbra_volume(float3 p, PnOccluder o, const PnSceneTables* tables,
                               float eps_length) {
  for (int j = 0; j < o.penumbraCount; ++j) {
    float4 pl = tables->planes[o.firstPenumbra + j];
    if (dot(pl.xyz, p) - pl.w > eps_length) return false;
  }
  return true;
}

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

typedef struct {
  int8 umbra;  /* some occluder hides the whole face */
  int8 shaded; /* some occluder may block part of it: the penumbra path */
} ShadowTests;

ShadowTests shadow_tests8(float8 px, float8 py, float8 pz, int8 own, PnSourceFace face,
                          PnPatchFace pf, bool culling, ApertureView8 view, PnAperture ap,
                          const PnSceneTables* tables, float eps_length, int8* inside_out) {
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
      for (int j = 0; j < o.penumbraCount && pn_any(inside); ++j) {
        float4 pl = tables->planes[o.firstPenumbra + j];
        inside &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) <= eps_length;
      }
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
      if (o.umbraCount == 0) continue;
      int8 hidden = inside;
      for (int j = 0; j < o.umbraCount && pn_any(hidden); ++j) {
        float4 pl = tables->planes[o.firstUmbra + j];
        hidden &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) < -eps_length;
      }
      tests.umbra |= hidden;
    } else {
      for (int j = 0; j < o.separatingCount; ++j) {
        float4 pl = tables->planes[o.firstSeparating + j];
        inside &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) < -eps_length;
      }
      tests.shaded |= inside;
    }
  }
  tests.shaded &= ~tests.umbra;
  return tests;
}
