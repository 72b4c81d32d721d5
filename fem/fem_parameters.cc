#include "fem/fem_parameters.h"

#include "core/number_text.h"

#include <deal.II/base/parameter_handler.h>

#include <stdexcept>
#include <string>

namespace tightfit {

namespace {
const char* const subsection_name = "Finite elements";
}

const char* to_string(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::direct:
      return "direct";
    case LinearSolverKind::cg_amg:
      return "cg-amg";
    case LinearSolverKind::gmres_amg:
      return "gmres-amg";
    case LinearSolverKind::cg_gamg:
      return "cg-gamg";
    case LinearSolverKind::gmres_gamg:
      return "gmres-gamg";
  }
  return "unknown";
}

bool uses_cg(LinearSolverKind kind) {
  return kind == LinearSolverKind::cg_amg || kind == LinearSolverKind::cg_gamg;
}

bool uses_gamg(LinearSolverKind kind) {
  return kind == LinearSolverKind::cg_gamg || kind == LinearSolverKind::gmres_gamg;
}

const char* to_string(SlackTreatment treatment) {
  switch (treatment) {
    case SlackTreatment::none:
      return "none";
    case SlackTreatment::tension_field:
      return "tension field";
  }
  return "unknown";
}

const char* to_string(IterativeSolverMemory memory) {
  switch (memory) {
    case IterativeSolverMemory::fast:
      return "fast";
    case IterativeSolverMemory::lean:
      return "lean";
  }
  return "unknown";
}

