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

// A parameter entry whose default depends on the case (the settle's defaults on a faceted body
// mesh, docs/parameters.md): its text is "auto" (nothing: the caller's default for the case) or
// a whole number. Throws std::invalid_argument naming `entry` when it is neither.
std::optional<double> auto_or_number(const std::string& text, const std::string& entry);

// A count entry with an automatic choice (Solver/Threads, Contact set predictions): "auto"
// (nothing) or the digits of a whole number from 0 to `largest`. Throws std::invalid_argument
// naming `entry` for anything else ("-1", "2.5", "two", " 2").
std::optional<int> auto_or_count(const std::string& text, const std::string& entry, int largest);

}  // namespace tightfit
