// Where a load step's residual sits, for the message of a step that cannot meet its stop rule
// (docs/backends.md, "Stalls"): the vertex holding the largest residual force, its split into the
// parts along the body's outward normal and across it, and the net force on the whole garment.
// A settle that drags on because the garment slides over the body shows a net force (the sum
// of the residuals is the contact and gravity forces' sum: the internal forces cancel), a
// contact chattering vertex a large normal part next to the body, a flapping free border a
// vertex far from it.
#pragma once

#include "bodies/rigid_body.h"
#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

struct ResidualLocation {
  int vertex = -1;  // the vertex with the largest residual (-1: no vertex)
  Vec3 position_m = Vec3::Zero();
  double largest_N = 0.0;           // |f| at that vertex
  double normal_N = 0.0;            // f . n there, n the body's outward normal at its closest point
  double tangential_N = 0.0;        // |f - (f . n) n|
  double gap_m = 0.0;               // its signed distance to the body
  Vec3 net_force_N = Vec3::Zero();  // the sum of the residuals over every vertex
  double rms_N = 0.0;               // sqrt(mean |f|^2): a spread-out residual next to a peak
};

// `body` may be null (no body: normal, tangential and gap stay 0).
ResidualLocation locate_residual(const std::vector<Vec3>& positions_m,
                                 const std::vector<Vec3>& residual_N, const RigidBody* body);

// One line: "largest residual ... on vertex i at (x, y, z) m, gap g m (normal a N, across b N);
// rms r N; net force on the garment (fx, fy, fz) N".
std::string text(const ResidualLocation& where);

}  // namespace tightfit
