// The finite-element backend as the registry sees it (no deal.II here).
#pragma once

#include "core/backend_registry.h"

namespace tightfit {

// Name "fem"; declares and reads the "Finite elements" subsection (fem/fem_parameters.h).
BackendEntry fem_backend_entry();

}  // namespace tightfit
