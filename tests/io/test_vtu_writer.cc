// VTU files read back with VTK's own reader: every named array, its values, the field data.
#include "bodies/cylinder.h"
#include "io/vtu_writer.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <Eigen/Geometry>

#include <cmath>
#include <set>

namespace tightfit {
namespace {

using VtuWriter = ScratchDir;

// The reader is returned so that the grid it owns stays alive.
vtkSmartPointer<vtkXMLUnstructuredGridReader> read_vtu(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader;
}

// A 10 cm square cut in two triangles, stretched 1.2 along x and 0.9 along y, then rotated and
// moved: its principal stretches are 1.2 and 0.9 at every vertex whatever the rigid motion.
struct StretchedSquare {
  SimulationMesh mesh;
  SurfaceState state;
  PressureField field;
  Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();

  StretchedSquare() {
    const std::vector<Vec2> rest = {{0, 0}, {0.1, 0}, {0.1, 0.1}, {0, 0.1}};
    mesh.n_vertices = 4;
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.triangle_panel = {0, 0};
    for (const Triangle& t : mesh.triangles)
      mesh.rest_triangles.push_back({rest[t[0]], rest[t[1]], rest[t[2]]});
    for (const Vec2& X : rest)
      state.positions_m.push_back(rotation * Vec3(1.2 * X.x(), 0.9 * X.y(), 0.0) +
                                  Vec3(0.3, -0.1, 0.05));
    state.internal_force_N = {{1, 2, 3}, {-4, 5, 6}, {7, -8, 9}, {0.1, 0.2, -0.3}};
    state.contact_force_N = {{-1, -2, -3}, {4, -5, -6}, {0, 0, 0}, {0, 0, 0}};
    state.in_contact = {1, 1, 0, 0};
    state.gap_m = {-1e-4, -2e-4, 3e-3, 4e-3};
    field.area_definition = VertexAreaDefinition::adjacent_triangles;
    field.pressure_Pa = {1500.25, 1234.5, -7.0, 0.0};
    field.normal_force_N = {0.01, 0.02, -0.003, 0.0};
    field.vertex_area_m2 = {1e-4, 2e-4, 3e-4, 4e-4};
    field.normal.assign(4, rotation * Vec3::UnitZ());
    field.contact = {1, 1, 0, 0};
  }

  PrincipalStretches stretches() const {
    return vertex_principal_stretches(mesh, state.positions_m);
  }
};

void expect_scalars(vtkUnstructuredGrid* grid, const char* name, const std::vector<double>& want) {
  vtkDataArray* array = grid->GetPointData()->GetArray(name);
  ASSERT_NE(array, nullptr) << name;
  ASSERT_EQ(array->GetNumberOfComponents(), 1) << name;
  ASSERT_EQ(array->GetNumberOfTuples(), vtkIdType(want.size())) << name;
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_DOUBLE_EQ(array->GetTuple1(i), want[i]) << name << "[" << i << "]";
}

void expect_vectors(vtkUnstructuredGrid* grid, const char* name, const std::vector<Vec3>& want) {
  vtkDataArray* array = grid->GetPointData()->GetArray(name);
  ASSERT_NE(array, nullptr) << name;
  ASSERT_EQ(array->GetNumberOfComponents(), 3) << name;
  ASSERT_EQ(array->GetNumberOfTuples(), vtkIdType(want.size())) << name;
  for (std::size_t i = 0; i < want.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_DOUBLE_EQ(array->GetComponent(i, c), want[i][c]) << name << "[" << i << "]";
}

TEST_F(VtuWriter, GarmentFileHoldsEveryNamedArrayWithItsValues) {
  const StretchedSquare s;
  const std::string file = path("garment_0003.vtu");
  write_garment_vtu(file, s.mesh, s.state, s.field, s.stretches(), 1.35);

  auto reader = read_vtu(file);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), 4);
  for (int v = 0; v < 4; ++v) {
    double x[3];
    grid->GetPoint(v, x);
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(x[c], s.state.positions_m[v][c]);
  }
  ASSERT_EQ(grid->GetNumberOfCells(), 2);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(grid->GetCellType(k), VTK_TRIANGLE);
    vtkCell* cell = grid->GetCell(k);
    ASSERT_EQ(cell->GetNumberOfPoints(), 3);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(cell->GetPointId(i), s.mesh.triangles[k][i]);
  }

