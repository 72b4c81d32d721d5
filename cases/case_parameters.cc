// Declares and reads the case file. This is the only translation unit of cases/ that includes
// deal.II (its ParameterHandler), so that changing a case does not rebuild the heavy headers.
#include "cases/case_parameters.h"

#include "cases/parameter_names.h"
#include "cases/parameter_tree.h"
#include "cases/scenario_parts.h"
#include "core/backend_registry.h"
#include "core/garment.h"
#include "core/number_text.h"
#include "core/thread_count.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tightfit {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

namespace {

Vec3 parse_vec3(const std::string& text) {
  const auto parts = dealii::Utilities::split_string_list(text, ',');
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = dealii::Utilities::string_to_double(parts.at(i));
  return v;
}

const Patterns::List vec3_pattern(Patterns::Double(), 3, 3, ",");

// A default as a person writes it: the shortest decimal that reads back as the same double
// ("0.24", not deal.II's "0.23999999999999999"), or 15 significant digits where that is shorter
// (a default computed from other numbers, 6864.655 rather than 6864.655000000001: one unit in
// the last place, and the run reads the printed text back).
std::string shortest_decimal(double value) {
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, value);
  const std::string exact(text, written.ptr);
  std::snprintf(text, sizeof text, "%.15g", value);
  return std::string(text).size() < exact.size() ? std::string(text) : exact;
}

// The scenario parts' view of the handler (cases/parameter_tree.h).
class HandlerTree final : public ParameterTree {
 public:
  explicit HandlerTree(ParameterHandler& prm, const std::string& case_file_directory = "")
      : prm_(prm) {
    case_directory = case_file_directory;
  }
  void enter_subsection(const std::string& name) override { prm_.enter_subsection(name); }
  void leave_subsection() override { prm_.leave_subsection(); }
  void declare_double(const std::string& name, double default_value, double min, double max,
                      const std::string& documentation) override {
    prm_.declare_entry(name, shortest_decimal(default_value),
                       max == unbounded ? Patterns::Double(min) : Patterns::Double(min, max),
                       documentation);
  }
  void declare_integer(const std::string& name, int default_value, int min, int max,
                       const std::string& documentation) override {
    prm_.declare_entry(name, std::to_string(default_value), Patterns::Integer(min, max),
                       documentation);
  }
  void declare_bool(const std::string& name, bool default_value,
                    const std::string& documentation) override {
    prm_.declare_entry(name, default_value ? "true" : "false", Patterns::Bool(), documentation);
  }
  void declare_selection(const std::string& name, const std::string& default_value,
                         const std::string& options, const std::string& documentation) override {
    prm_.declare_entry(name, default_value, Patterns::Selection(options), documentation);
  }
  void declare_multiple_selection(const std::string& name, const std::string& default_value,
                                  const std::string& options,
                                  const std::string& documentation) override {
    prm_.declare_entry(name, default_value, Patterns::MultipleSelection(options), documentation);
  }
  void declare_vector(const std::string& name, const std::string& default_value,
                      const std::string& documentation) override {
    prm_.declare_entry(name, default_value, vec3_pattern, documentation);
  }
  void declare_text(const std::string& name, const std::string& default_value,
                    const std::string& documentation) override {
    prm_.declare_entry(name, default_value, Patterns::Anything(), documentation);
  }
  void declare_file_name(const std::string& name, const std::string& default_value,
                         const std::string& documentation) override {
    prm_.declare_entry(name, default_value, Patterns::FileName(), documentation);
  }
  std::string get(const std::string& name) override { return prm_.get(name); }
  double get_double(const std::string& name) override { return prm_.get_double(name); }
  int get_integer(const std::string& name) override {
    return static_cast<int>(prm_.get_integer(name));
  }
  bool get_bool(const std::string& name) override { return prm_.get_bool(name); }

 private:
  ParameterHandler& prm_;
};

// Kind = one of the registry's parts, then each part's own subsection.
template <class Made>
void declare_kind(ParameterTree& tree, const PartRegistry<Made>& registry,
                  const std::string& default_kind, const std::string& documentation) {
  tree.declare_selection("Kind", default_kind, registry.names_joined("|"),
                         documentation + " " + registry.descriptions());
  registry.declare_parts(tree);
}

