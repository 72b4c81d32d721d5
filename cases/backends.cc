// The backends built into tightfit, by name.
#include "core/backend_registry.h"
#include "fem/fem_entry.h"
#include "massspring/massspring_entry.h"

namespace tightfit {

const BackendRegistry& backend_registry() {
  static const BackendRegistry registry = [] {
    BackendRegistry r;
    r.add(massspring_backend_entry());
    r.add(fem_backend_entry());
    return r;
  }();
  return registry;
}

}  // namespace tightfit