  std::set<std::string> names;
  for (int i = 0; i < grid->GetPointData()->GetNumberOfArrays(); ++i)
    names.insert(grid->GetPointData()->GetArrayName(i));
  EXPECT_EQ(names, (std::set<std::string>{"pressure_Pa", "normal_force_N", "vertex_area_m2",
                                          "contact", "normal", "stretch_max", "stretch_min",
                                          "internal_force_N", "contact_force_N", "gap_m"}));

  expect_scalars(grid, "pressure_Pa", s.field.pressure_Pa);
  expect_scalars(grid, "normal_force_N", s.field.normal_force_N);
  expect_scalars(grid, "vertex_area_m2", s.field.vertex_area_m2);
  expect_scalars(grid, "gap_m", s.state.gap_m);
  expect_vectors(grid, "normal", s.field.normal);
  expect_vectors(grid, "internal_force_N", s.state.internal_force_N);
  expect_vectors(grid, "contact_force_N", s.state.contact_force_N);

  vtkDataArray* contact = grid->GetPointData()->GetArray("contact");
  ASSERT_NE(contact, nullptr);
  EXPECT_EQ(contact->GetDataType(), VTK_UNSIGNED_CHAR);
  expect_scalars(grid, "contact", {1, 1, 0, 0});

  // The stretches handed to the writer come from the deformation itself: 1.2 and 0.9
  // everywhere.
  vtkDataArray* largest = grid->GetPointData()->GetArray("stretch_max");
  vtkDataArray* smallest = grid->GetPointData()->GetArray("stretch_min");
  ASSERT_NE(largest, nullptr);
  ASSERT_NE(smallest, nullptr);
  for (int v = 0; v < 4; ++v) {
    EXPECT_NEAR(largest->GetTuple1(v), 1.2, 1e-12);
    EXPECT_NEAR(smallest->GetTuple1(v), 0.9, 1e-12);
  }

  auto* definition = vtkStringArray::SafeDownCast(
      grid->GetFieldData()->GetAbstractArray("vertex_area_definition"));
  ASSERT_NE(definition, nullptr);
  ASSERT_EQ(definition->GetNumberOfValues(), 1);
  EXPECT_EQ(definition->GetValue(0), "adjacent triangles");
  vtkDataArray* alpha = grid->GetFieldData()->GetArray("alpha");
  ASSERT_NE(alpha, nullptr);
  EXPECT_DOUBLE_EQ(alpha->GetTuple1(0), 1.35);
}

TEST_F(VtuWriter, DataIsBinaryAppendedAndCompressed) {
  const StretchedSquare s;
  const std::string file = path("garment.vtu");
  write_garment_vtu(file, s.mesh, s.state, s.field, s.stretches(), 1.0);
  const std::string text = read_text(file);
  EXPECT_NE(text.find("format=\"appended\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
}

TEST_F(VtuWriter, CallerArraysAreWrittenBesideTheStandardOnes) {
  const StretchedSquare s;
  SurfaceVtu vtu = garment_vtu(s.mesh, s.state, s.field, s.stretches(), 1.8);
  const std::vector<double> difference = {0.5, -0.25, 1e-9, -3e7};
  const std::vector<Vec3> traction = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1.5, -2.5, 3.5}};
  vtu.add_point_scalar("pressure_difference_Pa", difference);
  vtu.add_point_vector("contact_traction_Pa", traction);
  vtu.add_field_string("backend", "fem");
  const std::string file = path("garment.vtu");
  vtu.write(file);

  auto reader = read_vtu(file);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  expect_scalars(grid, "pressure_difference_Pa", difference);
  expect_vectors(grid, "contact_traction_Pa", traction);
  expect_scalars(grid, "pressure_Pa", s.field.pressure_Pa);
  auto* backend = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("backend"));
  ASSERT_NE(backend, nullptr);
  EXPECT_EQ(backend->GetValue(0), "fem");
}

