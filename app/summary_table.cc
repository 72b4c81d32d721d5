#include "app/summary_table.h"

#include "core/units.h"

#include <cmath>
#include <cstdio>
#include <ostream>

namespace tightfit {

namespace {

// "free" without constraints, else e.g. "bottom, top held along (1, 0, 0)".
std::string describe_constraints(const Problem& problem) {
  if (problem.constraints.empty()) return "no constraints (free ends)";
  std::string text;
  for (const VertexConstraint& c : problem.constraints) {
    char line[160];
    if (c.kind == VertexConstraint::Kind::fixed)
      std::snprintf(line, sizeof line, "%s fixed", c.group.c_str());
    else
      std::snprintf(line, sizeof line, "%s held along (%g, %g, %g)", c.group.c_str(),
                    c.direction.x(), c.direction.y(), c.direction.z());
    text += (text.empty() ? "" : ", ") + std::string(line);
  }
  return text;
}

}  // namespace

TextTable pressure_summary_table(const Scenario& scenario, const RunResult& result) {
  const CaseParameters& c = scenario.parameters;
  std::vector<std::string> columns{"step",       "alpha",      "p_mean [Pa]", "spread [%]",
                                   "theory [Pa]", "error [%]", "p [gf/cm2]",  "p [mmHg]",
                                   "contact [%]"};
  columns.insert(columns.end(), result.columns.begin(), result.columns.end());
  TextTable table("Pressure on the " + scenario.body->body().name() + ": garment '" +
                      c.garment.name + "', " + c.law + ", " + describe_constraints(scenario.problem) +
                      ", " + result.backend + " backend, " + to_string(c.pressure.vertex_area) +
                      " vertex area, " + to_string(c.pressure.definition),
                  columns);
  for (const StepMeasurement& m : result.steps) {
    const double spread = m.p_mean_Pa() > 0 ? 100.0 * m.summary.std_Pa / m.p_mean_Pa() : NAN;
    std::vector<std::string> row{std::to_string(m.step),
                                 format_fixed(m.alpha, 3),
                                 format_fixed(m.p_mean_Pa(), 2),
                                 format_fixed(spread, 2),
                                 format_fixed(m.p_theory_Pa, 2),
                                 format_fixed(100.0 * m.rel_error, 2),
                                 format_fixed(units::to_gf_per_cm2(m.p_mean_Pa()), 3),
                                 format_fixed(units::to_mmHg(m.p_mean_Pa()), 3),
                                 format_fixed(100.0 * m.summary.contact_fraction, 1)};
    for (double value : m.extra_values) row.push_back(format_number(value, 5));
    table.add_row(row);
  }
  return table;
}

void print_case_header(std::ostream& out, const std::string& case_file,
                       const Scenario& scenario) {
  const CaseParameters& c = scenario.parameters;
  char line[512];
  out << "Case " << case_file << "\n";
  out << "  garment '" << c.garment.name << "': " << scenario.garment.description << "\n";
  std::snprintf(line, sizeof line, "  mesh: %d vertices, %zu triangles, mean edge %.2f cm\n",
                scenario.mesh.n_vertices, scenario.mesh.triangles.size(),
                100 * scenario.mean_edge_length_m);
  out << line;
  std::snprintf(line, sizeof line,
                "  material: %s, Et weft %.3g N/m, warp %.3g N/m, nu12 %.4g; body: %s, alpha up "
                "to %.3g in %zu steps\n",
                c.law.c_str(), c.fabric.stiffness_weft_N_per_m, c.fabric.stiffness_warp_N_per_m,
                c.fabric.poisson_weft_warp, scenario.body->describe().c_str(),
                c.protocol.final_alpha, scenario.alphas.size() - 1);
  out << line;
  std::snprintf(line, sizeof line, "  backend: %s; %s; penalty stiffness %.3g Pa/m\n",
                c.backend.c_str(), describe_constraints(scenario.problem).c_str(),
                scenario.problem.contact_stiffness_Pa_per_m);
  out << line;
}

}  // namespace tightfit
