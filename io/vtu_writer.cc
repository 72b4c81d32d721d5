#include "io/vtu_writer.h"

#include "core/mesh_geometry.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>
#include <utility>

namespace tightfit {

SurfaceVtu::SurfaceVtu(std::vector<Vec3> points_m, std::vector<Triangle> triangles)
    : points_m_(std::move(points_m)), triangles_(std::move(triangles)) {
  const int n = static_cast<int>(points_m_.size());
  for (const Triangle& t : triangles_)
    for (int v : t)
      if (v < 0 || v >= n)
        throw std::invalid_argument("VTU output: a triangle refers to point " + std::to_string(v) +
                                    " of a surface with " + std::to_string(n) + " points");
}

void SurfaceVtu::check_new_name(const std::string& name) const {
  if (name.empty()) throw std::invalid_argument("VTU output: an array has no name");
  for (const PointArray& a : point_arrays_)
    if (a.name == name)
      throw std::invalid_argument("VTU output: point array '" + name + "' is added twice");
  for (const FieldValue& f : field_values_)
    if (f.name == name)
      throw std::invalid_argument("VTU output: field value '" + name + "' is added twice");
}

void SurfaceVtu::check_size(const std::string& name, std::size_t size) const {
  if (size != points_m_.size())
    throw std::invalid_argument("VTU output: point array '" + name + "' has " +
                                std::to_string(size) + " values for " +
                                std::to_string(points_m_.size()) + " points");
}

void SurfaceVtu::add_point_scalar(const std::string& name, const std::vector<double>& values) {
  check_new_name(name);
  check_size(name, values.size());
  point_arrays_.push_back({name, 1, false, values});
}

void SurfaceVtu::add_point_vector(const std::string& name, const std::vector<Vec3>& values) {
  check_new_name(name);
  check_size(name, values.size());
  PointArray array{name, 3, false, {}};
  array.values.reserve(3 * values.size());
  for (const Vec3& v : values) array.values.insert(array.values.end(), {v.x(), v.y(), v.z()});
  point_arrays_.push_back(std::move(array));
}

void SurfaceVtu::add_point_flag(const std::string& name, const std::vector<char>& values) {
  check_new_name(name);
  check_size(name, values.size());
  PointArray array{name, 1, true, {}};
  array.values.reserve(values.size());
  for (char c : values) array.values.push_back(c ? 1.0 : 0.0);
  point_arrays_.push_back(std::move(array));
}

void SurfaceVtu::add_field_scalar(const std::string& name, double value) {
  check_new_name(name);
  field_values_.push_back({name, false, value, {}});
}

void SurfaceVtu::add_field_string(const std::string& name, const std::string& value) {
  check_new_name(name);
  field_values_.push_back({name, true, 0.0, value});
}

namespace {

vtkSmartPointer<vtkUnstructuredGrid> make_grid(const std::vector<Vec3>& points_m,
                                               const std::vector<Triangle>& triangles) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(points_m.size()));
  for (std::size_t v = 0; v < points_m.size(); ++v)
    points->SetPoint(static_cast<vtkIdType>(v), points_m[v].x(), points_m[v].y(), points_m[v].z());
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(triangles.size()),
                       3 * static_cast<vtkIdType>(triangles.size()));
  for (const Triangle& t : triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    cells->InsertNextCell(3, ids);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(VTK_TRIANGLE, cells);
  return grid;
}

void write_grid(const std::string& path, vtkUnstructuredGrid* grid) {
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(grid);
  // Raw binary appended data is the smallest and fastest form ParaView reads.
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1 || writer->GetErrorCode() != 0)
    throw std::runtime_error("cannot write VTU file '" + path + "'");
}

}  // namespace

void SurfaceVtu::write(const std::string& path) const {
  auto grid = make_grid(points_m_, triangles_);
  const vtkIdType n = static_cast<vtkIdType>(points_m_.size());
  for (const PointArray& a : point_arrays_) {
    if (a.is_flag) {
      vtkNew<vtkUnsignedCharArray> array;
      array->SetName(a.name.c_str());
      array->SetNumberOfTuples(n);
      for (vtkIdType v = 0; v < n; ++v) array->SetValue(v, a.values[v] != 0.0 ? 1 : 0);
      grid->GetPointData()->AddArray(array);
    } else {
      vtkNew<vtkDoubleArray> array;
      array->SetName(a.name.c_str());
      array->SetNumberOfComponents(a.n_components);
      array->SetNumberOfTuples(n);
      for (vtkIdType i = 0; i < n * a.n_components; ++i) array->SetValue(i, a.values[i]);
      grid->GetPointData()->AddArray(array);
    }
  }
  for (const FieldValue& f : field_values_) {
    if (f.is_string) {
      vtkNew<vtkStringArray> array;
      array->SetName(f.name.c_str());
      array->InsertNextValue(f.text);
      grid->GetFieldData()->AddArray(array);
    } else {
      vtkNew<vtkDoubleArray> array;
      array->SetName(f.name.c_str());
      array->InsertNextValue(f.number);
      grid->GetFieldData()->AddArray(array);
    }
  }
  write_grid(path, grid);
}

SurfaceVtu garment_vtu(const SimulationMesh& mesh, const SurfaceState& state,
                       const PressureField& field, const PrincipalStretches& stretches,
                       double alpha) {
  if (static_cast<int>(state.size()) != mesh.n_vertices)
    throw std::invalid_argument("VTU output: the surface state has " +
                                std::to_string(state.size()) + " vertices, the mesh " +
                                std::to_string(mesh.n_vertices));
  SurfaceVtu vtu(state.positions_m, mesh.triangles);
  vtu.add_point_scalar("pressure_Pa", field.pressure_Pa);
  vtu.add_point_scalar("normal_force_N", field.normal_force_N);
  if (!field.friction_traction_Pa.empty())
    vtu.add_point_scalar("friction_traction_Pa", field.friction_traction_Pa);
  vtu.add_point_scalar("vertex_area_m2", field.vertex_area_m2);
  vtu.add_point_flag("contact", field.contact);
  vtu.add_point_vector("normal", field.normal);

  if (!stretches.empty()) {
    std::vector<double> largest, smallest;
    largest.reserve(stretches.size());
    smallest.reserve(stretches.size());
    for (const auto& s : stretches) {
      largest.push_back(s[0]);
      smallest.push_back(s[1]);
    }
    vtu.add_point_scalar("stretch_max", largest);
    vtu.add_point_scalar("stretch_min", smallest);
  }

  // A backend that does not compute a quantity leaves its vector empty.
  if (!state.internal_force_N.empty())
    vtu.add_point_vector("internal_force_N", state.internal_force_N);
  if (!state.contact_force_N.empty())
    vtu.add_point_vector("contact_force_N", state.contact_force_N);
  if (!state.gap_m.empty()) vtu.add_point_scalar("gap_m", state.gap_m);

  vtu.add_field_string("vertex_area_definition", to_string(field.area_definition));
  vtu.add_field_scalar("alpha", alpha);
  return vtu;
}

void write_garment_vtu(const std::string& path, const SimulationMesh& mesh,
                       const SurfaceState& state, const PressureField& field,
                       const PrincipalStretches& stretches, double alpha) {
  garment_vtu(mesh, state, field, stretches, alpha).write(path);
}

void write_body_vtu(const std::string& path, const DisplayMesh& body) {
  SurfaceVtu(body.vertices_m, body.triangles).write(path);
}

}  // namespace tightfit
