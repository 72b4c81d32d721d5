// Small text helpers the file readers and their messages share.
#pragma once

#include "core/types.h"

#include <string>

namespace tightfit {

// `text` without the blanks (spaces, tabs, carriage returns, line feeds) at either end.
std::string trimmed(const std::string& text);

// A pattern-space point as "(x, y)" with six significant digits, for messages.
std::string point_text(const Vec2& x);

}  // namespace tightfit
