// How a body mesh file is brought into tightfit's frame (metres, +z up): unit scale, the
// file's up axis, a rotation and a translation; quads are split into triangles
// (docs/bodies.md "Files and import options").
#pragma once

#include "bodies/polygon_mesh.h"
#include "bodies/triangle_surface.h"

#include <string>

namespace tightfit {

struct MeshImportOptions {
  double metres_per_unit = 1.0;  // 0.01 for a file in centimetres, 0.001 in millimetres
  // The file's up direction, one of +x, -x, +y, -y, +z, -z: it is turned onto +z (a +y-up file
  // by +90 degrees about x, so its +z front faces -y).
  std::string up_axis = "+y";
  // Then a rotation about x, y and z in that order (degrees), then a translation (m).
  Vec3 rotation_deg = Vec3::Zero();
  Vec3 translation_m = Vec3::Zero();
  // Accept a surface with a boundary (a torso cut at the neck and limbs). Its signed distance
  // is only meaningful where the closest point is not on the boundary.
  bool allow_open_surface = false;
};

// The rotation the options apply after scaling (the up axis's, then the user's). Throws
// std::invalid_argument for an unknown up axis.
Mat3 import_rotation(const MeshImportOptions& options);

// Scales, turns and moves the vertices; splits every quad (a b c d) along its first diagonal
// into (a b c) and (a c d), the same split whatever the shape, so that two meshes with one
// connectivity stay alike (morphing). Throws std::invalid_argument for a scale that is not
// positive.
TriangleSurface import_surface(const PolygonMesh& mesh, const MeshImportOptions& options);

}  // namespace tightfit
