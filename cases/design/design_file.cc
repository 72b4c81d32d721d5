#include "cases/design/design_file.h"

#include "cases/case_parameters.h"
#include "cases/limb_tube_cut.h"
#include "cases/scenario.h"
#include "cases/scenario_landmarks.h"
#include "core/tensile_curves.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <stdexcept>

namespace tightfit {

using dealii::ParameterHandler;
namespace Patterns = dealii::Patterns;

struct DesignFile::Handler {
  ParameterHandler prm;
};

namespace {

// deal.II's messages hold a stack trace; users want the sentence after "Additional
// information:".
std::string reason(const std::exception& e) {
  std::string text = e.what();
  const std::string marker = "Additional information:";
  const auto at = text.find(marker);
  if (at == std::string::npos) return text;
  text = text.substr(at + marker.size(), text.find("Stacktrace:") - at - marker.size());
  std::string folded;
  for (char ch : text)
    if (!(std::isspace(static_cast<unsigned char>(ch)) && (folded.empty() || folded.back() == ' ')))
      folded += std::isspace(static_cast<unsigned char>(ch)) ? ' ' : ch;
  while (!folded.empty() && folded.back() == ' ') folded.pop_back();
  return folded;
}

void declare_design(ParameterHandler& prm) {
  prm.enter_subsection("Design");
  prm.declare_entry(
      "Case", "", Patterns::FileName(),
      "The case file of the garment to design (a tapered tube on a limb, its "
      "Girths the limb's, with a Negative ease), from the directory tightfit runs in.");
  prm.declare_entry("Case settings", "", Patterns::Anything(),
                    "Path/To/Entry=value; ...: entries of the case set for the design (the "
                    "fabric, a coarser mesh), as --set would, separated by ';'.");
  prm.declare_entry("Points", "B:0.02, C:0.24, G:0.55", Patterns::Anything(),
                    "NAME or NAME:HEIGHT, ...: the measuring points (RAL-GZ 387: B, B1, C, D, E, "
                    "F, G) in order up the limb; a point without a height lies where the body's "
                    "landmarks put it (a case whose Garment/Kind is limb tube, docs/stocking.md), "
                    "one with a height at that height along the garment from its bottom edge (m).");
  prm.declare_entry("Target", "class", Patterns::Selection("class|pressures"),
                    "class: a compression class at B with the degressive Profile; pressures: "
                    "the mean pressure at every point (Pressures).");
  prm.declare_entry("Class", "II", Patterns::Selection("I|II|III|IV"),
                    "The RAL-GZ 387 class at B (I 18-21, II 23-32, III 34-46, IV >= 49 mmHg).");
  prm.declare_entry("Pressure at B", "0", Patterns::Double(0),
                    "The mean pressure wanted at B (mmHg), within the class's range; 0: the "
                    "middle of the range (class IV needs one).");
  prm.declare_entry("Profile", "B:1, C:0.7, G:0.4", Patterns::Anything(),
                    "NAME:SHARE, ...: the pressure at each point as a share of B's (-), 1 at B and "
                    "falling up the limb (degressive).");
  prm.declare_entry("Pressures", "", Patterns::Anything(),
                    "NAME:PRESSURE, ...: the mean pressure wanted over each point's band (mmHg), "
                    "for Target = pressures.");
  prm.declare_entry("Band width", "0.02", Patterns::Double(1e-4),
                    "Width along the garment of each point's band, centred on it (m).");
  prm.declare_entry("Tolerance", "0.5", Patterns::Double(1e-6),
                    "How close every band's simulated mean must come to its target (mmHg).");
  prm.declare_entry("Maximum iterations", "6", Patterns::Integer(1, 100),
                    "Simulations at most, the first from Laplace's guess.");
  prm.declare_entry("Hoop strip", "free", Patterns::Selection("free|held"),
                    "The fabric's hoop force for Laplace's law: free, the course direction's "
                    "tensile curve (a strip free to narrow); held, a strip held at its rest "
                    "length along the limb (docs/design.md).");
  prm.declare_entry(
      "Largest strain", "1", Patterns::Double(1e-6),
      "The hoop strain range (-) the fabric is trusted over for a law with a "
      "constant stiffness; the tensile-curves law's is its weft curve's last strain.");
  prm.declare_entry("Check backend", "none", Patterns::Selection("none|massspring|fem"),
                    "Runs the final design once more on this backend and reports its bands "
                    "beside the design's; none: no check.");
  prm.declare_entry("Check tolerance", "1", Patterns::Double(1e-6),
                    "How close every band's mean on the check backend must come to its target "
                    "(mmHg); the design's exit status is 1 when one does not, or the check does "
                    "not finish.");
  prm.declare_entry("Output directory", "output/design", Patterns::Anything(),
                    "Where the iterations' runs, the tables and the cut are written.");
  prm.leave_subsection();
}

// The few entries of the case's garment the design reads; the rest of the case file is skipped.
void declare_case_garment(ParameterHandler& prm) {
  prm.enter_subsection("Garment");
  prm.declare_entry("Kind", "tube", Patterns::Anything(), "");
  prm.enter_subsection("Tapered tube");
  prm.declare_entry("Length", "0.24", Patterns::Anything(), "");
  prm.declare_entry("Girths", "0:0.30, 0.24:0.36", Patterns::Anything(), "");
  prm.declare_entry("Negative ease", "", Patterns::Anything(), "");
  prm.leave_subsection();
  prm.enter_subsection("Limb tube");
  prm.declare_entry("Limb", "leg left", Patterns::Anything(), "");
  prm.declare_entry("From", "B - 0.02", Patterns::Anything(), "");
  prm.declare_entry("To", "G + 0.04", Patterns::Anything(), "");
  prm.declare_entry("Girth step", "0.05", Patterns::Anything(), "");
  prm.declare_entry("Negative ease", "", Patterns::Anything(), "");
  prm.leave_subsection();
  prm.leave_subsection();
}

// A limb tube's limb: the case's body measured, the tube cut to its leg as the case cuts it.
LimbGarment limb_tube_limb(ParameterHandler& garment, const std::string& case_file,
                           const std::vector<std::string>& case_overrides) {
  garment.enter_subsection("Garment");
  garment.enter_subsection("Limb tube");
  const std::string limb = garment.get("Limb"), from = garment.get("From"), to = garment.get("To"),
                    step = garment.get("Girth step"), ease = garment.get("Negative ease");
  garment.leave_subsection();
  garment.leave_subsection();
  const std::string where = "case file '" + case_file + "': Garment/Limb tube: ";
  LimbTubeSpec spec;
  try {
    spec = parse_limb_tube_spec(limb, from, to, std::stod(step), ease);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where + e.what());
  }
  if (ease.find_first_not_of(" \t") == std::string::npos)
    throw std::invalid_argument(where +
                                "Negative ease is empty; a design states the cut's ease "
                                "against the limb's girths");
  CaseFile file;
  file.read(case_file, case_overrides);
  const std::unique_ptr<ScenarioBody> body = make_case_body(file.parameters());
  const TriangleSurface surface = scenario_body_surface(*body);
  LimbTubeCut cut;
  try {
    cut = cut_tube_to_leg(surface, measure_body(surface), spec);
  } catch (const BodyMeasureError& e) {
    throw BodyMeasureError(where + "the " + limb + " cannot be measured: " + e.what());
  }
  LimbGarment g;
  g.kind = "limb tube";
  g.length_m = cut.length_m;
  g.girths_m = cut.girths_m;
  for (const PointValue& p : cut.points) g.landmark_points.push_back({p.point, p.value});
  return g;
}

// "Path/To/Entry=value" into `prm`, as the text "subsection Path ... set Entry = value ... end"
// it stands for; an entry `prm` does not declare is refused when `must_exist`, else skipped.
void assign(ParameterHandler& prm, const std::string& assignment, bool must_exist) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos)
    throw std::runtime_error("--set \"" + assignment + "\": expected \"Path/To/Entry=value\"");
  std::string text, closing, path = assignment.substr(0, equals);
  for (auto slash = path.find('/'); slash != std::string::npos; slash = path.find('/')) {
    text += "subsection " + path.substr(0, slash) + "\n";
    closing += "end\n";
    path.erase(0, slash + 1);
  }
  text += "set " + path + " = " + assignment.substr(equals + 1) + "\n" + closing;
  try {
    prm.parse_input_from_string(text, "", !must_exist);
  } catch (const std::exception& e) {
    throw std::runtime_error("--set \"" + assignment + "\": " + reason(e));
  }
}

