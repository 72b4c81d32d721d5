// Placement/Kind = pattern arrangement: every panel flat where its pattern file puts it round
// the file's own body (GarmentCode's translation and rotation), moved onto the case's body by
// the landmarks (the reference body's torso onto the body's: root, length and girths), then
// sewn onto the body by the dressing stage (core/dressing_stage.h) while the body grows back
// from a start shrunk about its skeleton, each part about its own axis (docs/arrangement.md
// "Arrangement from the pattern file").
#include "bodies/mesh_import.h"
#include "bodies/polygon_mesh.h"
#include "body/garment_arrangement.h"
#include "cases/coarse_dressing.h"
#include "cases/failed_dressing_output.h"
#include "cases/parts/part_entries.h"
#include "cases/scenario.h"
#include "core/backend_registry.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace tightfit {

namespace {

const char* const up_axes = "+x|-x|+y|-y|+z|-z";

BodyMeasurements measured(const TriangleSurface& surface, const std::string& what) {
  try {
    return measure_body(surface);
  } catch (const BodyMeasureError& error) {
    throw std::invalid_argument("Placement/Pattern arrangement: the " + what +
                                " needs its landmarks: " + error.what());
  }
}

TriangleSurface surface_of(const RigidBody& body) {
  const DisplayMesh mesh = body.display_mesh();
  TriangleSurface surface;
  surface.vertices_m = mesh.vertices_m;
  surface.triangles = mesh.triangles;
  return surface;
}

}  // namespace

PartEntry<PlacementMaker> pattern_arrangement_placement_entry() {
  PartEntry<PlacementMaker> e;
  e.name = "pattern arrangement";
  e.subsection = "Pattern arrangement";
  e.description =
      "the panels unsewn and flat where the pattern file arranges them (GarmentCode), moved onto "
      "the body by its landmarks, sewn by seam springs while the body grows from a start shrunk "
      "about its skeleton (docs/arrangement.md).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_selection("Pattern up axis", "+y", up_axes,
                          "The pattern file's up direction (GarmentCode: +y, its front +z): "
                          "turned onto +z as Body/Mesh/Up axis turns a body's.");
    prm.declare_file_name("Reference body", "",
                          "The body the file's arrangement was made round (GarmentCode: its mean "
                          "body); its torso is moved onto the case body's by their landmarks. "
                          "Empty: the arrangement is taken as it is, in the body's frame.");
    prm.declare_selection("Reference body up axis", "+y", up_axes,
                          "The reference body file's up direction.");
    prm.declare_double("Reference body unit scale", 1, 1e-6, 1e6,
                       "Metres per unit of the reference body file (0.01 for centimetres).");
    prm.declare_double("Lift", 0, -1, 1,
                       "The arrangement moved up by this after the fit (m): for a file drafted "
                       "round a body that is not given as Reference body.");
    prm.declare_double("Start scale", 0.6, 0.05, 1,
                       "The body's scale about its skeleton at the start of the dressing (-): "
                       "each part's distance from its own axis times this.");
    prm.declare_double("Skeleton blend", 0.03, 0, 1,
                       "Where two parts' axes are within this of equally near (shoulders, "
                       "armpits, crotch), a vertex shrinks towards both, blended (m).");
    prm.declare_double("Arm raise", 30, 0, 80,
                       "At the start the arms are turned this far away from the torso about "
                       "their shoulders (degrees), and back as the body grows, so that the "
                       "torso's side seams find room under them.");
    prm.declare_bool("Shorten torso", true,
                     "The torso also shrinks along its axis about its middle, the limbs moving "
                     "with their roots, so that the shoulders start lower than the shoulder "
                     "seams; false: each part shrinks across its own axis only.");
    prm.declare_double("Damping", 2000, 0, ParameterTree::unbounded,
                       "Mass-proportional damping while the seams close (1/s): the panels, "
                       "drawn from tenths of a metre apart, move without overshooting their "
                       "partners (docs/cookbook-jumpsuit.md); 0: the automatic one, critical "
                       "for the garment's slowest membrane wave.");
    declare_dressing_frames(prm);
  };
  e.parse = [](ParameterTree& prm) -> PlacementMaker {
    MeshImportOptions pattern_frame;
    pattern_frame.up_axis = prm.get("Pattern up axis");
    const Mat3 frame = import_rotation(pattern_frame);
    std::optional<TriangleSurface> reference;
    if (const std::string file = prm.get_file_name("Reference body"); !file.empty()) {
      MeshImportOptions options;
      options.up_axis = prm.get("Reference body up axis");
      options.metres_per_unit = prm.get_double("Reference body unit scale");
      reference = import_surface(read_polygon_mesh(file), options);
    }
    const double lift_m = prm.get_double("Lift");
    const double blend_m = prm.get_double("Skeleton blend");
    const double arm_raise_rad = prm.get_double("Arm raise") * M_PI / 180.0;
    const bool shorten_torso = prm.get_bool("Shorten torso");
    DressingSettings settings;
    draw_seams_from_afar(settings);
    settings.start_scale = prm.get_double("Start scale");
    read_dressing_frames(prm, settings);
    settings.damping_per_s = prm.get_double("Damping");
    settings.progress = &std::cout;
    return [=](const Scenario& scenario) {
      const BodyMeasurements body = measured(surface_of(scenario.body->body()), "case's body");
      ArrangementFit fit =
          reference ? fit_arrangement(frame, measured(*reference, "reference body"), body)
                    : unfitted_arrangement(frame);
      fit.body_origin_m.z() += lift_m;
      std::printf(
          "  arrangement: the pattern's torso moved onto the body's at (%.3f, %.3f, %.3f) m, "
          "scaled %.3f across and %.3f along\n",
          fit.body_origin_m.x(), fit.body_origin_m.y(), fit.body_origin_m.z(), fit.across,
          fit.vertical);
      DressingSettings dressing = settings;
      dressing.skeleton = skeleton_bones(body);
      dressing.skeleton_blend_m = blend_m;
      dressing.skeleton_arm_raise_rad = arm_raise_rad;
      dressing.skeleton_shortens_torso = shorten_torso;
      write_failed_dressing_to(scenario.parameters.output, dressing);
      std::vector<Vec3> start;
      try {
        start = arranged_positions(scenario.garment, scenario.mesh, fit);
        const DressingResult dressed = backend_registry().dressing_stage().dress(
            scenario.problem, scenario.garment, start, dressing);
        print_dressing(dressed);
        return dressed.welded_positions_m;
      } catch (const std::invalid_argument& error) {
        throw std::invalid_argument(std::string("Placement/Pattern arrangement: ") + error.what());
      }
    };
  };
  return e;
}

}  // namespace tightfit