void declare_garment(ParameterHandler& prm) {
  HandlerTree tree(prm);
  Subsection in(tree, "Garment");
  declare_kind(tree, garment_kinds(), "tube", "What the garment is cut from:");
  prm.declare_entry("Name", "4 5T", Patterns::Anything(), "Name of the garment, for tables.");
  prm.declare_entry("Edge length weft", "0.008", Patterns::Double(1e-5),
                    "Target mesh spacing along the weft, round the tube (m). It sets how "
                    "closely the flat triangles follow the body's curvature.");
  prm.declare_entry("Edge length warp", "0.022", Patterns::Double(1e-5),
                    "Target mesh spacing along the warp, along the tube (m).");
  prm.declare_entry("Mesh scale", "1", Patterns::Double(1e-3, 100),
                    "Multiplies both edge lengths and a pattern file's Mesh edge length: 0.5 "
                    "halves them (about four times the "
                    "vertices). 0.62 gives the paper's fine '4 5T': 1444 vertices, 2736 "
                    "triangles (the paper: 1397 and 2738).");
}

void declare_material(ParameterHandler& prm) {
  prm.enter_subsection("Material");
  std::string law_names;
  for (const std::string& name : material_law_names())
    law_names += (law_names.empty() ? "" : "|") + name;
  prm.declare_entry("Law", "linear biot", Patterns::Selection(law_names),
                    material_law_descriptions());
  prm.declare_entry("Stiffness weft", "130", Patterns::Double(0),
                    "Membrane stiffness E t along the weft/course (N/m; 1 N/cm = 100 N/m). "
                    "Table 2: 1.3 N/cm.");
  prm.declare_entry("Stiffness warp", "70", Patterns::Double(0),
                    "Membrane stiffness E t along the warp/wale (N/m). Table 2: 0.7 N/cm.");
  prm.declare_entry("Poisson ratio weft-warp", "0.2021", Patterns::Double(0, 0.99),
                    "nu12: contraction along the warp per stretch along the weft (-). Table 2: "
                    "0.3499 at 500 g, 0.2021 at 1000 g.");
  prm.declare_entry("Shear stiffness", "30", Patterns::Double(0),
                    "In-plane shear stiffness G12 t (N/m). Not measured in the paper.");
  prm.declare_entry("Thickness", "0.00039", Patterns::Double(0),
                    "Rest thickness (m). Table 2: 0.039 cm.");
  prm.declare_entry("Areal density", "0.1057", Patterns::Double(0),
                    "Mass per rest area (kg/m^2). Table 2: 1.057e-5 kg/cm^2.");
  prm.declare_entry("Neo-Hookean shear modulus", "85470.0854700855", Patterns::Double(0),
                    "Shear modulus G of the neo-hookean law (Pa). Default: 3 G t = 100 N/m, "
                    "the mean of the two stiffnesses.");
  const FabricParameters table2;
  prm.declare_entry("Tension curve weft", format_curve_points(table2.tension_curve_weft),
                    Patterns::Anything(),
                    "The tensile curves law's weft/course curve: strain:force pairs, engineering "
                    "strain (l - l0) / l0 (-) against force per unit rest width (N/m), strictly "
                    "increasing, through 0:0; interpolated by a monotone C1 cubic, straight "
                    "beyond the data. Default: Table 2 (0.245 and 0.49 N/cm).");
  prm.declare_entry("Tension curve warp", format_curve_points(table2.tension_curve_warp),
                    Patterns::Anything(),
                    "The tensile curves law's warp/wale curve, as Tension curve weft (N/m). "
                    "Default: Table 2.");
  prm.declare_entry("Poisson curve", format_curve_points(table2.poisson_curve),
                    Patterns::Anything(),
                    "The tensile curves law's nu12 against weft strain: strain:coefficient pairs "
                    "(-), constant beyond the data; one pair for a constant coefficient. "
                    "Default: Table 2 (0.3499 at the lower load, 0.2021 at the higher).");
  prm.leave_subsection();
}

void declare_body(ParameterHandler& prm) {
  HandlerTree tree(prm);
  Subsection in(tree, "Body");
  declare_kind(tree, body_kinds(), "cylinder",
               "The rigid body the garment is worn on; its own entries are in the subsection of "
               "the same name.");
}

void declare_placement(ParameterHandler& prm) {
  HandlerTree tree(prm);
  Subsection in(tree, "Placement");
  declare_kind(tree, placement_kinds(), "tube round cylinder",
               "Where the garment starts, before the first load step settles it:");
}

