// Parallel garment output: a surface split into pieces plus the .pvtu header, read back with
// VTK's own parallel reader, must be the unsplit surface read back with the serial reader,
// cell by cell (a point shared by two pieces is in both).
#include "io/vtu_share.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace tightfit {
namespace {

using VtuShare = ScratchDir;

// A 4 x 3 grid of squares, each cut in two triangles, bent out of its plane, with arrays of
// every kind SurfaceVtu writes: scalars, 3-vectors, 0/1 flags and field data.
struct BentGrid {
  static constexpr int nx = 4, ny = 3;
  std::vector<Vec3> points_m;
  std::vector<Triangle> triangles;
  std::vector<double> pressure_Pa, traction_Pa;
  std::vector<Vec3> force_N;
  std::vector<char> contact;

  BentGrid() {
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double x = 0.01 * i, y = 0.02 * j;
        points_m.emplace_back(x, y, 0.003 * std::sin(40.0 * x) * std::cos(25.0 * y));
      }
    const auto id = [](int i, int j) { return j * (nx + 1) + i; };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    for (std::size_t v = 0; v < points_m.size(); ++v) {
      pressure_Pa.push_back(1000.0 + 12.5 * v);
      traction_Pa.push_back(-0.25 * v * v);
      force_N.emplace_back(0.1 * v, -0.2 * v, 1.0 / (1.0 + v));
      contact.push_back(v % 3 == 0);
    }
  }

  SurfaceVtu surface() const {
    SurfaceVtu vtu(points_m, triangles);
    vtu.add_point_scalar("pressure_Pa", pressure_Pa);
    vtu.add_point_vector("contact_force_N", force_N);
    vtu.add_point_flag("contact", contact);
    vtu.add_point_scalar("contact_traction_Pa", traction_Pa);  // as a backend adds it
    vtu.add_field_scalar("alpha", 1.35);
    vtu.add_field_string("vertex_area_definition", "barycentric");
    return vtu;
  }
};

template <typename Reader>
vtkSmartPointer<Reader> read(const std::string& path) {
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader;
}

// Every cell of `split` has the corners of the same cell of `whole`: the same coordinates and
// the same values in every point array, which have the same names, types and components.
void expect_same_surface(vtkUnstructuredGrid* whole, vtkUnstructuredGrid* split) {
  vtkPointData* whole_data = whole->GetPointData();
  vtkPointData* split_data = split->GetPointData();
  ASSERT_EQ(split_data->GetNumberOfArrays(), whole_data->GetNumberOfArrays());
  for (int a = 0; a < whole_data->GetNumberOfArrays(); ++a) {
    vtkDataArray* w = whole_data->GetArray(a);
    vtkDataArray* s = split_data->GetArray(w->GetName());
    ASSERT_NE(s, nullptr) << w->GetName();
    EXPECT_EQ(s->GetDataType(), w->GetDataType()) << w->GetName();
    EXPECT_EQ(s->GetNumberOfComponents(), w->GetNumberOfComponents()) << w->GetName();
  }
  ASSERT_EQ(split->GetNumberOfCells(), whole->GetNumberOfCells());
  for (vtkIdType k = 0; k < whole->GetNumberOfCells(); ++k) {
    ASSERT_EQ(split->GetCellType(k), VTK_TRIANGLE);
    vtkCell* w_cell = whole->GetCell(k);
    vtkCell* s_cell = split->GetCell(k);
    ASSERT_EQ(s_cell->GetNumberOfPoints(), 3);
    for (int i = 0; i < 3; ++i) {
      const vtkIdType w = w_cell->GetPointId(i), s = s_cell->GetPointId(i);
      double xw[3], xs[3];
      whole->GetPoint(w, xw);
      split->GetPoint(s, xs);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(xs[c], xw[c]) << "cell " << k << " corner " << i;
      for (int a = 0; a < whole_data->GetNumberOfArrays(); ++a) {
        vtkDataArray* wa = whole_data->GetArray(a);
        vtkDataArray* sa = split_data->GetArray(wa->GetName());
        for (int c = 0; c < wa->GetNumberOfComponents(); ++c)
          EXPECT_EQ(sa->GetComponent(s, c), wa->GetComponent(w, c))
              << wa->GetName() << " at cell " << k << " corner " << i;
      }
    }
  }
}

// Points a block of triangles uses, counted straight from the triangles.
std::size_t points_used(const std::vector<Triangle>& triangles, TriangleBlock block) {
  std::set<int> used;
  for (std::size_t k = block.first; k < block.end; ++k)
    used.insert(triangles[k].begin(), triangles[k].end());
  return used.size();
}

TEST(TriangleBlock, BlocksCoverEveryTriangleOnceInOrderAndDifferByAtMostOne) {
  for (std::size_t n : {0, 1, 7, 24, 1397})
    for (int n_pieces : {1, 2, 3, 5, 30}) {
      std::size_t expected_first = 0, smallest = n, largest = 0;
      for (int p = 0; p < n_pieces; ++p) {
        const TriangleBlock block = triangle_block(n, p, n_pieces);
        EXPECT_EQ(block.first, expected_first) << n << " triangles, piece " << p;
        ASSERT_LE(block.first, block.end);
        smallest = std::min(smallest, block.end - block.first);
        largest = std::max(largest, block.end - block.first);
        expected_first = block.end;
      }
      EXPECT_EQ(expected_first, n) << n << " triangles in " << n_pieces << " pieces";
      EXPECT_LE(largest - smallest, 1u);
    }
  EXPECT_THROW(triangle_block(10, 2, 2), std::invalid_argument);
  EXPECT_THROW(triangle_block(10, -1, 2), std::invalid_argument);
  EXPECT_THROW(triangle_block(10, 0, 0), std::invalid_argument);
}

