// The case file as the scenario parts (cases/parts/) see it: typed, range-checked entries in
// nested subsections, declared and read through this interface so that a part's file needs no
// deal.II header. The one implementation wraps deal.II's ParameterHandler in
// case_parameters.cc.
#pragma once

#include "core/types.h"

#include <limits>
#include <string>
#include <vector>

namespace tightfit {

class ParameterTree {
 public:
  virtual ~ParameterTree() = default;
  virtual void enter_subsection(const std::string& name) = 0;
  virtual void leave_subsection() = 0;

  // Declarations: name, default, allowed values, documentation (with units).
  virtual void declare_double(const std::string& name, double default_value, double min, double max,
                              const std::string& documentation) = 0;
  virtual void declare_integer(const std::string& name, int default_value, int min, int max,
                               const std::string& documentation) = 0;
  virtual void declare_bool(const std::string& name, bool default_value,
                            const std::string& documentation) = 0;
  // One of `options`, separated by '|'.
  virtual void declare_selection(const std::string& name, const std::string& default_value,
                                 const std::string& options, const std::string& documentation) = 0;
  // A comma-separated list of `options` (separated by '|'), possibly empty.
  virtual void declare_multiple_selection(const std::string& name, const std::string& default_value,
                                          const std::string& options,
                                          const std::string& documentation) = 0;
  // Three comma-separated numbers.
  virtual void declare_vector(const std::string& name, const std::string& default_value,
                              const std::string& documentation) = 0;
  // Free text: a name, or a comma-separated list of words.
  virtual void declare_text(const std::string& name, const std::string& default_value,
                            const std::string& documentation) = 0;
  // A path to an input file.
  virtual void declare_file_name(const std::string& name, const std::string& default_value,
                                 const std::string& documentation) = 0;

  // Values of the entries declared above.
  virtual std::string get(const std::string& name) = 0;
  virtual double get_double(const std::string& name) = 0;
  virtual int get_integer(const std::string& name) = 0;
  virtual bool get_bool(const std::string& name) = 0;
  Vec3 get_vector(const std::string& name);
  // A file_name entry (or a text entry naming an input file) as a path that exists: relative
  // paths from the working directory, else from the case file's folder
  // (cases/input_file_path.h). "" stays "". Throws std::invalid_argument naming the paths tried.
  std::string get_file_name(const std::string& name);
  // The comma-separated words of a text or multiple-selection entry, blanks trimmed, empty
  // words dropped.
  std::vector<std::string> get_list(const std::string& name);

  static constexpr double unbounded = std::numeric_limits<double>::max();

  // The folder of the case file being read; empty when the entries come from no file.
  std::string case_directory;
};

// Enters a subsection for the lifetime of the object.
class Subsection {
 public:
  Subsection(ParameterTree& tree, const std::string& name) : tree_(tree) {
    tree_.enter_subsection(name);
  }
  ~Subsection() { tree_.leave_subsection(); }
  Subsection(const Subsection&) = delete;
  Subsection& operator=(const Subsection&) = delete;

 private:
  ParameterTree& tree_;
};

}  // namespace tightfit