void declare_constraints(ParameterHandler& prm) {
  prm.enter_subsection("Constraints");
  prm.declare_entry("Held groups", "", Patterns::Anything(),
                    "Comma-separated vertex groups of the garment (a tube's: bottom, top; a "
                    "sheet's: bottom, top, left, right; 'all': every vertex) that keep their "
                    "coordinate along Held direction. 'bottom, top' on a tube: the paper's held "
                    "ends (axial stretch 1); 'all' on a stocking: the knit gripped along the "
                    "leg, and its mean turn round the direction held too (docs/backends.md, "
                    "\"The held turn\"); empty: free ends.");
  prm.declare_entry("Held direction", "axis", Patterns::Anything(),
                    "Direction the held groups may not move along: 'axis' for the axis a "
                    "garment cut to the body was cut along (Garment/Kind = limb tube: the "
                    "limb's), else the body's own (a cylinder's axis, a plane's normal), or "
                    "three numbers x,y,z (-).");
  prm.declare_entry("Fixed groups", "", Patterns::Anything(),
                    "Comma-separated vertex groups that do not move at all.");
  prm.leave_subsection();
}

void declare_measurements(ParameterHandler& prm) {
  HandlerTree tree(prm);
  Subsection in(tree, "Measurements");
  const auto& registry = measurement_kinds();
  tree.declare_multiple_selection(
      "List", "cylinder theory, angular profile", registry.names_joined("|"),
      "Comma-separated measurements taken at every load step beside the generic pressure "
      "summary of pressure.csv; the first that knows a closed form gives p_theory_Pa. " +
          registry.descriptions());
  registry.declare_parts(tree);
}

void declare_contact(ParameterHandler& prm) {
  prm.enter_subsection("Contact");
  prm.declare_entry("Penalty factor", "100", Patterns::Double(1e-3),
                    "beta in the penalty stiffness k = beta Y / h^2 (Pa/m), Y the law's "
                    "stiffness scale, h the mean rest edge length (-). The mass-spring "
                    "backend's contact: its multiplier updates take the penetration p / k "
                    "away, so beta sets only their speed and the time step; with Mass "
                    "spring/Contact multiplier updates = 0 the penetration stays and "
                    "docs/model.md gives its effect on the pressure.");
  prm.declare_entry("Friction coefficient", "0", Patterns::Double(0),
                    "Coulomb friction coefficient mu between garment and body (-); 0 = "
                    "frictionless (the paper's cylinder). Quasi-static and path dependent: each "
                    "vertex sticks to an anchor on the body's own surface (carried as the body "
                    "grows or morphs) until its tangential force reaches mu times its normal "
                    "force, then slips (docs/model.md, \"Friction\").");
  prm.declare_entry("Tangential penalty ratio", "1", Patterns::Double(1e-3),
                    "The friction's regularisation (-): a sticking vertex is held to its anchor "
                    "by a spring of this times the normal penalty k A0, so it creeps |f| / k_t. "
                    "Larger is closer to exact sticking and, on the mass-spring backend, a "
                    "smaller time step; the results do not depend on it (docs/model.md).");
  prm.leave_subsection();
}

void declare_protocol(ParameterHandler& prm) {
  prm.enter_subsection("Protocol");
  prm.declare_entry("Final alpha", "1.8", Patterns::Double(0),
                    "The body's morph parameter alpha at the last load step (-): for a cylinder "
                    "its radius over the tube's rest radius, r / R0; a plane ignores it.");
  prm.declare_entry("Alpha increment", "0.05", Patterns::Double(1e-4),
                    "After settling on the initial body, alpha goes through every multiple of "
                    "this increment up to the final one (-).");
  prm.declare_entry("Gravity while settling", "false", Patterns::Bool(),
                    "Gravity on while the garment first settles (the paper: it speeds settling).");
  prm.declare_entry("Gravity while measuring", "false", Patterns::Bool(),
                    "Gravity on during the growth steps (the paper turns it off: Figure 13).");
  prm.declare_entry("Gravity", "9.81", Patterns::Double(0), "Acceleration of gravity (m/s^2).");
  prm.declare_entry("Up", "0,0,1", vec3_pattern, "Direction opposite to gravity (-).");
  prm.leave_subsection();
}

void declare_pressure(ParameterHandler& prm) {
  prm.enter_subsection("Pressure");
  prm.declare_entry("Vertex area", "barycentric",
                    Patterns::Selection("barycentric|mixed voronoi|adjacent triangles"),
                    "Area a vertex's normal force is divided by: barycentric (a third of each "
                    "adjacent triangle; balances forces), mixed voronoi (Meyer et al. 2003; also "
                    "balances forces, smoother on irregular meshes) or adjacent triangles (the "
                    "paper's Section 2.2: reads a third of the pressure).");
  prm.declare_entry("Definition", "contact traction",
                    Patterns::Selection("contact traction|garment force (paper)"),
                    "The normal force read as pressure: contact traction (the body's force on "
                    "the garment along the body's normal: what a sensor on the skin reads) or "
                    "garment force (paper) (the garment's own force along its normal, the "
                    "paper's Section 2.2; it misses the weight the body carries).");
  prm.leave_subsection();
}