std::vector<NamedValue> named(const std::string& text, const std::string& entry) {
  return parse_named_values(text, entry);
}

}  // namespace

DesignFile::DesignFile() : prm_(std::make_unique<Handler>()) {
  declare_design(prm_->prm);
}
DesignFile::~DesignFile() = default;

void DesignFile::read(const std::string& path, const std::vector<std::string>& overrides) {
  if (!std::ifstream(path)) throw std::runtime_error("cannot open the design file '" + path + "'");
  path_ = path;
  try {
    prm_->prm.parse_input(path, "", false, false);
  } catch (const std::exception& e) {
    throw std::runtime_error("design file '" + path + "': " + reason(e));
  }
  for (const std::string& o : overrides)
    if (o.rfind("Design/", 0) == 0) assign(prm_->prm, o, true);
  // The design file's own settings of the case first, the command line's after them.
  case_overrides_.clear();
  prm_->prm.enter_subsection("Design");
  const std::string settings = prm_->prm.get("Case settings");
  prm_->prm.leave_subsection();
  for (std::size_t begin = 0; begin < settings.size();) {
    const std::size_t end = std::min(settings.find(';', begin), settings.size());
    std::string piece = settings.substr(begin, end - begin);
    piece.erase(0, piece.find_first_not_of(" \t\n"));
    piece.erase(piece.find_last_not_of(" \t\n") + 1);
    // "Path = value" as in a case file: blanks round the '=' dropped.
    const std::size_t equals = piece.find('=');
    if (equals != std::string::npos) {
      std::string path = piece.substr(0, equals), value = piece.substr(equals + 1);
      path.erase(path.find_last_not_of(" \t") + 1);
      value.erase(0, value.find_first_not_of(" \t"));
      piece = path + "=" + value;
    }
    if (!piece.empty()) case_overrides_.push_back(piece);
    begin = end + 1;
  }
  for (const std::string& o : overrides)
    if (o.rfind("Design/", 0) != 0) case_overrides_.push_back(o);
}

