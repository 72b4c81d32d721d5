// The garment's pressure carried onto the body's surface (docs/measurements.md, "Pressure on
// the body"), so that the body can be drawn coloured by the pressure it feels.
//
// The body's display surface is first refined (each triangle split in four, the new corners
// put back on the body's surface) until no edge is longer than a given length, about half the
// garment's edges, so that the map keeps the garment's detail. Each body vertex b then takes
// the pressure of the closest point q of the garment's surface, interpolated linearly from the
// corners of the garment triangle it lies in (vertices out of contact count as zero), when the
// garment lies on it: q is within `max_distance_m` and b - q runs along the garment's normal
// (within 45 degrees), as under the cloth, not across its edge. Elsewhere the pressure is zero.
//
// Under MPI the ranks may make the map together (RankShare, cases/nearest_over_ranks.h): each
// searches its block of the garment's triangles, and every rank gets the nearest of the blocks'
// points, decided by the exact comparison one search of the whole garment decides by; so that no
// rank holds a search tree of the whole garment (docs/performance.md, "## MPI"). The map is one
// search's but where two triangles hold exactly the same nearest point (their common edge or
// corner): one search keeps whichever its tree meets last, the ranks the lower index, and the
// two interpolate the corners' pressures with different rounding (1e-16 relative, measured).
#pragma once

#include "bodies/rigid_body.h"
#include "cases/nearest_over_ranks.h"
#include "contact/pressure_extractor.h"
#include "io/vtu_writer.h"

#include <vector>

namespace tightfit {

// `mesh` split until its longest edge is at most `max_edge_m`, or until another split would
// pass `max_triangles`; new vertices are moved onto `body`'s surface (RigidBody::query).
DisplayMesh refined_body_surface(const RigidBody& body, const DisplayMesh& mesh, double max_edge_m,
                                 std::size_t max_triangles = 400000);

struct BodySurfacePressure {
  DisplayMesh surface;
  std::vector<double> pressure_Pa;     // zero where the garment does not lie
  std::vector<double> vertex_area_m2;  // barycentric
  std::vector<char> under_garment;
  double normal_force_N = 0.0;  // sum of pressure x vertex area
};

BodySurfacePressure body_surface_pressure(DisplayMesh surface,
                                          const std::vector<Triangle>& garment_triangles,
                                          const std::vector<Vec3>& garment_positions_m,
                                          const PressureField& field, double max_distance_m,
                                          const RankShare& share = {});

struct Scenario;
struct StepMeasurement;
// The pressure of load step `m` on the scenario's body, refined to Output/Body edge length
// (default half the garment's mean edge), the garment within its mean edge length. With
// several ranks in `share`, collective: every one of them calls it.
BodySurfacePressure body_surface_pressure(const Scenario& scenario, const StepMeasurement& m,
                                          const RankShare& share = {});

// The body VTU with point data pressure_Pa, pressure_mmHg, under_garment (0/1) and
// vertex_area_m2, and field data normal_force_N (on the body) and garment_normal_force_N
// (the garment's contact vertices' pressure x area, for comparison).
SurfaceVtu body_pressure_vtu(const BodySurfacePressure& body, const PressureField& field);

}  // namespace tightfit