void declare_output(ParameterHandler& prm) {
  prm.enter_subsection("Output");
  prm.declare_entry("Directory", "output", Patterns::Anything(),
                    "Where the tables and VTU files go; --output overrides it.");
  prm.declare_entry("Write VTU", "true", Patterns::Bool(),
                    "Write one VTU per load step for the garment and the body, with .pvd "
                    "time series for ParaView.");
  prm.declare_entry("Body pressure", "true", Patterns::Bool(),
                    "The body VTU carries the garment's pressure mapped onto the body's surface "
                    "(pressure_Pa, pressure_mmHg, under_garment), on the body's display surface "
                    "refined to Body edge length (docs/measurements.md).");
  prm.declare_entry("Body edge length", "0", Patterns::Double(0),
                    "Longest edge of the body's surface in the body VTU and the pictures, m; 0: "
                    "half the garment's mean edge length.");
  prm.leave_subsection();
}

// The stop rule both backends read (core/load_step.h; docs/backends.md, "Reaching equilibrium").
// Its entries default to auto: on a body mesh touched on its flat faces (Body/Mesh/Contact
// surface = faceted) or by a garment held by friction the rms at 3e-3 and a gap of 1e-6 m,
// elsewhere the largest at 1e-4 and 1e-8 m (docs/parameters.md; the reasons in
// massspring/massspring_parameters.h, on_rough_mesh_body).
void declare_stop_rule(ParameterHandler& prm) {
  prm.declare_entry("Relative tolerance", "auto", Patterns::Anything(),
                    "Stop rule of both backends, dimensionless: a state is stable when its "
                    "residual force (Stop norm; internal + contact + gravity, held components "
                    "removed) is below this times the tension scale Y h^2 / L: the law's "
                    "stiffness scale Y (N/m) times the mean rest edge length h (m) squared over "
                    "the garment's size L (m, the square root of its rest area). That is the "
                    "force a smooth strain error of this size leaves on a vertex, so the "
                    "tolerance bounds the strain error on every mesh (docs/model.md, 'Reaching "
                    "equilibrium'). The FE backend counts each node's residual relative to its "
                    "own edge (R_k h / h_k) and also meets its own absolute rule, Finite "
                    "elements/Residual tolerance (the tighter by default). 0: off, for the FE "
                    "backend only (its own rule alone); the mass-spring backend needs a value "
                    "above 0. auto: 3e-3 on a body mesh with Body/Mesh/Contact surface = faceted "
                    "or Contact/Friction coefficient above 0 "
                    "(with the rms norm: the chatter of a few vertices on the flat faces stays "
                    "near 1e-3 of the tension scale), 1e-4 elsewhere.");
  prm.declare_entry("Contact load tolerance", "auto", Patterns::Anything(),
                    "The stop rule measured also against the step's own contact load, "
                    "dimensionless: a state is stable when its residual is also below this "
                    "times the mean normal contact force F on a vertex in contact (N), but never "
                    "asked below a tenth of the Relative tolerance rule: threshold = min(e Y h^2 "
                    "/ L, max(0.1 e Y h^2 / L, c F)). A residual r on a vertex in contact errs "
                    "its contact force by up to r, so the mean pressure over the contact errs by "
                    "at most r / F of itself: c bounds the pressure error relative to the "
                    "pressure where the tension-scale rule alone, at a small strain and a small "
                    "contact load, would leave it at 1e-3 (docs/backends.md, 'The stop rule at "
                    "the contact load'). 0: off. auto: 0 on a body mesh with Body/Mesh/Contact "
                    "surface = faceted or with friction (its rule is loosened for the chatter on "
                    "the flat faces and of the vertices that stick and slip), "
                    "1e-4 elsewhere.");
  prm.declare_entry("Stop norm", "auto", Patterns::Selection("auto|largest|rms"),
                    "Which size of the residual force field the stop rule (Relative tolerance) "
                    "and the mass-spring stall test read. 'largest': the largest residual on any "
                    "vertex (the FE backend: its largest component). 'rms': the root mean square "
                    "over the vertices, sqrt(sum |f|^2 / n), for a garment on a body mesh touched "
                    "on its flat faces or held by friction, where a few vertices chatter in a "
                    "limit cycle the largest residual "
                    "never leaves (docs/dressing.md). 'auto': rms on a body mesh with "
                    "Body/Mesh/Contact surface = faceted or with friction, largest elsewhere.");
  prm.declare_entry("Gap tolerance", "auto", Patterns::Anything(),
                    "Largest penetration of a vertex in contact at a finished load step with "
                    "contact multiplier updates, m (both backends). auto: 1e-6 on a body mesh "
                    "with Body/Mesh/Contact surface = faceted or with friction (the rounds on "
                    "the flat faces stall between 1e-7 and 5e-7 m on the FE backend), 1e-8 "
                    "elsewhere; on a body mesh (Body/Kind = mesh or morph) raised to the gap the "
                    "stop rule resolves, Relative tolerance times h^2 / L (h the mean rest edge, "
                    "L the square root of the rest area, m): the stop rule's residual over the "
                    "stiffness Y of a vertex the membrane alone holds (docs/backends.md, 'The gap "
                    "the stop rule resolves'). A number is used as given.");
}

