// Triangle surfaces as VTK XML unstructured grids (.vtu), for ParaView.
//
// A SurfaceVtu collects points, triangles, point-data arrays and field data, and writes them in
// one go (binary appended data, zlib-compressed). garment_vtu() fills one with the garment of a
// load step and its standard arrays; callers add their own arrays (a backend's contact
// traction, a cross-backend difference) before writing. The writer computes nothing: every
// array is a quantity it is handed.
#pragma once

#include "core/garment.h"
#include "core/mesh_geometry.h"
#include "core/pressure_field.h"
#include "core/surface_state.h"
#include "core/types.h"

#include <string>
#include <vector>

namespace tightfit {

class SurfaceVtu {
 public:
  // A surface of `points_m.size()` points; every triangle index must be a valid point index
  // (std::invalid_argument otherwise).
  SurfaceVtu(std::vector<Vec3> points_m, std::vector<Triangle> triangles);

  // Point-data arrays, one value per point. Each throws std::invalid_argument when the size
  // differs from the number of points or the name is already taken (ParaView would show only
  // one of two equal names).
  void add_point_scalar(const std::string& name, const std::vector<double>& values);
  void add_point_vector(const std::string& name, const std::vector<Vec3>& values);
  // 0/1 flags, stored as unsigned char.
  void add_point_flag(const std::string& name, const std::vector<char>& values);

  // Field data: values that describe the whole file.
  void add_field_scalar(const std::string& name, double value);
  void add_field_string(const std::string& name, const std::string& value);

  // Throws std::runtime_error naming `path` when it cannot be written.
  void write(const std::string& path) const;

  // The triangles [first_triangle, end_triangle) alone (std::invalid_argument when the range
  // is not within this surface), with the points they use, in the order of their index here,
  // every point array restricted to those points, and the same field data: one piece of a
  // parallel file. A point shared with triangles outside the range is in both pieces.
  SurfaceVtu piece(std::size_t first_triangle, std::size_t end_triangle) const;

  // The header of a parallel file (.pvtu, VTK's PUnstructuredGrid) whose pieces are
  // `piece_files` (relative to the header's folder), each written by write() from a piece()
  // of this surface: it declares this surface's point arrays with the same names, types and
  // component counts. Written through a temporary file renamed over `path`, so a reader never
  // sees half a header. Throws std::runtime_error naming `path` when it cannot be written.
  void write_pvtu_header(const std::string& path,
                         const std::vector<std::string>& piece_files) const;

  std::size_t n_points() const { return points_m_.size(); }
  std::size_t n_triangles() const { return triangles_.size(); }

 private:
  struct PointArray {
    std::string name;
    int n_components;            // 1 or 3
    bool is_flag;                // unsigned char instead of double
    std::vector<double> values;  // point-major: n_points * n_components
  };
  struct FieldValue {
    std::string name;
    bool is_string;
    double number;
    std::string text;
  };

  void check_new_name(const std::string& name) const;
  void check_size(const std::string& name, std::size_t size) const;

  std::vector<Vec3> points_m_;
  std::vector<Triangle> triangles_;
  std::vector<PointArray> point_arrays_;
  std::vector<FieldValue> field_values_;
};

// The garment of one load step: points are state.positions_m, cells mesh.triangles. Point data:
//   pressure_Pa, normal_force_N, friction_traction_Pa (tangential contact force / area),
//   vertex_area_m2, contact (0/1), normal (unit, away from the body)
//     from `field`;
//   stretch_max, stretch_min: from `stretches` (core's vertex_principal_stretches), unless
//     it is empty;
//   internal_force_N, contact_force_N (3-vectors), gap_m: from `state` when it holds them
//     (an empty vector is skipped, a vector of another size is an error).
// Field data: vertex_area_definition (to_string of field.area_definition) and alpha (the
// load step's r / R0).
SurfaceVtu garment_vtu(const SimulationMesh& mesh, const SurfaceState& state,
                       const PressureField& field, const PrincipalStretches& stretches,
                       double alpha);

// Shorthand for garment_vtu(...).write(path).
void write_garment_vtu(const std::string& path, const SimulationMesh& mesh,
                       const SurfaceState& state, const PressureField& field,
                       const PrincipalStretches& stretches, double alpha);

// A body's display surface, without arrays.
void write_body_vtu(const std::string& path, const DisplayMesh& body);

}  // namespace tightfit
