// The paper's protocol (Section 4.3): settle on the initial cylinder, then grow its radius.
#pragma once

#include <vector>

namespace tightfit {

// alpha of every load step: first the initial alpha (the garment settles there), then every
// multiple of `increment` above it up to `final_alpha` (included when it is a multiple, and
// appended otherwise). Throws std::invalid_argument when final < initial or increment <= 0.
std::vector<double> alpha_schedule(double initial_alpha, double final_alpha, double increment);

}  // namespace tightfit