// The stop rule's entries once lived in each backend's subsection, with other defaults: a case
// file that still sets one there is refused with the entry to use instead.
const char* const moved_entries[] = {"Relative tolerance", "Stop norm", "Gap tolerance"};

void declare_moved_entries(ParameterHandler& prm, const std::string& subsection) {
  prm.enter_subsection(subsection);
  for (const char* name : moved_entries)
    prm.declare_entry(name, "", Patterns::Anything(),
                      std::string("Moved: set Solver/") + name +
                          " instead (one stop rule for both backends). Refused here.");
  prm.leave_subsection();
}

// Whether the case's body is a rough mesh body: a mesh touched on its flat faces (whose ridges the
// garment catches on), or on its smooth surface by a garment held by friction; the auto entries'
// case (massspring_parameters.h, on_rough_mesh_body). A top held by friction under gravity on the
// smooth surface sticks and slips at a few vertices and creeps as a whole as on the flat faces:
// with the largest residual at 1e-4 the male top's stayed between 1e-3 and 0.1 N against a rule of
// 2e-6 N (docs/performance-bodies.md).
bool rough_mesh_body(ParameterHandler& prm) {
  prm.enter_subsection("Body");
  const bool mesh = prm.get("Kind") == "mesh";
  prm.enter_subsection("Mesh");
  const bool faceted = prm.get("Contact surface") == "faceted";
  prm.leave_subsection();
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  const bool friction = prm.get_double("Friction coefficient") > 0.0;
  prm.leave_subsection();
  return mesh && (faceted || friction);
}

StopRule parse_stop_rule(ParameterHandler& prm) {
  StopRule rule;
  rule.rough_mesh_body = rough_mesh_body(prm);
  prm.enter_subsection("Solver");
  const std::string tolerance = prm.get("Relative tolerance");
  const std::string load_tolerance = prm.get("Contact load tolerance");
  const std::string norm = prm.get("Stop norm");
  const std::string gap = prm.get("Gap tolerance");
  prm.leave_subsection();
  rule.relative_tolerance = auto_or_number(tolerance, "Solver/Relative tolerance")
                                .value_or(rule.rough_mesh_body ? 3e-3 : 1e-4);
  rule.contact_load_tolerance = auto_or_number(load_tolerance, "Solver/Contact load tolerance")
                                    .value_or(rule.rough_mesh_body ? 0.0 : 1e-4);
  rule.norm =
      norm == "rms" || (norm == "auto" && rule.rough_mesh_body) ? StopNorm::rms : StopNorm::largest;
  const std::optional<double> gap_m = auto_or_number(gap, "Solver/Gap tolerance");
  rule.gap_tolerance_m = gap_m.value_or(rule.rough_mesh_body ? 1e-6 : 1e-8);
  prm.enter_subsection("Body");
  const std::string body_kind = prm.get("Kind");
  prm.leave_subsection();
  rule.gap_tolerance_auto = !gap_m && (body_kind == "mesh" || body_kind == "morph");
  return rule;
}

void refuse_moved_entries(ParameterHandler& prm, const std::string& subsection) {
  prm.enter_subsection(subsection);
  for (const char* name : moved_entries)
    if (!prm.get(name).empty())
      throw std::invalid_argument(subsection + "/" + name + " has moved: set Solver/" + name +
                                  " (one stop rule for both backends; docs/parameters.md)");
  prm.leave_subsection();
}

