// Body/Kind = cone: a rigid circular cone (a limb that tapers). Its entries are declared so
// that case files can be written against them; the body itself is not built into this version
// yet, and choosing it stops with a message saying so.
#include "cases/parts/part_entries.h"

#include <stdexcept>

namespace tightfit {

PartEntry<BodyMaker> cone_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "cone";
  e.subsection = "Cone";
  e.description = "a rigid circular cone (not built into this version yet).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_vector("Axis point", "0,0,0", "A point on the cone's axis (m).");
    prm.declare_vector("Axis", "1,0,0", "Direction of the axis, towards the wider end (-).");
    prm.declare_double("Radius at axis point", 0.05, 0, ParameterTree::unbounded,
                       "Radius of the cone where its axis passes the axis point (m).");
    prm.declare_double("Half angle", 5, 0, 89,
                       "Angle between the cone's surface and its axis (degrees).");
    prm.declare_double("Display height", 0.24, 0, ParameterTree::unbounded,
                       "Length of cone drawn in the body's VTU (m).");
  };
  e.parse = [](ParameterTree&) -> BodyMaker {
    throw std::invalid_argument("Kind = cone: this version of tightfit has no cone body yet");
  };
  return e;
}

}  // namespace tightfit
