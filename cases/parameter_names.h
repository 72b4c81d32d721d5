// The names a case file may use, for messages that refuse a name it does not know: the
// subsections and entries declared in deal.II's ParameterHandler (read back from its ShortPRM
// print, so that this file needs no deal.II header) and the values of a selection. Each
// message names the closest known names (core/closest_names.h).
#pragma once

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace tightfit {

class DeclaredParameters {
 public:
  // `short_prm`: ParameterHandler::print_parameters(..., ShortPRM) of every declaration.
  explicit DeclaredParameters(std::istream& short_prm);

  // "" when the subsection at `path` declares `name`; otherwise why not, with the closest
  // known names: "Material has no entry 'Stifness'; did you mean 'Stiffness weft'?".
  std::string check_entry(const std::vector<std::string>& path, const std::string& name) const;
  std::string check_subsection(const std::vector<std::string>& path, const std::string& name) const;

  // The first subsection or entry of the case file that is not declared, as "line N: ...";
  // "" when every one is (or the file cannot be read).
  std::string first_unknown_name_in(const std::string& case_file) const;

 private:
  struct Level {
    std::vector<std::string> entries, subsections;
  };
  const Level* level(const std::vector<std::string>& path) const;
  std::map<std::string, Level> levels_;  // by path, "Garment/Tube"; "" the top level
};

// For a value deal.II's selection pattern refused (its description "[Selection a|b|c ]" or
// "[MultipleSelection a|b ]"), the first word that is not an option: "'c' is not one of 'a',
// 'b'; did you mean 'b'?"; "" for other patterns.
std::string selection_refusal(const std::string& value, const std::string& pattern_description);

}  // namespace tightfit
