// Virtual stamps (the paper's Section 3 and Figure 3, after Lee 2005): circles printed on a
// panel in pattern space. After deformation each stamp's outline is followed onto the garment,
// unrolled onto the body's tangent plane at the stamp's centre, and fitted by a homogeneous
// deformation: its principal stretches and directions. docs/instruments.md gives the fit.
#pragma once

#include "bodies/rigid_body.h"
#include "core/garment.h"
#include "instruments/pattern_point.h"

#include <string>
#include <vector>

namespace tightfit {

struct StampDefinition {
  std::string name;
  int panel = 0;
  Vec2 centre_m = Vec2::Zero();  // in the panel's grain axes (x weft, y warp), m
  double radius_m = 0.02;        // the paper's stamps: outer radius 2 cm
};

// A stamp found on the mesh: its centre and outline as material points.
struct PrintedStamp {
  StampDefinition definition;
  MaterialPoint centre;
  std::vector<MaterialPoint> outline;  // at equal angles round the circle
  std::vector<Vec2> outline_rest_m;    // the same points in pattern space, from the centre
};

// Throws std::invalid_argument naming the stamp when its circle leaves its panel.
PrintedStamp print_stamp(const SimulationMesh& mesh, const StampDefinition& stamp,
                         int n_outline_points = 360);

struct StampFit {
  Vec3 centre_m = Vec3::Zero();  // the stamp's centre on the deformed garment
  Vec3 normal = Vec3::UnitZ();   // the body's outward normal there
  // The fitted deformation gradient from the grain axes to 3D, tangent to the body.
  Mat32 deformation_gradient = Mat32::Zero();
  double stretch_max = 1.0, stretch_min = 1.0;                        // principal stretches
  Vec3 direction_max = Vec3::UnitX(), direction_min = Vec3::UnitY();  // deformed, unit
  double grain_angle_max_deg = 0.0;  // the direction of stretch_max in pattern space, from the weft
};

// Fits the deformed outline: each short chord between neighbouring outline points is turned
// with the body's normal onto the tangent plane at the centre (unrolling the outline, exact on
// a developable body such as a cylinder), and the least-squares linear map from the rest
// chords gives the deformation gradient. Chords measure lengths in the garment's own
// (piecewise flat) metric, as its elements do.
StampFit fit_stamp(const SimulationMesh& mesh, const std::vector<Vec3>& positions_m,
                   const PrintedStamp& stamp, const RigidBody& body);

}  // namespace tightfit
