#include "massspring/massspring_parameters.h"

#include "core/number_text.h"

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tightfit {

namespace {
// A default as the parameter file shows it ("0.9", not "0.900000").
template <class T>
std::string text(T value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// The documentation's note on an entry whose default depends on the body (on_rough_mesh_body).
std::string auto_note(double faceted, double elsewhere) {
  return " auto: " + text(faceted) +
         " on a body mesh with Body/Mesh/Contact surface = faceted or Contact/Friction "
         "coefficient above 0 (massspring_parameters.h says why), " +
         text(elsewhere) + " elsewhere.";
}

// A count's entry read as a number: a whole one, in range for an int.
int whole_count(double value, const std::string& name) {
  if (!(value == std::floor(value) && std::abs(value) < 1e9))
    throw std::invalid_argument("Mass spring/" + name + " = " + text(value) +
                                ": must be a whole number");
  return int(value);
}

// An entry's text, auto or a number: the number, or `fallback` for auto.
double auto_or(const std::string& text, const std::string& name, double fallback) {
  return auto_or_number(text, "Mass spring/" + name).value_or(fallback);
}
}  // namespace

MassSpringParameters MassSpringParameters::on_rough_mesh_body() {
  MassSpringParameters p;
  p.contact_normal_damping_ratio = 0.5;
  p.time_step_update_frames = 100;
  p.net_force_tolerance = 0.05;
  p.creep_slide_damping_per_s = 50.0;
  return p;
}

void MassSpringParameters::declare_parameters(dealii::ParameterHandler& prm) {
  using dealii::Patterns::Anything;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;
  const MassSpringParameters d;
  const MassSpringParameters f = on_rough_mesh_body();
  prm.enter_subsection("Mass spring");
  prm.declare_entry("Integrator", "rk4", Selection("rk4|implicit"),
                    "How each load step reaches its stable state. 'rk4': the paper's damped "
                    "fourth-order Runge-Kutta frames (Time step, Damping, Quasi-static frames, "
                    "the stall test). 'implicit': a regularised Newton iteration on the static "
                    "equilibrium with the same forces and their analytic stiffness, each step a "
                    "sparse Cholesky solve (CHOLMOD) of (K + M / tau^2) dx = f with a pseudo "
                    "time step tau that grows tenfold after every full step; the same stop rule "
                    "and contact multiplier updates, so the same equilibrium within the stop "
                    "rule, in far less time on fine meshes of the analytic bodies "
                    "(docs/performance.md), and with Implicit RK4 approach on the frictionless "
                    "mesh-body cases (the stockings: 2 to 7 times less CPU than rk4; "
                    "docs/backends.md, \"Where each integrator is used\").");
  prm.declare_entry("Maximum Newton iterations", text(d.maximum_newton_iterations),
                    Integer(1, 100000000),
                    "Implicit integrator: guard against non-convergence, factorisations per "
                    "load step; a step that needs more fails with an error quoting the "
                    "iteration history.");
  prm.declare_entry("Contact set predictions", text(d.contact_set_predictions), Integer(0, 100),
                    "Implicit integrator: each Newton iteration solves again, at most this many "
                    "times, on the contact set its last increment predicts (the vertices it "
                    "brings into the body, or out of it, to first order in their gaps), so a "
                    "step does not drive a vertex through the penalty; 0 = the contact set at "
                    "the iteration's start only.");
  prm.declare_entry("Implicit tangent", "auto", Selection("auto|projected|exact"),
                    "Implicit integrator: the stiffness each Newton iteration factorises. "
                    "'projected': each compressed triangle's 9x9 stiffness and each contact's "
                    "3x3 block (the body's curvature, friction's slip) replaced by its positive "
                    "semi-definite part (negative eigenvalues set to zero), the triangles in "
                    "tension exact, so the matrix stays positive definite on a compressed, "
                    "friction-held garment; 'exact': the analytic stiffness, faster where it is "
                    "positive definite (the frictionless stockings); 'auto': projected with "
                    "friction, exact without (docs/backends.md, \"The implicit route on the "
                    "tops\").");
  prm.declare_entry("Implicit RK4 approach", text(d.implicit_approach_factor), Double(0.0),
                    "Implicit integrator on a mesh body without friction, above 0: each load "
                    "step starts with RK4 frames until the largest residual is below this many "
                    "times the stop rule's tolerance (the garment's travel onto the body, where "
                    "the contact set changes at every Newton iteration), its contact rounds stop "
                    "early as RK4's do (Inexact contact rounds), and a Newton settle whose "
                    "largest residual has not fallen by 10% in 10 iterations is finished by RK4 "
                    "frames (docs/backends.md, \"Where each integrator is used\"). 0 = Newton "
                    "alone.");
  prm.declare_entry("Time step", text(d.time_step_s), Double(0.0, 1.0),
                    "RK4 time step, s. 0 = automatic: a fraction (Time step safety) of the RK4 "
                    "stability limit 2 sqrt(2)/omega_max, omega_max from the stiffest vertex "
                    "(membrane, bending, penalty contact), recomputed every load step.");
  prm.declare_entry("Time step update frames", "auto", Anything(),
                    "With the automatic time step (Time step = 0), above 0: the step is chosen "
                    "again from the current state every this many frames of a load step (halved "
                    "as often as the stall test has halved it). 0 = chosen once at the start of "
                    "each load step." +
                        auto_note(f.time_step_update_frames, d.time_step_update_frames));
  prm.declare_entry("Time step safety", text(d.time_step_safety), Double(1e-3, 1.2),
                    "Fraction of the RK4 stability limit used by the automatic time step, "
                    "dimensionless.");
  prm.declare_entry("Mass scaling", text(d.mass_scaling_ratio), Double(0.0),
                    "RK4 with the automatic time step, dimensionless, 0 or >= 1: a particle "
                    "whose stiffness bound (membrane, bending, penalty contact) over mass exceeds "
                    "this many times the median particle's moves with the mass that brings it to "
                    "that bound, chosen again with the time step; its weight stays its own. The "
                    "few stiffest, lightest particles (the small triangles at a pattern's short "
                    "edges) then do not set the whole garment's time step. The stable state does "
                    "not depend on the masses, only the frames to reach it "
                    "(docs/cookbook-jumpsuit.md, \"The settle\"). 0 = off.");
  prm.declare_entry("Damping", text(d.damping_per_s), Double(0.0, 1e7),
                    "Mass-proportional damping c, 1/s (each particle's acceleration gets -c v). "
                    "0 = automatic: critical damping of the garment's slowest membrane wave.");
  prm.declare_entry("Slide damping", text(d.slide_damping_per_s), Double(0.0, 1e7),
                    "Above 0 (with a Net force tolerance): each load step starts with this "
                    "mass-proportional damping instead of Damping, 1/s, while the garment slides "
                    "over the body as a whole, and takes Damping once the slide has ended: the "
                    "damping force on the garment's mean velocity, total mass x this x |mean "
                    "velocity|, below half the net force limit for 3 / (this) s. The stop rule is "
                    "read only after that. A garment creeping down the body under its weight "
                    "slides at a speed the damping sets (docs/dressing.md). 0 = off. RK4 only.");
  prm.declare_entry("Creep slide damping", "auto", Anything(),
                    "Above 0 (with a Net force tolerance), 1/s: a load step whose stall test "
                    "fires while it creeps (the residual's norm below the stop rule, the net force "
                    "on the garment above its limit and held for at least half by the damping of "
                    "the garment's mean velocity) slides at this mass-proportional damping instead "
                    "of halving its time step, until the slide has ended (as with Slide damping), "
                    "then settles at Damping again; once per load step, and not in a step that "
                    "starts sliding (Slide damping above 0). A tight top whose weight friction "
                    "does not hold where it was dressed slides down to where it is held instead "
                    "of creeping there at the automatic damping (docs/dressing.md). 0 = off. RK4 "
                    "only." +
                        auto_note(f.creep_slide_damping_per_s, d.creep_slide_damping_per_s));
  prm.declare_entry("Contact normal damping ratio", "auto", Anything(),
                    "Damping ratio zeta of each vertex's penalty contact spring along the body's "
                    "normal, dimensionless in [0, 1]: a vertex in contact gets -2 zeta sqrt(kA m) "
                    "(v . d) d (kA its penalty stiffness in N/m, m its mass in kg, v its velocity, "
                    "d the gradient of its gap: the normal, the face's on a faceted body); 1 = "
                    "critical damping of the mass on its contact spring. Damps the chatter of "
                    "vertices on a faceted body, not a slide along "
                    "it; the stop rule's residual leaves it out. 0 = off. RK4 only." +
                        auto_note(f.contact_normal_damping_ratio, d.contact_normal_damping_ratio));
  prm.declare_entry("Contact stick damping ratio", "auto", Anything(),
                    "Damping ratio zeta of each sticking vertex's friction spring across the "
                    "body's normal, dimensionless in [0, 1]: a vertex in contact whose friction "
                    "sticks gets -2 zeta sqrt(kt m) (v - (v . n) n) (kt its tangential penalty "
                    "stiffness in N/m, m its mass in kg, n the body's outward normal). Damps a "
                    "stuck vertex ringing on its friction spring in a crease between two body "
                    "parts (docs/cookbook-jumpsuit.md), not a slipping vertex; the stop rule's "
                    "residual leaves it out. 0 = off. RK4 only. auto: 0.5 on a body mesh with "
                    "Body/Mesh/Contact surface = faceted or with friction for a garment arranged "
                    "from the body's "
                    "landmarks (Placement/Kind = pattern arrangement or arrangement), 0 "
                    "elsewhere.");
  prm.declare_entry("Quasi-static frames", text(d.quasi_static_frames), Integer(0, 100000000),
                    "Frames of the paper's quasi-static start (Section 4.3: velocity reset to "
                    "zero every frame) before damped RK4 takes over; the start also ends when "
                    "the stop rule is met.");
  prm.declare_entry("Net force tolerance", "auto", Anything(),
                    "Stop rule on the garment as a whole beside Solver/Relative tolerance, "
                    "dimensionless: above 0, a state is stable only when the net force on the "
                    "garment (the sum of the residual "
                    "forces: what the body, friction and gravity leave unbalanced) is also "
                    "below this times the garment's weight (its mass times 9.80665 m/s^2, "
                    "whether gravity acts or not). The rms stop norm alone accepts a garment "
                    "still sliding over the body: a net force F spread over n vertices adds "
                    "only F / n to each (docs/dressing.md). 0 = off." +
                        auto_note(f.net_force_tolerance, d.net_force_tolerance));
  prm.declare_entry("Maximum frames", text(d.maximum_frames), Integer(1, 2000000000),
                    "Guard against non-convergence, frames: a load step that has not met the "
                    "stop rule by then fails with an error naming the step and residual.");
  prm.declare_entry("Stall window", text(d.stall_window_frames), Integer(1, 2000000000),
                    "Stall test, frames: the residual is watched in windows of this many frames; "
                    "a window whose smallest residual is not below Stall residual fall times the "
                    "smallest of the earlier windows of the same settle has stalled (a limit "
                    "cycle or a floor above the stop rule). The time step is then halved.");
  prm.declare_entry("Stall residual fall", text(d.stall_fall), Double(1e-6, 0.999999),
                    "Stall test, dimensionless: the factor by which each window's smallest "
                    "residual must fall below the earlier windows'.");
  prm.declare_entry("Stall time step halvings", text(d.stall_halvings), Integer(0, 30),
                    "Stall test, count: time-step halvings allowed per settle (a load step's "
                    "first, and each after a contact multiplier update, which starts again at the "
                    "stable time step); a stall after the last ends the step with an error "
                    "quoting the residual history (also in solver.log).");
  prm.declare_entry("Contact multiplier updates", text(d.contact_updates), Integer(0, 1000),
                    "Augmented-Lagrangian (Uzawa) updates per load step, count: after each stable "
                    "state every vertex's contact multiplier becomes its contact force and the "
                    "garment settles again, until the largest penetration is below Solver/Gap "
                    "tolerance; the pressure then does not depend on Contact/Penalty factor, "
                    "as with the FE backend. A step that needs more updates fails. 0 = the "
                    "plain penalty: vertices settle p / k inside the body.");
  prm.declare_entry("Inexact contact rounds", text(d.inexact_round_fraction), Double(0.0, 1.0),
                    "Dimensionless: a settle that a contact multiplier update will follow stops "
                    "once its residual force is below this times the largest change that update "
                    "would make to a vertex's multiplier (kA |g| in contact), or below the stop "
                    "rule if that is larger. The settle after the last update always meets the "
                    "stop rule, so the stable state meets the same rule; settling the earlier "
                    "rounds below what their update changes only spends frames. Once an update "
                    "leaves more than a quarter of the last update's penetration (a garment still "
                    "sliding reopens the gaps), every later settle meets the stop rule. Read on "
                    "mesh bodies without friction under the largest-residual stop rule only. 0 = "
                    "every settle meets the stop rule.");
  prm.declare_entry("Bending rigidity", text(d.bending_rigidity_N_m), Double(0.0, 1.0),
                    "Bending rigidity B of the fabric, N m (a knit: about 1e-6 to 1e-5 N m). "
                    "Angular springs on interior edges, hinge stiffness 3 B |e|^2 / (A1 + A2) "
                    "(Grinspun et al. 2003). 0 = no bending springs.");
  prm.declare_entry("Placement", "sewn tube", Selection("sewn tube|flat panels"),
                    "How the first load step starts. 'sewn tube': from the case's start, the "
                    "garment already sewn round the body (fast). 'flat panels': the paper's "
                    "start (Section 4.3, Figure 5): the panels unsewn and laid flat on opposite "
                    "sides of the cylinder, Placement gap from its surface, pulled together by "
                    "zero-rest-length seam springs (membrane, bending and contact acting) until "
                    "every seam vertex pair is within 5% of the mean edge length; then the "
                    "seams are welded and the step continues on the sewn garment. Needs a "
                    "cylinder body; the case's start positions are not used.");
  prm.declare_entry("Placement gap", text(d.placement_gap_m), Double(0.0, 1.0),
                    "Flat panels: distance from the cylinder's surface to each flat panel, m "
                    "(the paper: small and equal on both sides).");
  prm.declare_entry("Seam spring stiffness factor", text(d.seam_stiffness_factor),
                    Double(1e-6, 1e6),
                    "Flat panels: stiffness of each seam spring as a multiple of the law's "
                    "stiffness scale (N/m), dimensionless. A seam pair balances the hoop pull "
                    "at a gap of (strain x seam length per vertex) / factor: it must be small "
                    "against 5% of an edge for the seams to close.");
  prm.leave_subsection();
}

void MassSpringParameters::parse_parameters(dealii::ParameterHandler& prm, bool rough_mesh_body,
                                            bool arranged_from_landmarks) {
  const MassSpringParameters d = rough_mesh_body ? on_rough_mesh_body() : MassSpringParameters{};
  prm.enter_subsection("Mass spring");
  integrator = prm.get("Integrator") == "implicit" ? Integrator::implicit : Integrator::rk4;
  maximum_newton_iterations = prm.get_integer("Maximum Newton iterations");
  contact_set_predictions = prm.get_integer("Contact set predictions");
  implicit_approach_factor = prm.get_double("Implicit RK4 approach");
  const std::string tangent = prm.get("Implicit tangent");
  implicit_tangent = tangent == "projected" ? ImplicitTangent::projected
                     : tangent == "exact"   ? ImplicitTangent::exact
                                            : ImplicitTangent::automatic;
  time_step_s = prm.get_double("Time step");
  time_step_safety = prm.get_double("Time step safety");
  mass_scaling_ratio = prm.get_double("Mass scaling");
  // The entries that may be auto are read as text here and as numbers once the subsection is
  // left, so that a refused one leaves the handler where it was.
  const std::string update_frames_text = prm.get("Time step update frames");
  damping_per_s = prm.get_double("Damping");
  slide_damping_per_s = prm.get_double("Slide damping");
  const std::string creep_slide_text = prm.get("Creep slide damping");
  const std::string contact_damping_text = prm.get("Contact normal damping ratio");
  const std::string stick_damping_text = prm.get("Contact stick damping ratio");
  quasi_static_frames = prm.get_integer("Quasi-static frames");
  const std::string net_force_text = prm.get("Net force tolerance");
  maximum_frames = prm.get_integer("Maximum frames");
  stall_window_frames = prm.get_integer("Stall window");
  stall_fall = prm.get_double("Stall residual fall");
  stall_halvings = prm.get_integer("Stall time step halvings");
  contact_updates = prm.get_integer("Contact multiplier updates");
  inexact_round_fraction = prm.get_double("Inexact contact rounds");
  bending_rigidity_N_m = prm.get_double("Bending rigidity");
  placement = prm.get("Placement") == "flat panels" ? Placement::flat_panels : Placement::sewn_tube;
  placement_gap_m = prm.get_double("Placement gap");
  seam_stiffness_factor = prm.get_double("Seam spring stiffness factor");
  prm.leave_subsection();
  time_step_update_frames =
      whole_count(auto_or(update_frames_text, "Time step update frames", d.time_step_update_frames),
                  "Time step update frames");
  contact_normal_damping_ratio =
      auto_or(contact_damping_text, "Contact normal damping ratio", d.contact_normal_damping_ratio);
  contact_stick_damping_ratio = auto_or(stick_damping_text, "Contact stick damping ratio",
                                        rough_mesh_body && arranged_from_landmarks ? 0.5 : 0.0);
  net_force_tolerance = auto_or(net_force_text, "Net force tolerance", d.net_force_tolerance);
  creep_slide_damping_per_s = auto_or(creep_slide_text, "Creep slide damping",
                                      net_force_tolerance > 0 ? d.creep_slide_damping_per_s : 0.0);
  validate();
}

}  // namespace tightfit