void declare_case_parameters(ParameterHandler& prm) {
  declare_garment(prm);
  declare_material(prm);
  declare_body(prm);
  declare_placement(prm);
  declare_constraints(prm);
  declare_contact(prm);
  declare_protocol(prm);
  declare_pressure(prm);
  declare_measurements(prm);
  declare_output(prm);
  const BackendRegistry& registry = backend_registry();
  prm.enter_subsection("Solver");
  prm.declare_entry("Backend", "massspring", Patterns::Selection(registry.names_joined("|")),
                    "The cloth solver: massspring (the paper's particle model with RK4) or fem "
                    "(a finite-element membrane solved by Newton's method).");
  prm.declare_entry("Threads", "auto", Patterns::Anything(),
                    "Threads the mass-spring backend shares a frame's body queries out to (one "
                    "per garment vertex, on a body mesh; an analytic body's queries stay on one "
                    "thread): the same results to the last bit with any number "
                    "(docs/performance-bodies.md, 'Threads'). 1: one thread. auto or 0: one per "
                    "rank under MPI with more than one rank, else OMP_NUM_THREADS when set, else "
                    "the cores this process may run on.");
  declare_stop_rule(prm);
  prm.leave_subsection();
  for (const BackendEntry& entry : registry.entries()) {
    entry.declare_parameters(prm);
    declare_moved_entries(prm, entry.subsection);
  }
}

}  // namespace

