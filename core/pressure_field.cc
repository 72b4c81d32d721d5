#include "core/pressure_field.h"

namespace tightfit {

const char* to_string(PressureDefinition definition) {
  return definition == PressureDefinition::contact_traction ? "contact traction"
                                                            : "garment force (paper)";
}

}  // namespace tightfit
