#pragma once
// Reading a number written in a parameter's text, a command-line option or a table cell: the
// whole text must be one finite number ("12", "-0.5", "1e-3"), so that "12 cm", "1,5" or "nan"
// are refused rather than read as 12, 1 or a NaN that passes every comparison.
#include <optional>
#include <string>

namespace tightfit {

// The number `text` spells in full, or nothing when it spells none (empty text, trailing
// characters, an overflow, infinity or NaN).
std::optional<double> whole_number(const std::string& text);

}  // namespace tightfit
