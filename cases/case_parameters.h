// Everything a case file (.prm) says, as plain structs. The deal.II ParameterHandler that
// reads them stays inside case_parameters.cc.
#pragma once

#include "core/backend.h"
#include "core/material.h"
#include "core/mesh_geometry.h"
#include "core/rectangle_panel.h"

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace tightfit {

struct GarmentSettings {
  std::string name = "4 5T";
  double panel_width_m = 0.1878;  // round the tube, along the weft
  double panel_height_m = 0.24;   // along the tube, the warp
  int n_panels = 2;
  MeshSpacing spacing;      // Edge length weft / warp
  double mesh_scale = 1.0;  // multiplies both edge lengths (convergence studies)
};

struct BodySettings {
  Vec3 axis_point_m = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double initial_radius_m = 0.05;  // the paper's cylinder (Table 3)
  double display_height_m = 0.24;
};

struct ProtocolSettings {
  EndCondition end_condition = EndCondition::free_ends;
  double final_alpha = 1.8;
  double alpha_increment = 0.05;
  bool gravity_while_settling = false;
  bool gravity_while_measuring = false;
  double gravity_m_per_s2 = 9.81;  // along -Body/Up
  Vec3 up = Vec3::UnitZ();
};

struct PressureSettings {
  VertexAreaDefinition vertex_area = VertexAreaDefinition::barycentric;
  int angle_bins = 36;
};

struct OutputSettings {
  std::string directory = "output";
  bool write_vtu = true;
  // False for a run that only wants the numbers back (no file at all).
  bool write_files = true;
  // This process among the MPI ranks of the run. Every rank holds the whole result: the first
  // alone writes the CSV tables, the body and the .pvd collections; with more than one rank
  // each writes its piece of the garment of every load step (a .pvtu of n_ranks pieces).
  int rank = 0;
  int n_ranks = 1;
  bool is_first_rank() const { return rank == 0; }
};

struct CaseParameters {
  GarmentSettings garment;
  std::string law = "linear biot";
  FabricParameters fabric;
  BodySettings body;
  double penalty_factor = 100.0;
  ProtocolSettings protocol;
  PressureSettings pressure;
  OutputSettings output;
  std::string backend = "massspring";
};

// A case file: every entry declared (with units, ranges and documentation, each backend's
// own subsection included), read from a .prm file with "Path/To/Entry=value" overrides.
// The only holder of deal.II's ParameterHandler, so its header stays in one translation unit.
class CaseFile {
 public:
  CaseFile();
  ~CaseFile();
  CaseFile(const CaseFile&) = delete;
  CaseFile& operator=(const CaseFile&) = delete;

  // Reads `path` and applies each override in turn. Throws std::runtime_error naming the
  // file, line or entry at fault (a missing file, an unknown entry, a value out of range).
  void read(const std::string& path, const std::vector<std::string>& overrides);
  // Applies one "Path/To/Entry=value" override.
  void set(const std::string& assignment);
  // The values now held, checked; throws std::invalid_argument naming the entry at fault.
  CaseParameters parameters() const;
  // Creates the backend called `name` from its subsection.
  std::unique_ptr<Backend> create_backend(const std::string& name, const Problem& problem) const;
  // Every entry with its documentation and default: as readable text, as a .prm file to
  // start a case from, or as JSON (with each entry's pattern: docs/parameters.md is made from it).
  enum class ParameterFormat { text, prm, json };
  void print(std::ostream& out, ParameterFormat format) const;

 private:
  std::unique_ptr<dealii::ParameterHandler> prm_;
};

}  // namespace tightfit