namespace {

CaseParameters parse_case_parameters(ParameterHandler& prm, const std::string& case_directory) {
  CaseParameters c;
  HandlerTree tree(prm, case_directory);
  prm.enter_subsection("Garment");
  c.garment.kind = prm.get("Kind");
  c.garment.make = garment_kinds().parse_part(tree, c.garment.kind);
  c.garment.name = prm.get("Name");
  c.garment.mesh_scale = prm.get_double("Mesh scale");
  c.garment.spacing.along_x_m = prm.get_double("Edge length weft") * c.garment.mesh_scale;
  c.garment.spacing.along_y_m = prm.get_double("Edge length warp") * c.garment.mesh_scale;
  if (c.garment.kind == "pattern file") {
    // A pattern's own Mesh edge length is scaled too, so that a convergence study or a finer
    // run by Mesh scale refines it (docs/command-line.md, "tightfit convergence").
    prm.enter_subsection("Pattern file");
    c.garment.spacing.pattern_edge_length_m =
        prm.get_double("Mesh edge length") * c.garment.mesh_scale;
    prm.leave_subsection();
  }
  prm.leave_subsection();

  prm.enter_subsection("Material");
  c.law = prm.get("Law");
  c.fabric.stiffness_weft_N_per_m = prm.get_double("Stiffness weft");
  c.fabric.stiffness_warp_N_per_m = prm.get_double("Stiffness warp");
  c.fabric.poisson_weft_warp = prm.get_double("Poisson ratio weft-warp");
  c.fabric.shear_stiffness_N_per_m = prm.get_double("Shear stiffness");
  c.fabric.thickness_m = prm.get_double("Thickness");
  c.fabric.areal_density_kg_per_m2 = prm.get_double("Areal density");
  c.fabric.neo_hookean_shear_modulus_Pa = prm.get_double("Neo-Hookean shear modulus");
  c.fabric.tension_curve_weft =
      parse_curve_points(prm.get("Tension curve weft"), "Material/Tension curve weft");
  c.fabric.tension_curve_warp =
      parse_curve_points(prm.get("Tension curve warp"), "Material/Tension curve warp");
  c.fabric.poisson_curve = parse_curve_points(prm.get("Poisson curve"), "Material/Poisson curve");
  prm.leave_subsection();

  prm.enter_subsection("Body");
  c.body.kind = prm.get("Kind");
  c.body.make = body_kinds().parse_part(tree, c.body.kind);
  prm.leave_subsection();

  prm.enter_subsection("Placement");
  c.placement.kind = prm.get("Kind");
  c.placement.place = placement_kinds().parse_part(tree, c.placement.kind);
  prm.leave_subsection();

  prm.enter_subsection("Constraints");
  c.constraints.held_groups = tree.get_list("Held groups");
  c.constraints.fixed_groups = tree.get_list("Fixed groups");
  const std::string held_direction = prm.get("Held direction");
  prm.leave_subsection();
  if (held_direction != "axis") {
    try {
      c.constraints.held_direction = parse_vec3(held_direction);
    } catch (const std::exception&) {
      throw std::invalid_argument("Constraints/Held direction = '" + held_direction +
                                  "': expected 'axis' or three numbers x,y,z");
    }
    if (!(c.constraints.held_direction->norm() > 0))
      throw std::invalid_argument("Constraints/Held direction must not be zero");
  }

  prm.enter_subsection("Contact");
  c.penalty_factor = prm.get_double("Penalty factor");
  c.friction_coefficient = prm.get_double("Friction coefficient");
  c.tangential_penalty_ratio = prm.get_double("Tangential penalty ratio");
  prm.leave_subsection();

  prm.enter_subsection("Protocol");
  c.protocol.final_alpha = prm.get_double("Final alpha");
  c.protocol.alpha_increment = prm.get_double("Alpha increment");
  c.protocol.gravity_while_settling = prm.get_bool("Gravity while settling");
  c.protocol.gravity_while_measuring = prm.get_bool("Gravity while measuring");
  c.protocol.gravity_m_per_s2 = prm.get_double("Gravity");
  c.protocol.up = parse_vec3(prm.get("Up"));
  prm.leave_subsection();

  prm.enter_subsection("Pressure");
  const std::string area = prm.get("Vertex area");
  c.pressure.vertex_area = area == "barycentric"     ? VertexAreaDefinition::barycentric
                           : area == "mixed voronoi" ? VertexAreaDefinition::mixed_voronoi
                                                     : VertexAreaDefinition::adjacent_triangles;
  c.pressure.definition = prm.get("Definition") == "contact traction"
                              ? PressureDefinition::contact_traction
                              : PressureDefinition::garment_force;
  prm.leave_subsection();

  prm.enter_subsection("Measurements");
  for (const std::string& kind : tree.get_list("List"))
    c.measurements.push_back({kind, measurement_kinds().parse_part(tree, kind)});
  prm.leave_subsection();

  prm.enter_subsection("Output");
  c.output.directory = prm.get("Directory");
  c.output.write_vtu = prm.get_bool("Write VTU");
  c.output.body_pressure = prm.get_bool("Body pressure");
  c.output.body_edge_length_m = prm.get_double("Body edge length");
  prm.leave_subsection();

  prm.enter_subsection("Solver");
  c.backend = prm.get("Backend");
  c.threads = parse_threads(prm.get("Threads"));
  prm.leave_subsection();
  c.stop_rule = parse_stop_rule(prm);
  for (const BackendEntry& entry : backend_registry().entries())
    refuse_moved_entries(prm, entry.subsection);

  auto require = [](bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument(message);
  };
  require(c.protocol.up.norm() > 0, "Protocol/Up must not be zero");
  c.fabric.validate();
  if (c.law == "tensile curves") TensileCurves check(c.fabric.tensile_curves());
  return c;
}

// deal.II's messages carry the source location and a stack trace; users need the part that
// says what is wrong ("Additional information").
std::string user_message(const std::exception& e) {
  const std::string full = e.what();
  const std::string marker = "Additional information:";
  auto begin = full.find(marker);
  if (begin == std::string::npos) return full;
  begin += marker.size();
  auto end = full.find("Stacktrace:", begin);
  std::string text = full.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
  std::string folded;
  bool space = false;
  for (char ch : text) {
    const bool blank = ch == ' ' || ch == '\n' || ch == '\t';
    if (blank && !folded.empty()) space = true;
    if (!blank) {
      if (space) folded += ' ';
      folded += ch;
      space = false;
    }
  }
  return folded;
}

// Every subsection and entry declared, for the messages that refuse an unknown one.
DeclaredParameters declared_parameters(const ParameterHandler& prm) {
  std::stringstream short_prm;
  prm.print_parameters(short_prm, ParameterHandler::ShortPRM);
  return DeclaredParameters(short_prm);
}

// The text between `before` and `after` in `text`; "" when either is missing.
std::string between(const std::string& text, const std::string& before, const std::string& after) {
  const auto begin = text.find(before);
  if (begin == std::string::npos) return "";
  const auto end = text.find(after, begin + before.size());
  if (end == std::string::npos) return "";
  return text.substr(begin + before.size(), end - begin - before.size());
}

const char* const lists_every_entry = " (tightfit --print-parameters lists every entry)";

}  // namespace

CaseFile::CaseFile() : prm_(std::make_unique<ParameterHandler>()) {
  declare_case_parameters(*prm_);
  declared_ = std::make_unique<DeclaredParameters>(declared_parameters(*prm_));
}

