// A closed (or, when allowed, open) triangulated body surface in metres, and the checks that
// make it safe to take a signed distance from (docs/bodies.md "Checks").
#pragma once

#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct TriangleSurface {
  std::vector<Vec3> vertices_m;
  std::vector<Triangle> triangles;  // counter-clockwise seen from outside
  std::vector<int> source_face;     // the file's face (from 0) each triangle was split from
};

// Throws BodyMeshError, naming the file face and vertex indices (from 0), unless every
// triangle has an area (twice the area over the longest edge squared above 1e-10), every edge
// belongs to exactly two triangles (at most two, and the boundary is allowed, when
// `allow_open_surface`), two triangles that share an edge run through it in opposite
// directions, the triangles round every vertex form a single fan, and (closed surfaces) the
// enclosed volume is positive, that is the triangles face outwards. `what` starts each
// message (the file's name).
void check_body_surface(const TriangleSurface& surface, bool allow_open_surface,
                        const std::string& what);

// The part of check_body_surface that moving the vertices can change (the faces' areas and the
// volume's sign), for a surface whose connectivity already passed.
void check_body_geometry(const TriangleSurface& surface, bool allow_open_surface,
                         const std::string& what);

// Volume enclosed by a closed surface, sum of p0 . (p1 x p2) / 6 over the triangles
// (divergence theorem): positive when the triangles face outwards.
double enclosed_volume_m3(const std::vector<Vec3>& vertices_m,
                          const std::vector<Triangle>& triangles);
double surface_area_m2(const std::vector<Vec3>& vertices_m, const std::vector<Triangle>& triangles);

}  // namespace tightfit
