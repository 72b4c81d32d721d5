#include "app/command_line.h"

#include "core/closest_names.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace tightfit {

std::string usage_text() {
  return R"(tightfit: the pressure a tight garment puts on a body, by simulation.

Usage:
  tightfit run CASE.prm [CASE2.prm ...] [--output DIR] [--set "Path/To/Entry=value" ...]
      Runs each case: settles the garment, grows the body step by step, and writes
      pressure.csv, pressure_theta.csv and VTU/PVD files (ParaView) into DIR (with several
      cases, DIR/<case name>); prints progress and a summary table.
  tightfit compare CASE.prm [--output DIR] [--set ...]
      Runs the case on both backends on the same mesh and writes compare.csv.
  tightfit convergence CASE.prm [--levels N] [--ratio R] [--regions A,B,...]
                               [--backends massspring,fem] [--output DIR] [--set ...]
      Runs the case on N meshes (default 3), dividing the edge lengths by R (default 2) each
      time, on each backend (default both), and prints and writes the mean pressure's observed
      order, Richardson estimate and GCI; for a case with named regions (Measurements/List:
      regions) the same for each region's mean and peak pressure (default every region).
  tightfit pattern FILE [--edge-length L] [--seams "..."] [--folds "..."] [--size S]
                        [--units mm|cm|inch] [--output DIR]
      Reads a sewing pattern (.svg, .json, .dxf), prints its sizes (a graded DXF), panels,
      edge lengths and seam length mismatches, meshes it (target edge length L in m, default
      0.01) and writes the meshed panels (pattern.vtu) and a drawing of the outlines and seams
      (outlines.png) into DIR (default output/pattern). --seams, --folds, --size and --units
      are the case file's Garment/Pattern file entries Seams, Fold edges, Size and Units
      (docs/patterns.md).
  tightfit girths CASE.prm --near X,Y,Z --heights H1,H2,... [--axis X,Y,Z] [--set ...]
      Slices the case's body by planes normal to the axis (default 0,0,1) at each height (m,
      in the run's coordinates) and prints, for the loop round the point --near (a leg, not
      the other one), its girth along the section and as a tape reads it (the convex hull),
      its area and centroid, and the line through the first and last centroids: the limb's
      axis for Placement/Tube round axis (docs/stocking.md).
  tightfit measure BODY [--units m|cm|mm|SCALE] [--up +y] [--output DIR]
  tightfit measure CASE.prm [--set ...] [--output DIR]
      Finds a body's landmarks, part axes and standard girths (bust, waist, hips, thigh,
      knee, calf, ankle B, upper arm, wrist; height, shoulder width, arm length), prints them
      and the named regions built from them, and writes measurements.json, measurements.csv
      and body.png (front and side with landmarks and tape lines) into DIR (default
      output/measure/<file name>). BODY is an OBJ, STL or PLY file (--units: metres per unit
      or m, cm, mm, default m; --up: the file's up axis, default +z); a case's body is read as
      the case reads it (docs/measuring-bodies.md).
  tightfit design DESIGN.prm [--output DIR] [--set "Design/Entry=value" | "Case/Entry=value" ...]
      Designs the tapered tube of the design's case so that it gives the pressure asked for at
      the measuring points of the limb: Laplace's first guess, then simulations corrected band
      by band; prints each iteration and writes the tables and the cut (cut.csv, cut.svg,
      cut.dxf) into DIR (docs/design.md). --set "Design/..." sets the design's entries, every
      other one the case's.
  tightfit --print-parameters [--prm | --json]
      Lists every parameter with its documentation, unit and default (--prm: as a case file to
      start from; --json: with each entry's allowed values).
  tightfit --help | --version

Every parameter is in SI units (m, N/m, Pa, kg/m^2); tables also show gf/cm^2 and mmHg.
Exit status: 0 success, 1 a solver failed (results so far are kept), 2 bad input.
)";
}

namespace {

// "a,b,c" as names; throws UsageError naming the option for an empty one.
std::vector<std::string> name_list(const std::string& option, const std::string& text) {
  std::vector<std::string> names;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    std::string piece = text.substr(begin, comma - begin);
    piece.erase(0, piece.find_first_not_of(' '));
    piece.erase(piece.find_last_not_of(' ') + 1);
    if (piece.empty())
      throw UsageError(option + " needs names separated by commas, not '" + text + "'");
    names.push_back(piece);
    begin = comma + 1;
  }
  return names;
}

// "1,2.5,-3" as numbers; throws UsageError naming the option.
std::vector<double> number_list(const std::string& option, const std::string& text) {
  std::vector<double> numbers;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t comma = std::min(text.find(',', begin), text.size());
    const std::string piece = text.substr(begin, comma - begin);
    char* end = nullptr;
    const double x = std::strtod(piece.c_str(), &end);
    if (piece.empty() || end != piece.c_str() + piece.size() || !std::isfinite(x))
      throw UsageError(option + " needs numbers separated by commas, not '" + text + "'");
    numbers.push_back(x);
    begin = comma + 1;
  }
  return numbers;
}

