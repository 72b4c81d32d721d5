// Body/Kind = mesh: a rigid body given as a triangulated surface file (a scanned limb or
// torso). Its entries are declared so that case files can be written against them; the body
// itself is not built into this version yet, and choosing it stops with a message saying so.
#include "cases/parts/part_entries.h"

#include <stdexcept>

namespace tightfit {

PartEntry<BodyMaker> mesh_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "mesh";
  e.subsection = "Mesh";
  e.description = "a rigid body read from a surface mesh file (not built into this version yet).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_file_name("File", "", "The body's surface mesh (STL, OBJ, PLY or VTK/VTU).");
    prm.declare_double("Unit scale", 1.0, 0, ParameterTree::unbounded,
                       "Metres per unit of the file's coordinates (0.001 for millimetres) (-).");
    prm.declare_selection("Up axis", "z", "x|y|z|-x|-y|-z",
                          "The file's axis that points up; it is turned onto Protocol/Up.");
    prm.declare_vector("Rotation", "0,0,0",
                       "Rotation applied after the up axis is set: angles about x, y and z, in "
                       "that order (degrees).");
    prm.declare_vector("Translation", "0,0,0", "Translation applied last (m).");
    prm.declare_bool("Accept open surface", false,
                     "Accept a surface with boundary edges (a partial scan); inside and outside "
                     "are then those of the nearest triangle's normal.");
  };
  e.parse = [](ParameterTree&) -> BodyMaker {
    throw std::invalid_argument("Kind = mesh: this version of tightfit has no mesh body yet");
  };
  return e;
}

}  // namespace tightfit