TEST_F(VtuShare, OneWriterWritesAPlainVtu) {
  const SurfaceVtu surface = BentGrid().surface();
  EXPECT_EQ(write_vtu_share(surface, dir_.string(), "garment_0002", 0, 1), "garment_0002.vtu");
  EXPECT_TRUE(std::filesystem::exists(path("garment_0002.vtu")));
  EXPECT_FALSE(std::filesystem::exists(path("garment_0002.pvtu")));
  EXPECT_FALSE(std::filesystem::exists(path("garment_0002_0.vtu")));
}

TEST_F(VtuShare, PiecesReadBackAsTheWholeSurface) {
  const BentGrid grid;
  const SurfaceVtu surface = grid.surface();
  surface.write(path("whole.vtu"));
  const int n_writers = 3;
  // Writer 0 goes last here, as a slow first rank would; any order gives the same files.
  for (int writer = n_writers - 1; writer >= 0; --writer)
    EXPECT_EQ(write_vtu_share(surface, dir_.string(), "garment_0007", writer, n_writers),
              "garment_0007.pvtu");
  std::size_t total_points = 0;
  for (int p = 0; p < n_writers; ++p) {
    const std::string piece = path("garment_0007_" + std::to_string(p) + ".vtu");
    ASSERT_TRUE(std::filesystem::exists(piece)) << piece;
    const TriangleBlock block = triangle_block(grid.triangles.size(), p, n_writers);
    auto reader = read<vtkXMLUnstructuredGridReader>(piece);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), vtkIdType(block.end - block.first));
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(),
              vtkIdType(points_used(grid.triangles, block)));
    total_points += points_used(grid.triangles, block);
  }
  // Shared points are repeated, so the split surface has more points than the whole.
  EXPECT_GT(total_points, grid.points_m.size());

  auto whole = read<vtkXMLUnstructuredGridReader>(path("whole.vtu"));
  auto split = read<vtkXMLPUnstructuredGridReader>(path("garment_0007.pvtu"));
  EXPECT_EQ(split->GetOutput()->GetNumberOfPoints(), vtkIdType(total_points));
  EXPECT_EQ(split->GetOutput()->GetNumberOfCells(), vtkIdType(grid.triangles.size()));
  expect_same_surface(whole->GetOutput(), split->GetOutput());
  // The field data travels in every piece; the parallel reader passes it on.
  vtkDataArray* alpha = split->GetOutput()->GetFieldData()->GetArray("alpha");
  ASSERT_NE(alpha, nullptr);
  EXPECT_EQ(alpha->GetTuple1(0), 1.35);
}

TEST_F(VtuShare, MoreWritersThanTrianglesLeavesEmptyPiecesThatStillRead) {
  SurfaceVtu surface({Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), Vec3(1, 1, 0.5)},
                     {{0, 1, 2}, {1, 3, 2}});
  surface.add_point_scalar("pressure_Pa", {1, 2, 3, 4});
  surface.write(path("whole.vtu"));
  for (int writer = 0; writer < 5; ++writer)
    write_vtu_share(surface, dir_.string(), "step", writer, 5);
  auto whole = read<vtkXMLUnstructuredGridReader>(path("whole.vtu"));
  auto split = read<vtkXMLPUnstructuredGridReader>(path("step.pvtu"));
  EXPECT_EQ(split->GetOutput()->GetNumberOfPoints(), 6);
  expect_same_surface(whole->GetOutput(), split->GetOutput());
}

TEST_F(VtuShare, HeaderNamesEveryPieceAndArray) {
  const SurfaceVtu surface = BentGrid().surface();
  surface.write_pvtu_header(path("a.pvtu"), {"a_0.vtu", "a_1.vtu"});
  const std::string text = read_text(path("a.pvtu"));
  EXPECT_NE(text.find("type=\"PUnstructuredGrid\""), std::string::npos);
  EXPECT_NE(text.find("<Piece Source=\"a_0.vtu\""), std::string::npos);
  EXPECT_NE(text.find("<Piece Source=\"a_1.vtu\""), std::string::npos);
  EXPECT_NE(text.find("type=\"UInt8\" Name=\"contact\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"contact_force_N\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path("a.pvtu.tmp")));
}

TEST(SurfaceVtuPiece, RangeOutsideTheSurfaceThrows) {
  const SurfaceVtu surface = BentGrid().surface();
  EXPECT_THROW(surface.piece(0, surface.n_triangles() + 1), std::invalid_argument);
  EXPECT_THROW(surface.piece(3, 2), std::invalid_argument);
  EXPECT_EQ(surface.piece(2, 2).n_points(), 0u);
  EXPECT_EQ(surface.piece(0, 1).n_points(), 3u);
}

}  // namespace
}  // namespace tightfit
