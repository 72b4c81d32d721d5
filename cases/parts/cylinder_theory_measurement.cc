// Measurements/List: cylinder theory. The closed forms of a tube on a cylinder
// (cases/cylinder_theory.h, docs/model.md): the reference pressure of the law and end
// condition in use (p_theory_Pa, rel_error), the paper's Eq. 7, the cylinder's radius, and
// under gravity the top-minus-bottom pressure, measured by a least-squares fit of
// p = a + b cos(theta) + c sin(theta) round the axis (theta from the top) beside its closed form.
#include "cases/cylinder_theory.h"
#include "cases/parts/cylinder_body.h"
#include "cases/parts/part_entries.h"
#include "cases/step_measurement.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace tightfit {

namespace {

constexpr double not_defined = std::numeric_limits<double>::quiet_NaN();

// The end condition the scenario's constraints make: free without any, held when exactly the
// tube's two end rows are held along the axis; none of the closed forms otherwise.
std::optional<EndCondition> end_condition(const Problem& problem, const Vec3& axis) {
  if (problem.constraints.empty()) return EndCondition::free_ends;
  if (problem.constraints.size() != 2) return std::nullopt;
  bool bottom = false, top = false;
  for (const VertexConstraint& c : problem.constraints) {
    if (c.kind != VertexConstraint::Kind::held_along_direction) return std::nullopt;
    if (std::abs(std::abs(c.direction.normalized().dot(axis)) - 1.0) > 1e-9) return std::nullopt;
    bottom = bottom || c.group == "bottom";
    top = top || c.group == "top";
  }
  if (bottom && top) return EndCondition::held_ends;
  return std::nullopt;
}

class CylinderTheory final : public Measurement {
 public:
  std::optional<double> reference_pressure_Pa(const Scenario& scenario,
                                              const StepMeasurement& m) const override {
    const CylinderBody& body = cylinder_body_of(*scenario.body, "Measurements: cylinder theory");
    const std::optional<EndCondition> ends =
        end_condition(scenario.problem, body.cylinder().axis());
    if (!ends) return not_defined;
    return closed_form_pressure_Pa(scenario.parameters.law, *ends, scenario.parameters.fabric,
                                   body.reference_radius_m(), m.alpha);
  }

  std::vector<std::string> columns() const override {
    return {"radius_m", "p_eq7_Pa", "p_top_minus_bottom_Pa", "p_top_minus_bottom_theory_Pa"};
  }

  std::vector<double> values(const Scenario& scenario, const StepMeasurement& m) const override {
    const CylinderBody& body = cylinder_body_of(*scenario.body, "Measurements: cylinder theory");
    const CaseParameters& c = scenario.parameters;
    const double R0 = body.reference_radius_m();
    return {body.cylinder().radius_m(),
            paper_eq7_pressure_Pa(c.fabric.stiffness_weft_N_per_m, R0, m.alpha),
            measured_top_minus_bottom_Pa(scenario, body, m),
            theory_top_minus_bottom_Pa(scenario, body, m)};
  }

 private:
  // Unit vectors across the axis: towards the top (against gravity) and sideways.
  static std::pair<Vec3, Vec3> top_and_side(const Scenario& scenario, const Cylinder& cylinder) {
    const Vec3 axis = cylinder.axis();
    Vec3 up = scenario.parameters.protocol.up.normalized();
    up -= up.dot(axis) * axis;
    const Vec3 top = up.norm() > 1e-12 ? Vec3(up.normalized()) : cylinder.reference_direction();
    return {top, axis.cross(top)};
  }

  static double measured_top_minus_bottom_Pa(const Scenario& scenario, const CylinderBody& body,
                                             const StepMeasurement& m) {
    const Cylinder& cylinder = body.cylinder();
    const auto [top, side] = top_and_side(scenario, cylinder);
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Eigen::Vector3d right_side = Eigen::Vector3d::Zero();
    int n = 0;
    for (std::size_t v = 0; v < m.state.positions_m.size(); ++v) {
      if (!m.field.contact[v]) continue;
      const Vec3 outward = cylinder.query(m.state.positions_m[v]).outward_normal;
      const Eigen::Vector3d basis(1.0, outward.dot(top), outward.dot(side));
      normal_matrix += basis * basis.transpose();
      right_side += basis * m.field.pressure_Pa[v];
      ++n;
    }
    if (n < 3) return not_defined;
    const Eigen::Vector3d fit = normal_matrix.ldlt().solve(right_side);
    return 2.0 * fit[1];
  }

  static double theory_top_minus_bottom_Pa(const Scenario& scenario, const CylinderBody& body,
                                           const StepMeasurement& m) {
    const ProtocolSettings& protocol = scenario.parameters.protocol;
    const bool gravity_on =
        m.step == 0 ? protocol.gravity_while_settling : protocol.gravity_while_measuring;
    if (!gravity_on) return 0.0;
    const std::optional<EndCondition> ends =
        end_condition(scenario.problem, body.cylinder().axis());
    if (!ends || m.alpha <= 1.0) return not_defined;
    const Vec3 axis = body.cylinder().axis();
    const Vec3 g = scenario.problem.gravity_m_per_s2;
    const double g_across = (g - g.dot(axis) * axis).norm();
    const CaseParameters& c = scenario.parameters;
    const double b = axial_stretch(c.law, *ends, c.fabric, m.alpha);
    const double w =
        tube_weight_per_area_Pa(c.fabric.areal_density_kg_per_m2, g_across, m.alpha, b);
    return gravity_top_minus_bottom_Pa(
        w, c.pressure.definition == PressureDefinition::contact_traction);
  }
};

}  // namespace

PartEntry<MeasurementMaker> cylinder_theory_measurement_entry() {
  PartEntry<MeasurementMaker> e;
  e.name = "cylinder theory";
  e.subsection = "Cylinder theory";
  e.description =
      "the closed forms of a tube on a cylinder: p_theory_Pa of the law and end condition in "
      "use, and the columns radius_m, p_eq7_Pa (the paper's Eq. 7), p_top_minus_bottom_Pa and "
      "p_top_minus_bottom_theory_Pa (under gravity).";
  e.parse = [](ParameterTree&) -> MeasurementMaker {
    return [] { return std::make_unique<CylinderTheory>(); };
  };
  return e;
}

}  // namespace tightfit
