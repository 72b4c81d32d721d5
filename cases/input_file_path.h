// Where an input file a case names (a body mesh, a pattern, a garment VTU) is found. A relative
// path is read from the working directory first, as a shell would, then from the case file's own
// folder, so that a case and its files can be run from anywhere (docs/cases.md).
#pragma once

#include <string>

namespace tightfit {

// `name` when it is absolute or names a file from the working directory; else the file of that
// name beside the case file (in `case_directory`, empty when the case came from no file).
// "" stays "". Throws std::invalid_argument "'name': cannot open the file; tried ..." naming
// every path tried when neither exists.
std::string resolve_input_file(const std::string& name, const std::string& case_directory);

}  // namespace tightfit