CaseFile::~CaseFile() = default;

void CaseFile::set(const std::string& assignment) {
  ParameterHandler& prm = *prm_;
  const auto equals = assignment.find('=');
  if (equals == std::string::npos)
    throw std::runtime_error("--set \"" + assignment + "\": expected \"Path/To/Entry=value\"");
  std::string path = assignment.substr(0, equals);
  const std::string value = assignment.substr(equals + 1);
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const auto slash = path.find('/', start);
    parts.push_back(path.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  const std::string where = "--set \"" + assignment + "\": ";
  // An unknown subsection or entry, said with the closest declared names before deal.II sees
  // it (its enter_subsection would declare a new, empty subsection).
  std::vector<std::string> subsections;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string unknown = i + 1 < parts.size()
                                    ? declared_->check_subsection(subsections, parts[i])
                                    : declared_->check_entry(subsections, parts[i]);
    if (!unknown.empty()) throw std::runtime_error(where + unknown + lists_every_entry);
    subsections.push_back(parts[i]);
  }
  int depth = 0;
  try {
    for (std::size_t i = 0; i + 1 < parts.size(); ++i, ++depth) prm.enter_subsection(parts[i]);
    prm.set(parts.back(), value);
  } catch (const std::exception& e) {
    for (; depth > 0; --depth) prm.leave_subsection();
    // A value the entry's pattern refuses: for a selection, the closest of its values.
    const std::string refusal = selection_refusal(value, user_message(e));
    throw std::runtime_error(where + (refusal.empty() ? user_message(e) : refusal));
  }
  for (; depth > 0; --depth) prm.leave_subsection();
}

void CaseFile::read(const std::string& path, const std::vector<std::string>& overrides) {
  if (!std::ifstream(path))
    throw std::runtime_error("cannot open the case file '" + path +
                             "' (from the working directory " +
                             std::filesystem::current_path().string() + ")");
  case_directory_ = std::filesystem::path(path).parent_path().string();
  try {
    prm_->parse_input(path, "", false, false);
  } catch (const std::exception& e) {
    // deal.II stops at the first line it cannot use. An unknown subsection or entry is said
    // with the closest declared names; a value its pattern refuses, for a selection, with the
    // closest of its values.
    const std::string where = "case file '" + path + "', ";
    const std::string unknown = declared_->first_unknown_name_in(path);
    if (!unknown.empty()) throw std::runtime_error(where + unknown + lists_every_entry);
    const std::string message = user_message(e);
    const std::string line = between(message, "Line <", ">");
    const std::string rest = between(message + "\n", ">: ", "\n");
    if (line.empty() || rest.empty())
      throw std::runtime_error("case file '" + path + "': " + message);
    const std::string value = between(message, "The entry value ", " for the entry named");
    const std::string entry = between(message, " for the entry named ", " does not match");
    const std::string refusal = selection_refusal(value, message);
    throw std::runtime_error(where + "line " + line + ": " +
                             (refusal.empty() ? rest : entry + ": " + refusal));
  }
  for (const auto& assignment : overrides) set(assignment);
}

CaseParameters CaseFile::parameters() const {
  return parse_case_parameters(*prm_, case_directory_);
}

std::unique_ptr<Backend> CaseFile::create_backend(const std::string& name,
                                                  const Problem& problem) const {
  const BackendEntry& entry = backend_registry().find(name);
  if (problem.friction_coefficient > 0 && !entry.applies_friction)
    throw std::invalid_argument("Contact/Friction coefficient = " +
                                std::to_string(problem.friction_coefficient) + ": the " + name +
                                " backend has no friction yet; set it to 0 or use Solver/Backend "
                                "= massspring");
  // Solver/Gap tolerance = auto asks no gap the stop rule cannot resolve on this mesh
  // (core/load_step.h).
  StopRule rule = parse_stop_rule(*prm_);
  rule.raise_gap_tolerance_to_stop_rule(mean_rest_edge_length_m(*problem.mesh),
                                        rest_area(*problem.mesh));
  return entry.create(problem, rule, *prm_);
}

void CaseFile::print(std::ostream& out, ParameterFormat format) const {
  switch (format) {
    case ParameterFormat::text:
      prm_->print_parameters(out, ParameterHandler::Text);
      break;
    case ParameterFormat::prm:
      prm_->print_parameters(out, ParameterHandler::PRM);
      break;
    case ParameterFormat::json:
      prm_->print_parameters(out, ParameterHandler::JSON);
      break;
  }
}

}  // namespace tightfit
