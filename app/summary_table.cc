#include "app/summary_table.h"

#include "cases/cylinder_theory.h"
#include "core/units.h"

#include <cmath>
#include <cstdio>
#include <ostream>

namespace tightfit {

TextTable pressure_summary_table(const CylinderSetup& setup, const RunResult& result) {
  const CaseParameters& c = setup.parameters;
  TextTable table("Pressure on the cylinder: garment '" + c.garment.name + "', " + c.law + ", " +
                      to_string(c.protocol.end_condition) + " ends, " + result.backend +
                      " backend, " + to_string(c.pressure.vertex_area) + " vertex area",
                  {"step", "alpha", "r [mm]", "p_mean [Pa]", "spread [%]", "theory [Pa]",
                   "error [%]", "Eq.7 [Pa]", "p [gf/cm2]", "p [mmHg]", "contact [%]"});
  for (const StepMeasurement& m : result.steps) {
    const double spread = m.p_mean_Pa() > 0 ? 100.0 * m.summary.std_Pa / m.p_mean_Pa() : NAN;
    table.add_row({std::to_string(m.step), format_fixed(m.alpha, 3),
                   format_fixed(1e3 * m.radius_m, 2), format_fixed(m.p_mean_Pa(), 2),
                   format_fixed(spread, 2), format_fixed(m.p_theory_Pa, 2),
                   format_fixed(100.0 * m.rel_error, 2), format_fixed(m.p_eq7_Pa, 2),
                   format_fixed(units::to_gf_per_cm2(m.p_mean_Pa()), 3),
                   format_fixed(units::to_mmHg(m.p_mean_Pa()), 3),
                   format_fixed(100.0 * m.summary.contact_fraction, 1)});
  }
  return table;
}

void print_case_header(std::ostream& out, const std::string& case_file,
                       const CylinderSetup& setup) {
  const CaseParameters& c = setup.parameters;
  char line[512];
  out << "Case " << case_file << "\n";
  std::snprintf(line, sizeof line,
                "  garment '%s': %d panels %.2f x %.2f cm, rest circumference %.2f cm (R0 = "
                "%.3f cm)\n",
                c.garment.name.c_str(), c.garment.n_panels, 100 * c.garment.panel_width_m,
                100 * c.garment.panel_height_m, 100 * setup.garment.ring_circumference_m,
                100 * setup.rest_radius_m);
  out << line;
  std::snprintf(line, sizeof line, "  mesh: %d vertices, %zu triangles, mean edge %.2f cm\n",
                setup.mesh.n_vertices, setup.mesh.triangles.size(), 100 * setup.mean_edge_length_m);
  out << line;
  std::snprintf(line, sizeof line,
                "  material: %s, Et weft %.3g N/m, warp %.3g N/m, nu12 %.4g; body: cylinder "
                "r0 = %.2f cm, grown to alpha %.3g in %zu steps\n",
                c.law.c_str(), c.fabric.stiffness_weft_N_per_m, c.fabric.stiffness_warp_N_per_m,
                c.fabric.poisson_weft_warp, 100 * c.body.initial_radius_m, c.protocol.final_alpha,
                setup.alphas.size() - 1);
  out << line;
  std::snprintf(line, sizeof line, "  backend: %s; %s ends; penalty stiffness %.3g Pa/m\n",
                c.backend.c_str(), to_string(c.protocol.end_condition),
                setup.problem.contact_stiffness_Pa_per_m);
  out << line;
}

}  // namespace tightfit
