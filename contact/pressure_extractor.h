// The pressure extractor shared by both backends (the paper's Section 2.2).
//
// At each vertex: the garment's own force along the vertex normal, divided by the vertex area,
// p_v = -(f_v . n_v) / A_v, with n_v pointing away from the body, so that a garment pressing
// onto the body reads a positive pressure. At equilibrium f_v balances the contact force.
#pragma once

#include "contact/cylinder.h"
#include "contact/rigid_body.h"
#include "core/mesh_geometry.h"
#include "core/surface_state.h"

#include <vector>

namespace tightfit {

struct PressureField {
  VertexAreaDefinition area_definition = VertexAreaDefinition::barycentric;
  std::vector<double> pressure_Pa;
  std::vector<double> normal_force_N;  // -(f . n): the force pressing onto the body
  std::vector<double> vertex_area_m2;
  std::vector<Vec3> normal;  // unit, pointing away from the body
  std::vector<char> contact;
};

// `body` orients the normals (away from it); with no body the triangles' winding does.
PressureField extract_pressure(const std::vector<Triangle>& triangles, const SurfaceState& state,
                               VertexAreaDefinition area_definition, const RigidBody* body);

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
