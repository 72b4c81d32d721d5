// VTK's XML reader; VTK stays inside this file.
#include "io/triangle_vtu_reader.h"

#include "io/vtk_reader_run.h"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace tightfit {
namespace {

std::runtime_error vtu_error(const std::string& path, const std::string& what) {
  return std::runtime_error("VTU file '" + path + "': " + what);
}

}  // namespace

TriangleGrid read_triangle_vtu(const std::string& path) {
  if (!std::ifstream(path)) throw vtu_error(path, "cannot open the file");
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  // CanReadFile looks for a VTKFile element of type UnstructuredGrid: anything else (another
  // VTK type, a .pvtu, not XML at all) is refused before the reader parses it.
  if (!reader->CanReadFile(path.c_str()))
    throw vtu_error(path, "not a VTK XML unstructured grid (.vtu) file");
  reader->SetFileName(path.c_str());
  const std::string messages = update_reader_quietly(*reader);
  if (!messages.empty()) throw vtu_error(path, "the VTU reader failed: " + messages);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  TriangleGrid result;
  result.points_m.resize(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw vtu_error(path, "point " + std::to_string(i) + " is not finite");
    result.points_m[i] = Vec3(p[0], p[1], p[2]);
  }
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    if (grid->GetCellType(c) != VTK_TRIANGLE)
      throw vtu_error(path, "cell " + std::to_string(c) + " is not a triangle (VTK type " +
                                std::to_string(grid->GetCellType(c)) + ")");
    grid->GetCellPoints(c, ids);
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const vtkIdType id = ids->GetId(k);
      if (id < 0 || id >= grid->GetNumberOfPoints())
        throw vtu_error(path, "cell " + std::to_string(c) + " names point " + std::to_string(id) +
                                  " of " + std::to_string(grid->GetNumberOfPoints()));
      t[k] = static_cast<int>(id);
    }
    result.triangles.push_back(t);
  }
  return result;
}

}  // namespace tightfit