// The options each command takes, for the message that refuses another.
std::vector<std::string> options_of(const std::string& command) {
  std::vector<std::string> options{"--output", "--set"};
  if (command == "convergence")
    options.insert(options.end(), {"--levels", "--ratio", "--regions", "--backends"});
  if (command == "pattern")
    options.insert(options.end(), {"--edge-length", "--seams", "--folds", "--size", "--units"});
  if (command == "girths") options.insert(options.end(), {"--near", "--heights", "--axis"});
  return options;
}

}  // namespace

CommandLine parse_command_line(int argc, const char* const* argv) {
  CommandLine cl;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) throw UsageError("no command given");
  const std::string& first = args[0];
  if (first == "--help" || first == "-h" || first == "help") {
    cl.command = "help";
    return cl;
  }
  if (first == "--version") {
    cl.command = "version";
    return cl;
  }
  if (first == "--print-parameters") {
    cl.command = "print-parameters";
    for (std::size_t i = 1; i < args.size(); ++i) {
      if (args[i] != "--prm" && args[i] != "--json")
        throw UsageError("--print-parameters takes --prm or --json, not '" + args[i] + "'" +
                         did_you_mean(args[i], {"--prm", "--json"}));
      cl.parameters_format = args[i].substr(2);
    }
    return cl;
  }
  // The commands parsed here, then the ones only offered as suggestions ("measure" reads its
  // own options, app/measure_command.h).
  const std::vector<std::string> commands{"run",    "compare",  "convergence", "pattern",
                                          "girths", "design",   "measure",     "--print-parameters",
                                          "--help", "--version"};
  const auto parsed_end = commands.begin() + 6;
  if (std::find(commands.begin(), parsed_end, first) == parsed_end)
    throw UsageError("unknown command '" + first + "'" + did_you_mean(first, commands));
  cl.command = first;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--output" || a == "-o") {
      cl.output_dir = value();
    } else if (a == "--set" || a == "-s") {
      cl.overrides.push_back(value());
    } else if (a == "--levels") {
      const std::string& text = value();
      try {
        std::size_t used = 0;
        cl.levels = std::stoi(text, &used);
        if (used != text.size()) throw std::invalid_argument(text);
      } catch (const std::exception&) {
        throw UsageError("--levels needs a whole number, not '" + text + "'");
      }
      if (cl.levels < 2 || cl.levels > 8) throw UsageError("--levels must be between 2 and 8");
    } else if (first == "convergence" && a == "--ratio") {
      const std::string& text = value();
      char* end = nullptr;
      cl.refinement_ratio = std::strtod(text.c_str(), &end);
      // Above 4 a level would hold 16 times the vertices of the one before.
      if (end == text.c_str() || *end != '\0' || !(cl.refinement_ratio > 1.0) ||
          cl.refinement_ratio > 4.0)
        throw UsageError("--ratio needs a number above 1 and at most 4, not '" + text + "'");
    } else if (first == "convergence" && a == "--regions") {
      cl.convergence_regions = name_list(a, value());
    } else if (first == "convergence" && a == "--backends") {
      cl.convergence_backends = name_list(a, value());
    } else if (first == "pattern" && a == "--edge-length") {
      const std::string& text = value();
      char* end = nullptr;
      cl.pattern_edge_length_m = std::strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(cl.pattern_edge_length_m > 0))
        throw UsageError("--edge-length needs a positive length in m, not '" + text + "'");
    } else if (first == "pattern" && a == "--seams") {
      cl.pattern_seams = value();
    } else if (first == "pattern" && a == "--folds") {
      cl.pattern_folds = value();
    } else if (first == "pattern" && a == "--size") {
      cl.pattern_size = value();
    } else if (first == "pattern" && a == "--units") {
      cl.pattern_units = value();
      if (cl.pattern_units != "mm" && cl.pattern_units != "cm" && cl.pattern_units != "inch")
        throw UsageError("--units must be mm, cm or inch, not '" + cl.pattern_units + "'");
    } else if (first == "girths" && (a == "--near" || a == "--heights" || a == "--axis")) {
      std::vector<double>& list = a == "--near"      ? cl.girths_near
                                  : a == "--heights" ? cl.girths_heights
                                                     : cl.girths_axis;
      list = number_list(a, value());
      if (a != "--heights" && list.size() != 3) throw UsageError(a + " needs three numbers x,y,z");
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("unknown option '" + a + "' of " + first +
                       did_you_mean(a, options_of(first)));
    } else {
      cl.case_files.push_back(a);
    }
  }
  if (cl.command == "girths") {
    if (cl.case_files.size() != 1) throw UsageError("girths takes one case file");
    if (cl.girths_near.empty() || cl.girths_heights.empty())
      throw UsageError("girths needs --near X,Y,Z and --heights H1,H2,...");
    return cl;
  }
  if (cl.command == "pattern") {
    if (cl.case_files.size() != 1) throw UsageError("pattern takes one pattern file");
    return cl;
  }
  if (cl.case_files.empty()) throw UsageError(cl.command + " needs a case file (.prm)");
  if (cl.command != "run" && cl.case_files.size() > 1)
    throw UsageError(cl.command + " takes one case file");
  return cl;
}

}  // namespace tightfit
