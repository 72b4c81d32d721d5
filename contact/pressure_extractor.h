// The pressure extractor shared by both backends (docs/model.md, "The pressure extractor").
//
// At each vertex a normal force divided by the vertex area, p_v = F_v / A_v, in one of two
// definitions:
//   - contact traction (the default): what a sensor on the skin reads, the body's force on the
//     garment along the body's outward normal, F_v = c_v . n_body;
//   - garment force (the paper's Section 2.2): the garment's own force along the vertex normal
//     n_v (pointing away from the body), F_v = -(f_v . n_v).
// Without gravity the two agree at equilibrium (f_v balances c_v); with gravity the garment's
// weight presses where it lies on the body and hangs where it lies below, which only the
// contact traction reads. The tangential part of the contact force over the area is the
// friction traction (zero on the frictionless bodies of today).
#pragma once

#include "bodies/cylinder.h"
#include "bodies/rigid_body.h"
#include "core/mesh_geometry.h"
#include "core/pressure_field.h"
#include "core/surface_state.h"

#include <vector>

namespace tightfit {

// `body` orients the normals (away from it) and gives the contact traction its normal; with no
// body the triangles' winding does both.
PressureField extract_pressure(
    const std::vector<Triangle>& triangles, const SurfaceState& state,
    VertexAreaDefinition area_definition, const RigidBody* body,
    PressureDefinition definition = PressureDefinition::contact_traction);

struct PressureSummary {
  int n_contact = 0;
  double contact_fraction = 0.0;  // vertices in contact / all vertices
  double mean_Pa = 0.0;           // over the vertices in contact (zero when none)
  double std_Pa = 0.0;            // population standard deviation over the same vertices
  double min_Pa = 0.0;
  double max_Pa = 0.0;
};
PressureSummary summarize(const PressureField& field);

// Mean pressure of the contact vertices in `n_bins` equal sectors round a cylinder's axis
// (the paper's Figures 11 and 13); a sector without contact vertices holds NaN.
struct AngularProfile {
  std::vector<double> theta_deg;  // sector centres
  std::vector<double> pressure_Pa;
  std::vector<int> n_vertices;
};
AngularProfile pressure_against_angle(const PressureField& field,
                                      const std::vector<Vec3>& positions_m,
                                      const Cylinder& cylinder, int n_bins);

}  // namespace tightfit
