// Text placed inside double-quoted XML attributes (file and array names in .pvd and .pvtu
// files) must not end the attribute or open a tag.
#pragma once

#include <string>

namespace tightfit {

// `text` with &, <, > and " replaced by their XML entities.
std::string xml_escaped(const std::string& text);

}  // namespace tightfit
