// A design file (docs/design.md): the case to design the garment of (a tapered tube on a limb)
// and what it is designed to, in its subsection Design. The file's one holder of deal.II's
// ParameterHandler, so its header stays in this translation unit.
#pragma once

#include "cases/design/design_target.h"
#include "cases/design/hoop_force.h"
#include "core/tapered_tube_garment.h"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace tightfit {

struct DesignSettings {
  std::string case_file;
  std::vector<NamedValue> points;  // as stated: name, height along the garment (m)
  DesignTarget target;
  double band_width_m = 0.02;
  double tolerance_mmHg = 0.5;
  int maximum_iterations = 6;
  HoopStrip hoop_strip = HoopStrip::free;
  double largest_strain = 1.0;  // the strain range of a law without a curve
  std::string check_backend;    // empty: none
  double check_tolerance_mmHg = 1.0;
  std::string output_directory = "output/design";
};

// The garment of the case as the design sees it: a tapered tube cut to the limb's girths.
struct LimbGarment {
  std::string kind;  // Garment/Kind: tapered tube or limb tube
  double length_m = 0.0;
  PiecewiseLinear girths_m;  // the limb's, at heights along the garment
  // A limb tube's: the measuring points the body's landmarks give on it, heights along it (m).
  std::vector<NamedValue> landmark_points;
};

class DesignFile {
 public:
  DesignFile();
  ~DesignFile();
  DesignFile(const DesignFile&) = delete;
  DesignFile& operator=(const DesignFile&) = delete;

  // Reads the design file; each override "Design/Entry=value" sets the design's own entries,
  // every other one is kept for the case (case_overrides(): Design/Case settings first, then
  // these). Throws std::runtime_error naming
  // the file, line or entry at fault.
  void read(const std::string& path, const std::vector<std::string>& overrides);
  // Throws std::invalid_argument naming the entry at fault.
  DesignSettings settings() const;
  const std::vector<std::string>& case_overrides() const { return case_overrides_; }
  // The case's garment, read from the case file and the case's overrides: Garment/Kind must be
  // tapered tube with a Negative ease, so that its Girths are the limb's, or limb tube (cut to
  // the body's leg: its girths and measuring points are found on the case's body). Throws
  // std::invalid_argument saying why otherwise, BodyMeasureError when the body's leg cannot be
  // measured.
  LimbGarment limb_garment() const;

  void print(std::ostream& out) const;

 private:
  struct Handler;
  std::unique_ptr<Handler> prm_;
  std::vector<std::string> case_overrides_;
  std::string path_;
};

}  // namespace tightfit
