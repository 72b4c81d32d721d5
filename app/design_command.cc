#include "app/design_command.h"

#include "cases/case_parameters.h"
#include "cases/design/case_simulation.h"
#include "cases/design/design_file.h"
#include "cases/design/design_loop.h"
#include "cases/design/design_report.h"
#include "cases/design/stocking_cut.h"
#include "core/units.h"
#include "io/csv_table.h"
#include "io/text_table.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <ostream>

namespace tightfit {

namespace {

namespace fs = std::filesystem;

double mmHg(double Pa) {
  return units::to_mmHg(Pa);
}

// Each iteration's table on screen.
TextTable iteration_table(const DesignProblem& problem, const DesignIteration& it) {
  TextTable table("Iteration " + std::to_string(it.number) + " (" + format_fixed(it.seconds, 0) +
                      " s): band means in mmHg" +
                      (it.met ? ", every band within the tolerance" : ""),
                  {"point", "H [m]", "girth [cm]", "circumference [cm]", "ease", "target",
                   "Laplace", "simulated", "error", "peak"});
  for (std::size_t k = 0; k < it.bands.size(); ++k) {
    const DesignBand& b = it.bands[k];
    const double g = problem.girths_m[k];
    table.add_row(
        {problem.points[k].name, format_fixed(problem.points[k].value, 4), format_fixed(100 * g, 2),
         format_fixed(100 * b.circumference_m, 2), format_fixed(1 - b.circumference_m / g, 3),
         format_fixed(mmHg(problem.targets_Pa[k]), 2), format_fixed(mmHg(b.laplace_Pa), 2),
         format_fixed(mmHg(b.mean_Pa), 2), format_fixed(mmHg(b.mean_Pa - problem.targets_Pa[k]), 2),
         format_fixed(mmHg(b.peak_Pa), 2)});
  }
  return table;
}

}  // namespace

int design_command(const CommandLine& cl, std::ostream& out) {
  DesignFile file;
  file.read(cl.case_files.front(), cl.overrides);
  DesignSettings settings = file.settings();
  if (!cl.output_dir.empty()) settings.output_directory = cl.output_dir;
  const LimbGarment limb = file.limb_garment();

  // The case's fabric and law, for Laplace's hoop force.
  CaseFile case_file;
  case_file.read(settings.case_file, file.case_overrides());
  const CaseParameters parameters = case_file.parameters();
  const HoopForce hoop(
      make_material_law(parameters.law, parameters.fabric), settings.hoop_strip,
      known_largest_strain(parameters.law, parameters.fabric, settings.largest_strain));

  DesignProblem problem;
  problem.points = design_point_heights(settings.points, limb.length_m, limb.landmark_points);
  for (const NamedValue& p : problem.points) problem.girths_m.push_back(limb.girths_m.at(p.value));
  for (double t : target_pressures_mmHg(problem.points, settings.target))
    problem.targets_Pa.push_back(t * units::pascal_per_mmHg);
  problem.tolerance_Pa = settings.tolerance_mmHg * units::pascal_per_mmHg;
  problem.maximum_iterations = settings.maximum_iterations;
  // Refuses a target no strain in range gives before anything runs.
  laplace_first_guess(problem, hoop);

  CaseSimulationSetup setup;
  setup.case_file = settings.case_file;
  setup.case_overrides = file.case_overrides();
  setup.garment_kind = limb.kind;
  setup.limb_girths_m = limb.girths_m;
  setup.points = problem.points;
  setup.band_width_m = settings.band_width_m;
  const fs::path dir = settings.output_directory;
  fs::create_directories(dir);

  out << "Designing the garment of " << settings.case_file << " (" << parameters.law
      << ", hoop strip " << (settings.hoop_strip == HoopStrip::free ? "free" : "held")
      << ", strain range 0 to " << hoop.largest_strain() << ") on the " << parameters.backend
      << " backend; every band within " << settings.tolerance_mmHg << " mmHg, at most "
      << settings.maximum_iterations << " simulations\n";
  // Points closer than a band width share part of their bands (and so their peaks).
  for (std::size_t k = 1; k < problem.points.size(); ++k) {
    const double apart = problem.points[k].value - problem.points[k - 1].value;
    if (apart < settings.band_width_m)
      out << "  note: the bands of " << problem.points[k - 1].name << " and "
          << problem.points[k].name << " overlap (" << format_fixed(100 * apart, 1)
          << " cm apart, bands " << format_fixed(100 * settings.band_width_m, 1) << " cm wide)\n";
  }
  out << "\n";

  CsvTable iterations((dir / "design_iterations.csv").string(),
                      {"iteration", "seconds", "point", "height_m", "girth_m", "circumference_m",
                       "target_mmHg", "laplace_mmHg", "mean_mmHg", "peak_mmHg", "error_mmHg"});
  const auto on_iteration = [&](const DesignIteration& it) {
    out << iteration_table(problem, it) << "\n" << std::flush;
    for (std::size_t k = 0; k < it.bands.size(); ++k) {
      const DesignBand& b = it.bands[k];
      iterations.write_row({it.number, it.seconds, problem.points[k].name, problem.points[k].value,
                            problem.girths_m[k], b.circumference_m, mmHg(problem.targets_Pa[k]),
                            mmHg(b.laplace_Pa), mmHg(b.mean_Pa), mmHg(b.peak_Pa),
                            mmHg(b.mean_Pa - problem.targets_Pa[k])});
    }
  };
  // Each iteration starts from where the one before left the garment.
  const auto iteration_dir = [&](int number) {
    return (dir / ("iteration_" + std::to_string(number))).string();
  };
  const auto simulate = [&](const std::vector<double>& c, int number) {
    const std::string previous =
        number > 1 ? iteration_dir(number - 1) + "/garment_0000.vtu" : std::string();
    return simulate_cut(setup, c, "", iteration_dir(number), previous);
  };

  const auto start = std::chrono::steady_clock::now();
  DesignResult result;
  try {
    result = run_design(problem, hoop, simulate, on_iteration);
  } catch (const DesignRunFailed& e) {
    out << "design stopped: " << e.what() << "\n";
    return 1;
  }
  const double total_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const DesignIteration& last = result.iterations.back();
  std::vector<double> c;
  for (const DesignBand& b : last.bands) c.push_back(b.circumference_m);

  // The cut.
  const std::vector<CutKnot> cut = design_cut(limb.girths_m, problem.points, c);
  write_cut_csv((dir / "cut.csv").string(), cut);
  write_cut_svg((dir / "cut.svg").string(), parameters.garment.name, cut);
  write_cut_dxf((dir / "cut.dxf").string(), parameters.garment.name, cut);

  // What the simulation adds to Laplace's law, band by band (design.csv, written before the
  // check, which may take long, and again with it).
  const std::string title =
      std::string(result.met ? "The design" : "The last iteration (not met)") + " after " +
      std::to_string(result.iterations.size()) + " simulations, " + format_fixed(total_s, 0) +
      " s: Laplace's law against the simulation, mmHg";
  DesignCheck check;
  check.backend = settings.check_backend;
  check.tolerance_Pa = settings.check_tolerance_mmHg * units::pascal_per_mmHg;
  write_design_csv((dir / "design.csv").string(), problem, last, check);

  // The check on another backend: the final cut once more, from the case's placement.
  const std::string check_dir = (dir / ("check_" + check.backend)).string();
  if (!check.backend.empty()) {
    out << design_table(title, problem, last, check) << "Checking the cut on the " << check.backend
        << " backend (" << check_dir << ")\n"
        << std::flush;
    const auto check_start = std::chrono::steady_clock::now();
    try {
      check.bands = simulate_cut(setup, c, check.backend, check_dir);
    } catch (const DesignRunFailed& e) {
      check.failure = e.what();
    }
    out << "  the check took "
        << format_fixed(
               std::chrono::duration<double>(std::chrono::steady_clock::now() - check_start)
                   .count(),
               0)
        << " s\n";
    write_design_csv((dir / "design.csv").string(), problem, last, check);
  }

  out << design_table(title, problem, last, check) << "  results in " << dir.string()
      << "/ (design_iterations.csv, design.csv, cut.csv, cut.svg, cut.dxf, iteration_N/";
  if (!check.backend.empty()) out << ", " << check_dir << "/";
  out << ")\n";
  if (!result.met)
    out << "  not every band is within " << settings.tolerance_mmHg << " mmHg after "
        << settings.maximum_iterations << " simulations\n";
  bool check_holds = true;
  if (!check.backend.empty()) {
    const std::vector<std::string> outside = check_outside(problem, check);
    check_holds = check.failure.empty() && outside.empty();
    if (!check.failure.empty()) {
      out << "  the check on the " << check.backend << " backend did not finish: " << check.failure
          << "\n";
    } else if (outside.empty()) {
      out << "  the check on the " << check.backend << " backend: every band within "
          << settings.check_tolerance_mmHg << " mmHg of its target\n";
    } else {
      std::string names;
      for (const std::string& n : outside) names += (names.empty() ? "" : ", ") + n;
      out << "  the check on the " << check.backend << " backend: band(s) " << names
          << " farther than " << settings.check_tolerance_mmHg << " mmHg from the target\n";
    }
  }
  return result.met && check_holds ? 0 : 1;
}

}  // namespace tightfit
