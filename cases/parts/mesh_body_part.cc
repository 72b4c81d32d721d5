// Body/Kind = mesh: a rigid body read from a closed triangle or quad mesh (OBJ, STL, PLY; a
// scanned or modelled limb or torso; bodies/mesh_body.h). It does not change between load
// steps: alpha is ignored.
#include "body/body_size.h"
#include "cases/parts/mesh_body_settings.h"
#include "cases/parts/part_entries.h"

#include <stdexcept>

namespace tightfit {

namespace {

class MeshScenarioBody final : public ScenarioBody {
 public:
  MeshScenarioBody(std::unique_ptr<MeshBody> body, std::string file)
      : body_(std::move(body)), file_(std::move(file)) {}
  const RigidBody& body() const override { return *body_; }
  double initial_alpha() const override { return 1.0; }
  void morph(int, double) override {}
  std::string describe() const override {
    return "mesh body '" + file_ + "' (" + std::to_string(body_->surface().triangles.size()) +
           " triangles; " + describe_extent(body_extent(body_->surface().vertices_m)) + ")";
  }

 private:
  std::unique_ptr<MeshBody> body_;
  std::string file_;
};

}  // namespace

void declare_mesh_body_settings(ParameterTree& prm) {
  prm.declare_file_name("File", "", "The body's closed surface mesh (OBJ, STL or PLY).");
  prm.declare_double("Unit scale", 1.0, 0, ParameterTree::unbounded,
                     "Metres per unit of the file's coordinates (0.001 for millimetres) (-).");
  prm.declare_selection("Up axis", "+z", "+x|+y|+z|-x|-y|-z",
                        "The file's axis that points up; it is turned onto +z (a +y-up file by "
                        "+90 degrees about x).");
  prm.declare_vector("Rotation", "0,0,0",
                     "Rotation applied after the up axis is set: angles about x, y and z, in "
                     "that order (degrees).");
  prm.declare_vector("Translation", "0,0,0", "Translation applied last (m).");
  prm.declare_bool("Accept open surface", false,
                   "Accept a surface with boundary edges (a torso cut at neck and limbs); its "
                   "inside and outside are then only meaningful away from the boundary.");
  prm.declare_double("Skin offset", 0.0, 0, 1,
                     "The contact surface lies this far outside the mesh along its normal "
                     "(padding, an undergarment) (m).");
  prm.declare_selection(
      "Contact surface", "smooth", "smooth|faceted",
      "The surface the garment touches: smooth, the signed distance to blended osculating "
      "quadrics at the vertices (a C2 field whose gradient is the contact normal, so the "
      "contact force derives from an energy); faceted, the distance to the flat faces with the "
      "force along the interpolated vertex normals (docs/bodies.md).");
}

MeshBodySettings parse_mesh_body_settings(ParameterTree& prm) {
  MeshBodySettings s;
  s.file = prm.get_file_name("File");
  if (s.file.empty()) throw std::invalid_argument("File: no body mesh file given");
  s.options.import.metres_per_unit = prm.get_double("Unit scale");
  if (!(s.options.import.metres_per_unit > 0))
    throw std::invalid_argument("Unit scale must be positive (m per unit)");
  s.options.import.up_axis = prm.get("Up axis");
  s.options.import.rotation_deg = prm.get_vector("Rotation");
  s.options.import.translation_m = prm.get_vector("Translation");
  s.options.import.allow_open_surface = prm.get_bool("Accept open surface");
  s.options.skin_offset_m = prm.get_double("Skin offset");
  s.options.contact_surface = prm.get("Contact surface") == "faceted"
                                  ? MeshBodyOptions::ContactSurface::faceted
                                  : MeshBodyOptions::ContactSurface::smooth;
  return s;
}

PartEntry<BodyMaker> mesh_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "mesh";
  e.subsection = "Mesh";
  e.description = "a rigid body read from a closed surface mesh file (OBJ, STL, PLY).";
  e.declare_parameters = declare_mesh_body_settings;
  e.parse = [](ParameterTree& prm) -> BodyMaker {
    const MeshBodySettings s = parse_mesh_body_settings(prm);
    return [=](const Garment&) -> std::unique_ptr<ScenarioBody> {
      std::unique_ptr<MeshBody> body = load_mesh_body(s.file, s.options);
      // A body a thousand times too large (millimetres read as metres) or lying down (the
      // wrong up axis) stops here, before any placement or solve (docs/bodies.md).
      check_body_size(body_extent(body->surface().vertices_m),
                      "Body/Mesh: body mesh '" + s.file + "'");
      return std::make_unique<MeshScenarioBody>(std::move(body), s.file);
    };
  };
  return e;
}

}  // namespace tightfit
