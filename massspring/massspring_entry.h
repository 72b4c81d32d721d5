// The mass-spring backend as the program's backend registry sees it (name "massspring").
// No deal.II here: backend_registry.h forward-declares the ParameterHandler.
#pragma once

#include "core/backend_registry.h"

namespace tightfit {

BackendEntry massspring_backend_entry();

}  // namespace tightfit