DesignSettings DesignFile::settings() const {
  ParameterHandler& prm = prm_->prm;
  DesignSettings s;
  prm.enter_subsection("Design");
  try {
    s.case_file = prm.get("Case");
    if (s.case_file.empty())
      throw std::invalid_argument("Design/Case: no case file named (the garment to design)");
    s.points = parse_design_points(prm.get("Points"), "Design/Points");
    const bool by_class = prm.get("Target") == "class";
    s.target.kind =
        by_class ? DesignTarget::Kind::compression_class : DesignTarget::Kind::pressures;
    const std::string c = prm.get("Class");
    s.target.class_number = c == "I" ? 1 : c == "II" ? 2 : c == "III" ? 3 : 4;
    s.target.pressure_at_b_mmHg = prm.get_double("Pressure at B");
    if (by_class)
      s.target.profile = named(prm.get("Profile"), "Design/Profile");
    else
      s.target.pressures = named(prm.get("Pressures"), "Design/Pressures");
    s.band_width_m = prm.get_double("Band width");
    s.tolerance_mmHg = prm.get_double("Tolerance");
    s.maximum_iterations = prm.get_integer("Maximum iterations");
    s.hoop_strip = prm.get("Hoop strip") == "held" ? HoopStrip::held : HoopStrip::free;
    s.largest_strain = prm.get_double("Largest strain");
    s.check_backend = prm.get("Check backend") == "none" ? "" : prm.get("Check backend");
    s.check_tolerance_mmHg = prm.get_double("Check tolerance");
    s.output_directory = prm.get("Output directory");
  } catch (...) {
    prm.leave_subsection();
    throw;
  }
  prm.leave_subsection();
  return s;
}

LimbGarment DesignFile::limb_garment() const {
  const DesignSettings s = settings();
  ParameterHandler garment;
  declare_case_garment(garment);
  if (!std::ifstream(s.case_file))
    throw std::invalid_argument("Design/Case: cannot open the case file '" + s.case_file + "'");
  try {
    garment.parse_input(s.case_file, "", true, false);  // the case's other entries skipped
  } catch (const std::exception& e) {
    throw std::invalid_argument("case file '" + s.case_file + "': " + reason(e));
  }
  for (const std::string& o : case_overrides_) assign(garment, o, false);
  garment.enter_subsection("Garment");
  const std::string kind = garment.get("Kind");
  garment.leave_subsection();
  if (kind == "limb tube") return limb_tube_limb(garment, s.case_file, case_overrides_);
  garment.enter_subsection("Garment");
  garment.enter_subsection("Tapered tube");
  const std::string length = garment.get("Length"), girths = garment.get("Girths"),
                    ease = garment.get("Negative ease");
  garment.leave_subsection();
  garment.leave_subsection();
  if (kind != "tapered tube")
    throw std::invalid_argument("case file '" + s.case_file + "': Garment/Kind is '" + kind +
                                "'; a design cuts a tapered tube or a limb tube");
  if (ease.find_first_not_of(" \t") == std::string::npos)
    throw std::invalid_argument(
        "case file '" + s.case_file +
        "': Garment/Tapered tube/Negative ease is empty, so its Girths are the garment's and not "
        "the limb's; a design needs the limb's girths (Girths with a Negative ease)");
  LimbGarment limb;
  limb.kind = kind;
  try {
    limb.length_m = std::stod(length);
  } catch (const std::exception&) {
    throw std::invalid_argument("case file '" + s.case_file +
                                "': Garment/Tapered tube/Length is not a number: " + length);
  }
  std::vector<PiecewiseLinear::Point> points;
  for (const CurvePoint& p :
       parse_curve_points(girths, "Garment/Tapered tube/Girths", "height:girth (e.g. 0.1:0.21)"))
    points.push_back({p.strain, p.value});
  limb.girths_m = PiecewiseLinear(points, "Garment/Tapered tube/Girths");
  return limb;
}

void DesignFile::print(std::ostream& out) const {
  prm_->prm.print_parameters(out, ParameterHandler::PRM);
}

}  // namespace tightfit
