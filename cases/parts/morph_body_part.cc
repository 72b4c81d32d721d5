// Body/Kind = morph: a rigid body that changes between load steps from its mesh (Body/Mesh)
// towards a target mesh of the same connectivity, or by a schedule of scales. Its entries are
// declared so that case files can be written against them; the body itself is not built into
// this version yet, and choosing it stops with a message saying so.
#include "cases/parts/part_entries.h"

#include <stdexcept>

namespace tightfit {

PartEntry<BodyMaker> morph_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "morph";
  e.subsection = "Morph";
  e.description =
      "the mesh body (Body/Mesh) moved towards a target mesh or scaled as alpha grows (not "
      "built into this version yet).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_file_name("Target mesh", "",
                          "Surface mesh the body reaches at the last load step, with the same "
                          "vertices as Body/Mesh/File; empty to scale instead.");
    prm.declare_text("Scale schedule", "",
                     "Without a target mesh: comma-separated scale factors of the body about "
                     "its centroid, one per load step after settling (-); empty: alpha.");
  };
  e.parse = [](ParameterTree&) -> BodyMaker {
    throw std::invalid_argument("Kind = morph: this version of tightfit has no morphing body yet");
  };
  return e;
}

}  // namespace tightfit