TEST_F(VtuWriter, StateWithoutOptionalVectorsWritesTheRest) {
  StretchedSquare s;
  s.state.internal_force_N.clear();
  s.state.contact_force_N.clear();
  s.state.gap_m.clear();
  const std::string file = path("garment.vtu");
  write_garment_vtu(file, s.mesh, s.state, s.field, s.stretches(), 1.0);
  auto reader = read_vtu(file);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  EXPECT_EQ(grid->GetPointData()->GetArray("gap_m"), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetArray("contact_force_N"), nullptr);
  expect_scalars(grid, "pressure_Pa", s.field.pressure_Pa);
}

TEST_F(VtuWriter, StretchesAreWrittenOnlyWhenHanded) {
  const StretchedSquare s;
  const std::string file = path("garment.vtu");
  write_garment_vtu(file, s.mesh, s.state, s.field, PrincipalStretches{}, 1.0);
  auto reader = read_vtu(file);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  EXPECT_EQ(grid->GetPointData()->GetArray("stretch_max"), nullptr);
  EXPECT_EQ(grid->GetPointData()->GetArray("stretch_min"), nullptr);
  expect_scalars(grid, "pressure_Pa", s.field.pressure_Pa);
  // Handed stretches of another size are refused, as every other array.
  const PrincipalStretches short_list(3, {1.0, 1.0});
  EXPECT_THROW(garment_vtu(s.mesh, s.state, s.field, short_list, 1.0), std::invalid_argument);
}

TEST(SurfaceVtu, RejectsWrongSizesRepeatedNamesAndBadTriangles) {
  SurfaceVtu vtu({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()}, {{0, 1, 2}});
  EXPECT_THROW(vtu.add_point_scalar("a", {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(vtu.add_point_vector("b", {Vec3::Zero()}), std::invalid_argument);
  vtu.add_point_scalar("a", {1.0, 2.0, 3.0});
  EXPECT_THROW(vtu.add_point_vector("a", {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}),
               std::invalid_argument);
  EXPECT_THROW(vtu.add_field_scalar("a", 1.0), std::invalid_argument);
  EXPECT_THROW(SurfaceVtu({Vec3::Zero()}, {{0, 1, 2}}), std::invalid_argument);
}

TEST(SurfaceVtu, UnwritablePathThrowsNamingIt) {
  SurfaceVtu vtu({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()}, {{0, 1, 2}});
  const std::string bad = "/nonexistent_tightfit_dir/out.vtu";
  vtkObject::GlobalWarningDisplayOff();  // VTK's own complaint is expected here
  try {
    vtu.write(bad);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
  vtkObject::GlobalWarningDisplayOn();
}

TEST_F(VtuWriter, BodyFileHoldsTheDisplaySurface) {
  const Vec3 axis = Vec3(0, 1, 1).normalized();
  const Cylinder cylinder(Vec3(0.01, 0.02, 0.03), axis, 0.07);
  const DisplayMesh body = cylinder.display_mesh();
  const std::string file = path("body_0001.vtu");
  write_body_vtu(file, body);

  auto reader = read_vtu(file);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), vtkIdType(body.vertices_m.size()));
  ASSERT_EQ(grid->GetNumberOfCells(), vtkIdType(body.triangles.size()));
  EXPECT_EQ(grid->GetPointData()->GetNumberOfArrays(), 0);
  for (vtkIdType v = 0; v < grid->GetNumberOfPoints(); ++v) {
    double x[3];
    grid->GetPoint(v, x);
    // Every drawn point lies on the cylinder: 7 cm from the axis.
    const Vec3 d = Vec3(x[0], x[1], x[2]) - Vec3(0.01, 0.02, 0.03);
    EXPECT_NEAR((d - d.dot(axis) * axis).norm(), 0.07, 1e-12);
  }
  for (vtkIdType k = 0; k < grid->GetNumberOfCells(); ++k)
    EXPECT_EQ(grid->GetCellType(k), VTK_TRIANGLE);
}

}  // namespace
}  // namespace tightfit
