#include "contact/pressure_extractor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tightfit {

PressureField extract_pressure(const std::vector<Triangle>& triangles, const SurfaceState& state,
                               VertexAreaDefinition area_definition, const RigidBody* body,
                               PressureDefinition definition) {
  const int n = static_cast<int>(state.size());
  PressureField field;
  field.area_definition = area_definition;
  field.definition = definition;
  field.vertex_area_m2 = vertex_areas(triangles, state.positions_m, n, area_definition);
  field.normal = vertex_normals(triangles, state.positions_m, n);
  field.contact = state.in_contact;
  field.contact.resize(n, 0);
  field.pressure_Pa.assign(n, 0.0);
  field.normal_force_N.assign(n, 0.0);
  field.friction_traction_Pa.assign(n, 0.0);
  const bool has_contact_forces = static_cast<int>(state.contact_force_N.size()) == n;
  for (int v = 0; v < n; ++v) {
    Vec3& normal = field.normal[v];
    Vec3 body_normal = normal;
    if (body) {
      body_normal = body->query(state.positions_m[v]).outward_normal;
      if (normal.dot(body_normal) < 0) normal = -normal;
    }
    const double area = field.vertex_area_m2[v];
    if (has_contact_forces) {
      const Vec3& contact = state.contact_force_N[v];
      const Vec3 tangential = contact - contact.dot(body_normal) * body_normal;
      if (area > 0) field.friction_traction_Pa[v] = tangential.norm() / area;
    }
    if (definition == PressureDefinition::contact_traction)
      field.normal_force_N[v] = has_contact_forces ? state.contact_force_N[v].dot(body_normal) : 0;
    else
      field.normal_force_N[v] = -state.internal_force_N[v].dot(normal);
    if (area > 0) field.pressure_Pa[v] = field.normal_force_N[v] / area;
  }
  return field;
}

PressureSummary summarize(const PressureField& field) {
  PressureSummary s;
  double sum = 0.0;
  s.min_Pa = std::numeric_limits<double>::infinity();
  s.max_Pa = -std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < field.pressure_Pa.size(); ++v) {
    if (!field.contact[v]) continue;
    const double p = field.pressure_Pa[v];
    ++s.n_contact;
    sum += p;
    s.min_Pa = std::min(s.min_Pa, p);
    s.max_Pa = std::max(s.max_Pa, p);
  }
  if (!field.pressure_Pa.empty())
    s.contact_fraction = double(s.n_contact) / double(field.pressure_Pa.size());
  if (s.n_contact == 0) {
    s.min_Pa = s.max_Pa = 0.0;
    return s;
  }
  s.mean_Pa = sum / s.n_contact;
  // Two passes: the spread of a nearly uniform field (the contact traction of a tube) is far
  // below the mean, where E[p^2] - E[p]^2 would leave only round-off.
  double sum_squares = 0.0;
  for (std::size_t v = 0; v < field.pressure_Pa.size(); ++v)
    if (field.contact[v])
      sum_squares += (field.pressure_Pa[v] - s.mean_Pa) * (field.pressure_Pa[v] - s.mean_Pa);
  s.std_Pa = std::sqrt(sum_squares / s.n_contact);
  return s;
}

AngularProfile pressure_against_angle(const PressureField& field,
                                      const std::vector<Vec3>& positions_m,
                                      const Cylinder& cylinder, int n_bins) {
  AngularProfile profile;
  std::vector<double> sum(n_bins, 0.0);
  profile.n_vertices.assign(n_bins, 0);
  const double width_deg = 360.0 / n_bins;
  for (std::size_t v = 0; v < positions_m.size(); ++v) {
    if (!field.contact[v]) continue;
    const int bin = std::min(n_bins - 1, int(cylinder.angle_deg(positions_m[v]) / width_deg));
    sum[bin] += field.pressure_Pa[v];
    ++profile.n_vertices[bin];
  }
  for (int b = 0; b < n_bins; ++b) {
    profile.theta_deg.push_back((b + 0.5) * width_deg);
    profile.pressure_Pa.push_back(profile.n_vertices[b] > 0
                                      ? sum[b] / profile.n_vertices[b]
                                      : std::numeric_limits<double>::quiet_NaN());
  }
  return profile;
}

}  // namespace tightfit