void FemParameters::declare_parameters(dealii::ParameterHandler& prm) {
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;
  const FemParameters d;
  prm.enter_subsection(subsection_name);
  prm.declare_entry("Element degree", std::to_string(d.element_degree), Integer(1, 2),
                    "Polynomial degree of the 3D position field on the pattern's triangles "
                    "(dimensionless). Degree 1 (linear triangles) runs the very mesh of the "
                    "mass-spring backend and assembles the same membrane forces. Degree 2 "
                    "(quadratic triangles, a 7-point rule) adds a node at every edge midpoint, "
                    "with contact there too; the output stays per vertex, each vertex reading "
                    "the contact traction recovered on the curved surface.");
  prm.declare_entry("Linear solver", to_string(d.linear_solver),
                    Selection("direct|cg-amg|gmres-amg|cg-gamg|gmres-gamg"),
                    "Solver of each Newton system: 'direct' is PETSc's MUMPS sparse LU (its "
                    "symbolic analysis is reused while the pattern holds; the default, and the "
                    "fastest on the shipped cases, docs/performance.md); 'cg-amg' is conjugate "
                    "gradients preconditioned by BoomerAMG; 'gmres-amg' is GMRES with BoomerAMG; "
                    "'cg-gamg' "
                    "and 'gmres-gamg' the same with PETSc's smoothed aggregation (GAMG), each "
                    "node's three displacements one block and the six rigid motions of the "
                    "current positions its near null space. When CG meets an indefinite tangent "
                    "it switches to GMRES, and GMRES to MUMPS, noted in the step's log line. PETSc "
                    "options with the prefix fem_ tune every one "
                    "of them (-fem_pc_type, -fem_mat_mumps_icntl_14, ...).");
  prm.declare_entry(
      "Iterative solver memory", to_string(d.iterative_solver_memory), Selection("fast|lean"),
      "What the Krylov solvers trade. 'fast': PETSc's defaults. 'lean': GAMG forms each coarse "
      "operator P^T A P all at once, never storing A P, and GMRES restarts after 30 iterations "
      "instead of 100: less memory for more CPU time (measured in docs/performance.md). "
      "Unused by 'direct'.");
  prm.declare_entry("Linear solver tolerance", "1e-10", Double(1e-16, 1e-2),
                    "Krylov solvers stop when the residual falls below eta times the right-hand "
                    "side, eta = 0.9 (|R_k|/|R_k-1|)^2 clamped to [this value, 1e-2] (inexact "
                    "Newton), and at this value where the residual falls by less than half "
                    "(dimensionless). Unused by 'direct'.");
  prm.declare_entry("Maximum linear iterations", std::to_string(d.max_linear_iterations),
                    Integer(1, 100000), "Krylov iteration limit per Newton step (count).");
  prm.declare_entry("Residual tolerance", "auto", Anything(),
                    "The FE backend's own stop rule beside Solver/Relative tolerance: Newton "
                    "stops when both hold, the other being that the residual force (Solver/Stop "
                    "norm) on every free degree of freedom is below this fraction of Y h_k, the "
                    "law's stiffness scale (N/m) times the rest edge length of its node (the mean "
                    "of the edges meeting there, m): dimensionless, 0 to 1e-2. 0: off (the "
                    "shared rule alone). auto: 0 on a body mesh with Body/Mesh/Contact surface = "
                    "faceted or Contact/Friction coefficient above 0 (fabric that sticks and "
                    "slips there leaves Newton a residual floor far above 1e-10 Y h, "
                    "docs/performance-bodies.md, 'Newton on the tops'), 1e-10 elsewhere.");
  prm.declare_entry("Maximum Newton iterations", std::to_string(d.max_newton_iterations),
                    Integer(1, 1000),
                    "Newton iterations per augmented-Lagrangian round before the step fails "
                    "(count).");
  prm.declare_entry("Line search", d.line_search ? "true" : "false", Bool(),
                    "Backtrack along each Newton direction until the residual norm decreases.");
  prm.declare_entry("Globalization", d.potential_globalization ? "potential" : "residual",
                    Selection("potential|residual"),
                    "How a Newton step is made safe (docs/backends.md, \"Newton's line search\"). "
                    "potential: in the first Newton solve of a load step the line search judges "
                    "steps by the potential (the membrane's energy, the contact penalty's "
                    "potential, less the weight's work) while the residual is well above the "
                    "potential's defect on a mesh body, a step uphill in it or cut below an "
                    "eighth grows the tangent's shift, and each step is solved again on the "
                    "contact set it predicts (up to 5 times); later, a step the line search cut "
                    "is followed by one solve on the contact set it predicts; where that defect "
                    "is also above the shared stop rule (Solver/Relative tolerance times the "
                    "tension scale) and the garment's turn is not held, the residual norm alone "
                    "judges the rest of the load step, a first solve starting again from the "
                    "step's start. residual: the residual norm alone decides, with no "
                    "prediction after a cut step.");
  prm.declare_entry("Maximum line search halvings", std::to_string(d.max_line_search_halvings),
                    Integer(0, 60), "How often a Newton step may be halved (count).");
  prm.declare_entry("Contact set predictions", "auto", Anything(),
                    "How often a Newton step may be solved again with the contact set it "
                    "predicts (count): each node in or out of contact as the linearised gap after "
                    "the step says, and with friction sticking or slipping as the linearised "
                    "offset from its anchor and normal force say, until the sides the step was "
                    "solved on are those it predicts (a primal-dual active-set step; "
                    "fem/contact_set_prediction.h), or 'auto': 1 with friction (Contact/Friction "
                    "coefficient > 0), else 0. 0: a step is solved again on its predicted "
                    "set only while the potential judges (up to 5 times, Globalization) and after "
                    "a step the line search cut (once), every other step on the nodes in contact "
                    "where it starts (docs/backends.md, \"Newton's line search\").");
  prm.declare_entry(
      "Penalty factor", "100", Double(1e-3, 1e12),
      "Contact penalty k = beta Y / h_k^2 in Pa/m at each node (Y the law's stiffness "
      "scale, h_k the mean rest length of the edges meeting there): this beta, dimensionless. "
      "Augmented-Lagrangian "
      "updates remove its effect on the pressure; it only sets how fast they "
      "converge.");
  prm.declare_entry("Maximum augmented Lagrangian iterations",
                    std::to_string(d.max_augmented_lagrangian_iterations), Integer(1, 1000),
                    "Multiplier updates per load step before the step fails (count).");
  prm.declare_entry("Tangent shift", "0", Double(0, 1e12),
                    "Added to the tangent's diagonal, N/m, on every Newton system, beside the "
                    "adaptive Levenberg-Marquardt shift Newton grows where the line search would "
                    "cut a step below an eighth (docs/backends.md, \"Newton's line search\"; no "
                    "case needs it). It changes the Newton path; the residual is not "
                    "shifted, so the step still ends at an equilibrium to the stop rule (where "
                    "there are several, as for fabric slipping at friction's limit, not "
                    "necessarily the same one).");
  prm.declare_entry("Residual shift factor", "1", Double(0, 1e12),
                    "Each Newton system is solved with the tangent shifted by theta |R|_max / h "
                    "(N/m; |R|_max the largest residual force, N; h the mean rest edge, m): this "
                    "theta, dimensionless. The shift vanishes with the residual (quadratic "
                    "convergence is kept) and lets Newton through states where the tangent is "
                    "singular, such as a tube touching the body at zero tension. 0 turns it off.");
  prm.declare_entry("Pseudo time steps", std::to_string(d.max_pseudo_time_steps),
                    Integer(0, 100000),
                    "With friction (Contact/Friction coefficient > 0): at most this many "
                    "pseudo-transient steps open each load step, before Newton's rounds "
                    "(docs/backends.md, \"Pseudo-transient continuation\"; count). Each solves "
                    "(K + sigma I) dx = -R once, with no line search, sigma falling as the "
                    "residual falls; at the stop rule Newton's contact rounds take over. 0: none "
                    "(the default).");
  prm.declare_entry("Pseudo time shift", "0.1", Double(1e-8, 1e6),
                    "The first pseudo time step's sigma over the law's stiffness scale Y "
                    "(dimensionless): the inverse of the first pseudo time step, in the damping's "
                    "units.");
  prm.declare_entry("Slack treatment", to_string(d.slack_treatment),
                    Selection("none|tension field"),
                    "How the membrane treats compression. 'none': the law as given, as stiff in "
                    "compression as in tension. 'tension field': the law relaxed "
                    "(docs/model.md, 'Slack: the tension field'): where a principal stress "
                    "would be compressive the fabric wrinkles and carries tension along the "
                    "other principal direction only, with no stress across it; where both "
                    "principal strains are shortenings it carries nothing. Unchanged wherever "
                    "both principal stresses are tensile. Material/Law = linear biot only.");
  prm.declare_entry("Compression stiffness fraction", "1e-2", Double(0, 1),
                    "Under 'tension field': the fraction of the law's own stiffness kept where "
                    "the fabric is wrinkled or slack, W = W_rel + eps (W_law - W_rel): this eps, "
                    "dimensionless. Without it a state with no tension across (a tube with free "
                    "ends, whose axial stress is zero) has a family of equilibria, any axial "
                    "shortening costing nothing; with it the one of the law itself. The stress "
                    "across wrinkles is eps times the law's compression.");
  prm.leave_subsection();
}

