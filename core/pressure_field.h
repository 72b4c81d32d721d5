// A pressure map on the garment's vertices, as the pressure extractor
// (contact/pressure_extractor.h) makes it and the writers (io/) and measurements read it
// (docs/model.md, "The pressure extractor").
#pragma once

#include "core/mesh_geometry.h"
#include "core/types.h"

#include <vector>

namespace tightfit {

enum class PressureDefinition {
  contact_traction,  // the contact force along the body's normal (what a skin sensor reads)
  garment_force,     // the garment's own force along its normal (the paper's Section 2.2)
};
const char* to_string(PressureDefinition definition);

struct PressureField {
  VertexAreaDefinition area_definition = VertexAreaDefinition::barycentric;
  PressureDefinition definition = PressureDefinition::contact_traction;
  std::vector<double> pressure_Pa;
  std::vector<double> normal_force_N;  // the force pressing onto the body, by the definition
  // |tangential contact force| / vertex area, Pa: the friction traction.
  std::vector<double> friction_traction_Pa;
  std::vector<double> vertex_area_m2;
  std::vector<Vec3> normal;  // unit, pointing away from the body
  std::vector<char> contact;
};

// A triangulated surface for drawing a body (ParaView output, pictures); not used for contact.
struct DisplayMesh {
  std::vector<Vec3> vertices_m;
  std::vector<Triangle> triangles;
};

}  // namespace tightfit
