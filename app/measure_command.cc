#include "app/measure_command.h"
#include "core/number_text.h"

#include "app/command_line.h"
#include "bodies/mesh_import.h"
#include "bodies/polygon_mesh.h"
#include "body/anatomical_regions.h"
#include "body/body_picture.h"
#include "body/body_report.h"
#include "body/body_size.h"
#include "cases/case_parameters.h"
#include "cases/scenario.h"
#include "cases/scenario_body.h"
#include "core/closest_names.h"

#include <filesystem>
#include <ostream>
#include <sstream>

namespace tightfit {

namespace {

namespace fs = std::filesystem;

struct MeasureOptions {
  std::string file;
  MeshImportOptions import;
  std::vector<std::string> overrides;
  std::string output_dir;
};

double units_scale(const std::string& word) {
  if (word == "m") return 1.0;
  if (word == "cm") return 0.01;
  if (word == "mm") return 0.001;
  const std::optional<double> value = whole_number(word);
  if (!value || !(*value > 0))
    throw UsageError("--units needs m, cm, mm or a positive number of metres per unit, not '" +
                     word + "'");
  return *value;
}

MeasureOptions parse(int argc, const char* const* argv) {
  MeasureOptions o;
  o.import.up_axis = "+z";
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--units") {
      o.import.metres_per_unit = units_scale(value());
    } else if (a == "--up") {
      o.import.up_axis = value();
      import_rotation(o.import);  // an unknown axis is refused here, naming the six
    } else if (a == "--output" || a == "-o") {
      o.output_dir = value();
    } else if (a == "--set") {
      o.overrides.push_back(value());
    } else if (!a.empty() && a[0] == '-') {
      throw UsageError("measure: unknown option '" + a + "'" +
                       did_you_mean(a, {"--units", "--up", "--output", "--set"}));
    } else if (o.file.empty()) {
      o.file = a;
    } else {
      throw UsageError("measure takes one body or case file, not also '" + a + "'");
    }
  }
  if (o.file.empty()) throw UsageError("measure needs a body file (OBJ, STL, PLY) or a case file");
  return o;
}

bool is_case_file(const std::string& path) {
  return fs::path(path).extension() == ".prm";
}

// The case's body as the case reads it, in its starting shape.
TriangleSurface case_body(const MeasureOptions& o, std::string& description) {
  CaseFile file;
  file.read(o.file, o.overrides);
  const CaseParameters parameters = file.parameters();
  const std::unique_ptr<ScenarioBody> body = make_case_body(parameters);
  body->morph(0, body->initial_alpha());
  description = body->describe();
  const DisplayMesh mesh = body->body().display_mesh();
  TriangleSurface surface;
  surface.vertices_m = mesh.vertices_m;
  surface.triangles = mesh.triangles;
  return surface;
}

std::string region_text(const RegionPiece& p) {
  std::ostringstream text;
  text.precision(3);
  text << std::fixed;
  if (p.kind == RegionPiece::Kind::box)
    text << "box " << p.min_m.x() << "," << p.min_m.y() << "," << p.min_m.z() << " " << p.max_m.x()
         << "," << p.max_m.y() << "," << p.max_m.z();
  else
    text << "tube round " << p.point_m.x() << "," << p.point_m.y() << "," << p.point_m.z()
         << " along " << p.axis.x() << "," << p.axis.y() << "," << p.axis.z() << ", " << p.low_m
         << " to " << p.high_m << ", radius " << p.radius_m;
  return text.str();
}

}  // namespace

int measure_command(int argc, const char* const* argv, std::ostream& out) {
  const MeasureOptions o = parse(argc, argv);
  TriangleSurface surface;
  std::string description;
  if (is_case_file(o.file)) {
    surface = case_body(o, description);
  } else {
    if (!o.overrides.empty()) throw UsageError("measure: --set applies to a case file only");
    surface = import_surface(read_polygon_mesh(o.file), o.import);
    check_body_surface(surface, false, "body mesh '" + o.file + "'");
    description = "body mesh '" + o.file + "' (" + std::to_string(surface.triangles.size()) +
                  " triangles; " + describe_extent(body_extent(surface.vertices_m)) + ")";
  }
  const BodyExtent extent = body_extent(surface.vertices_m);
  out << "Measuring " << description << "\n\n";
  check_standing_person(extent, "body '" + o.file + "'");
  const BodyMeasurements m = measure_body(surface);
  for (const TextTable& t : measurement_tables(m)) out << t << "\n";
  TextTable regions("Named regions on this body (Measurements/Regions/Definitions), default widths",
                    {"region", "shapes (m)"});
  for (const std::string& name : anatomical_region_names()) {
    AnatomyRequest r;
    r.name = name;
    std::string shapes;
    for (const RegionPiece& p : anatomical_region(m, r))
      shapes += (shapes.empty() ? "" : " + ") + region_text(p);
    regions.add_row({name, shapes});
  }
  out << regions << "\n";
  const fs::path dir = o.output_dir.empty()
                           ? fs::path("output") / "measure" / fs::path(o.file).stem()
                           : fs::path(o.output_dir);
  fs::create_directories(dir);
  write_measurements_json((dir / "measurements.json").string(), m, o.file);
  write_measurements_csv((dir / "measurements.csv").string(), m);
  write_body_picture((dir / "body.png").string(), surface, m,
                     fs::path(o.file).filename().string() + ": landmarks and girth lines");
  out << "Wrote " << (dir / "measurements.json").string() << ", measurements.csv, body.png\n";
  return 0;
}

}  // namespace tightfit