void FemParameters::parse_parameters(dealii::ParameterHandler& prm, bool rough_mesh_body) {
  prm.enter_subsection(subsection_name);
  element_degree = prm.get_integer("Element degree");
  const std::string solver = prm.get("Linear solver");
  if (solver == "direct")
    linear_solver = LinearSolverKind::direct;
  else if (solver == "cg-amg")
    linear_solver = LinearSolverKind::cg_amg;
  else if (solver == "gmres-amg")
    linear_solver = LinearSolverKind::gmres_amg;
  else if (solver == "cg-gamg")
    linear_solver = LinearSolverKind::cg_gamg;
  else if (solver == "gmres-gamg")
    linear_solver = LinearSolverKind::gmres_gamg;
  else
    throw std::invalid_argument("Finite elements/Linear solver: unknown solver '" + solver + "'");
  const std::string memory = prm.get("Iterative solver memory");
  if (memory == to_string(IterativeSolverMemory::fast))
    iterative_solver_memory = IterativeSolverMemory::fast;
  else if (memory == to_string(IterativeSolverMemory::lean))
    iterative_solver_memory = IterativeSolverMemory::lean;
  else
    throw std::invalid_argument("Finite elements/Iterative solver memory: unknown choice '" +
                                memory + "'");
  linear_tolerance = prm.get_double("Linear solver tolerance");
  max_linear_iterations = prm.get_integer("Maximum linear iterations");
  residual_tolerance =
      auto_or_number(prm.get("Residual tolerance"), "Finite elements/Residual tolerance")
          .value_or(rough_mesh_body ? 0.0 : FemParameters{}.residual_tolerance);
  if (!(residual_tolerance >= 0.0 && residual_tolerance <= 1e-2))
    throw std::invalid_argument("Finite elements/Residual tolerance = " +
                                prm.get("Residual tolerance") + ": must be auto or from 0 to 1e-2");
  max_newton_iterations = prm.get_integer("Maximum Newton iterations");
  line_search = prm.get_bool("Line search");
  potential_globalization = prm.get("Globalization") == "potential";
  max_line_search_halvings = prm.get_integer("Maximum line search halvings");
  max_contact_set_predictions = auto_or_count(prm.get("Contact set predictions"),
                                              "Finite elements/Contact set predictions", 100)
                                    .value_or(kAutoPredictions);
  penalty_factor = prm.get_double("Penalty factor");
  max_augmented_lagrangian_iterations = prm.get_integer("Maximum augmented Lagrangian iterations");
  tangent_shift_N_per_m = prm.get_double("Tangent shift");
  residual_shift_factor = prm.get_double("Residual shift factor");
  compression_stiffness_fraction = prm.get_double("Compression stiffness fraction");
  max_pseudo_time_steps = prm.get_integer("Pseudo time steps");
  pseudo_time_initial_shift = prm.get_double("Pseudo time shift");
  const std::string slack = prm.get("Slack treatment");
  if (slack == to_string(SlackTreatment::none))
    slack_treatment = SlackTreatment::none;
  else if (slack == to_string(SlackTreatment::tension_field))
    slack_treatment = SlackTreatment::tension_field;
  else
    throw std::invalid_argument("Finite elements/Slack treatment: unknown treatment '" + slack +
                                "'");
  prm.leave_subsection();
}

}  // namespace tightfit
