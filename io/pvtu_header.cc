// SurfaceVtu::write_pvtu_header: the small XML file that makes pieces one dataset in ParaView.
#include "io/vtu_writer.h"
#include "io/xml_file.h"

namespace tightfit {

namespace {

void declare_array(pugi::xml_node parent, const char* type, const std::string& name,
                   int n_components) {
  pugi::xml_node array = parent.append_child("PDataArray");
  array.append_attribute("type") = type;
  array.append_attribute("Name") = name.c_str();
  array.append_attribute("NumberOfComponents") = n_components;
}

}  // namespace

void SurfaceVtu::write_pvtu_header(const std::string& path,
                                   const std::vector<std::string>& piece_files) const {
  pugi::xml_document document;
  pugi::xml_node root = add_vtk_file_root(document, "PUnstructuredGrid", "1.0");
  root.append_attribute("header_type") = "UInt64";
  pugi::xml_node grid = root.append_child("PUnstructuredGrid");
  grid.append_attribute("GhostLevel") = 0;
  // The types are those write() gives VTK: doubles as Float64, flags as UInt8.
  pugi::xml_node point_data = grid.append_child("PPointData");
  for (const PointArray& a : point_arrays_)
    declare_array(point_data, a.is_flag ? "UInt8" : "Float64", a.name, a.n_components);
  grid.append_child("PCellData");
  declare_array(grid.append_child("PPoints"), "Float64", "Points", 3);
  for (const std::string& file : piece_files)
    grid.append_child("Piece").append_attribute("Source") = file.c_str();
  save_xml_in_one_step(document, path, "PVTU file");
}

}  // namespace tightfit
