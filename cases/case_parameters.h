// Everything a case file (.prm) says, as plain structs: the scenario's parts (garment, body,
// placement, constraints, load steps, measurements; docs/scenarios.md) and the solver's. The
// deal.II ParameterHandler that reads them stays inside case_parameters.cc.
#pragma once

#include "cases/measurement.h"
#include "cases/scenario_body.h"
#include "contact/pressure_extractor.h"
#include "core/backend.h"
#include "core/load_step.h"
#include "core/material.h"
#include "core/mesh_geometry.h"
#include "core/rectangle_panel.h"

#include <exception>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace tightfit {

class DeclaredParameters;

// What each scenario part's parser returns (cases/part_registry.h): its settings, ready to
// build the part. Plain functions, so that a case's parameters can be copied (a convergence
// study builds one scenario per mesh level).
// A garment cut to the body (Garment/Kind = limb tube) and the line it was cut along: the limb's
// axis through the tube's middle, `axis` unit and up the limb. Placement/Tube round axis/Axis =
// garment and Constraints/Held direction = axis follow it.
struct GarmentLine {
  Vec3 centre_m = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
};
struct GarmentOnBody {
  Garment garment;
  GarmentLine line;
};
// Most garments need only their own entries (`make`); a garment cut to the body's landmarks and
// girths is made after the body, from it (`make_on_body`), and the body must then not need the
// garment (a mesh body).
struct GarmentMaker {
  std::function<Garment(const std::string& name, const MeshSpacing& spacing)> make;
  std::function<GarmentOnBody(const std::string& name, const MeshSpacing& spacing,
                              const ScenarioBody& body)>
      make_on_body;

  GarmentMaker() = default;
  template <class Make,
            std::enable_if_t<
                std::is_invocable_r_v<Garment, const Make&, const std::string&, const MeshSpacing&>,
                int> = 0>
  GarmentMaker(Make m) : make(std::move(m)) {}  // NOLINT: a part's maker converts implicitly

  bool needs_body() const { return static_cast<bool>(make_on_body); }
  // The garment of a part that needs only its entries. Throws std::invalid_argument for one cut
  // to the body (made by make_scenario, or with make_case_body's body).
  Garment operator()(const std::string& name, const MeshSpacing& spacing) const;
};
using BodyMaker = std::function<std::unique_ptr<ScenarioBody>(const Garment& garment)>;
// The welded start positions of the garment on the scenario's body, m. A placement may fit the
// garment to the body first (Placement/Kind = arrangement's ease against the body: its
// pattern scaled round the body, the mesh welded again).
using PlacementMaker = std::function<std::vector<Vec3>(Scenario& scenario)>;
using MeasurementMaker = std::function<std::unique_ptr<Measurement>()>;

struct GarmentSettings {
  std::string kind = "tube";
  std::string name = "4 5T";
  MeshSpacing spacing;      // Edge length weft / warp
  double mesh_scale = 1.0;  // multiplies both edge lengths (convergence studies)
  GarmentMaker make;
};

struct BodySettings {
  std::string kind = "cylinder";
  BodyMaker make;
};

struct PlacementSettings {
  std::string kind = "tube round cylinder";
  PlacementMaker place;
};

// Constraints on the garment's named vertex groups (SimulationMesh::vertex_groups).
struct ConstraintSettings {
  std::vector<std::string> held_groups;  // held along held_direction
  // Unset: along the body's own axis (ScenarioBody::axis()).
  std::optional<Vec3> held_direction;
  std::vector<std::string> fixed_groups;
};

struct ProtocolSettings {
  double final_alpha = 1.8;  // the body's morph parameter at the last load step
  double alpha_increment = 0.05;
  bool gravity_while_settling = false;
  bool gravity_while_measuring = false;
  double gravity_m_per_s2 = 9.81;  // along -Up
  Vec3 up = Vec3::UnitZ();
};

struct PressureSettings {
  VertexAreaDefinition vertex_area = VertexAreaDefinition::barycentric;
  PressureDefinition definition = PressureDefinition::contact_traction;
};

struct NamedMeasurement {
  std::string kind;
  MeasurementMaker make;
};

struct OutputSettings {
  std::string directory = "output";
  bool write_vtu = true;
  // The body VTU carries the garment's pressure on a refined copy of the body's surface
  // (cases/body_surface_pressure.h), its edges at most body_edge_length_m (0: half the
  // garment's mean edge length).
  bool body_pressure = true;
  double body_edge_length_m = 0.0;
  // False for a run that only wants the numbers back (no file at all).
  bool write_files = true;
  // This process among the MPI ranks of the run. Every rank holds every step's scalars (the
  // per-vertex arrays only while the step is written, scenario_run.h): the first
  // alone writes the CSV tables and the .pvd collections, the last the body; with more than
  // one rank each writes its piece of the garment of every load step (a .pvtu of n_ranks
  // pieces).
  int rank = 0;
  int n_ranks = 1;
  bool is_first_rank() const { return rank == 0; }
  // With several ranks: reports an error that reached this rank alone (its piece of the
  // output cannot be written) and ends every rank, before unwinding this rank's solver
  // objects, whose destructors would wait for the others (MPI_Abort). Unset: the error is
  // thrown as usual.
  std::function<void(const std::string&)> end_every_rank;
  // Runs `write`, output of this rank alone: with several ranks an exception from it ends
  // every rank (end_every_rank) with its message; otherwise it is thrown on.
  template <typename Write>
  void on_this_rank(Write&& write) const {
    try {
      write();
    } catch (const std::exception& e) {
      if (n_ranks > 1 && end_every_rank) end_every_rank(e.what());
      throw;
    }
  }
};

struct CaseParameters {
  GarmentSettings garment;
  std::string law = "linear biot";
  FabricParameters fabric;
  BodySettings body;
  PlacementSettings placement;
  ConstraintSettings constraints;
  double penalty_factor = 100.0;
  double friction_coefficient = 0.0;      // Contact/Friction coefficient, mu
  double tangential_penalty_ratio = 1.0;  // Contact/Tangential penalty ratio, k_t / (k A0)
  ProtocolSettings protocol;
  PressureSettings pressure;
  std::vector<NamedMeasurement> measurements;
  OutputSettings output;
  std::string backend = "massspring";
  int threads = 0;  // Solver/Threads: 0 automatic (core/thread_count.h)
  // The stop rule and gap tolerance of either backend (Solver subsection).
  StopRule stop_rule;
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
  // file, line or entry at fault (a missing file, an unknown entry, a value out of range), with
  // the closest declared names for an unknown subsection, entry or selection value.
  void read(const std::string& path, const std::vector<std::string>& overrides);
  // Applies one "Path/To/Entry=value" override.
  void set(const std::string& assignment);
  // The values now held, checked; throws std::invalid_argument naming the entry at fault.
  CaseParameters parameters() const;
  // Creates the backend called `name` from its subsection. Throws std::invalid_argument when the
  // problem has friction and the backend does not apply it.
  std::unique_ptr<Backend> create_backend(const std::string& name, const Problem& problem) const;
  // Every entry with its documentation and default: as readable text, as a .prm file to
  // start a case from, or as JSON (with each entry's pattern: docs/parameters.md is made from it).
  enum class ParameterFormat { text, prm, json };
  void print(std::ostream& out, ParameterFormat format) const;

 private:
  std::unique_ptr<dealii::ParameterHandler> prm_;
  // Every subsection and entry as declared, for the messages that refuse an unknown name.
  std::unique_ptr<DeclaredParameters> declared_;
  // The folder of the case file read, where input files it names are also looked for.
  std::string case_directory_;
};

}  // namespace tightfit
