// SurfaceVtu::write_pvtu_header: the small XML file that makes pieces one dataset in ParaView.
#include "io/vtu_writer.h"
#include "io/xml_text.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace tightfit {

namespace {

// The pieces are written by VTK in this machine's byte order; the header says the same.
const char* host_byte_order() {
  const std::uint16_t one = 1;
  unsigned char first_byte;
  std::memcpy(&first_byte, &one, 1);
  return first_byte == 1 ? "LittleEndian" : "BigEndian";
}

}  // namespace

void SurfaceVtu::write_pvtu_header(const std::string& path,
                                   const std::vector<std::string>& piece_files) const {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write PVTU file '" + path + "'");
    // The types are those write() gives VTK: doubles as Float64, flags as UInt8.
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"" << host_byte_order()
        << "\" header_type=\"UInt64\">\n"
        << "  <PUnstructuredGrid GhostLevel=\"0\">\n"
        << "    <PPointData>\n";
    for (const PointArray& a : point_arrays_)
      out << "      <PDataArray type=\"" << (a.is_flag ? "UInt8" : "Float64") << "\" Name=\""
          << xml_escaped(a.name) << "\" NumberOfComponents=\"" << a.n_components << "\"/>\n";
    out << "    </PPointData>\n"
        << "    <PCellData>\n"
        << "    </PCellData>\n"
        << "    <PPoints>\n"
        << "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
        << "    </PPoints>\n";
    for (const std::string& file : piece_files)
      out << "    <Piece Source=\"" << xml_escaped(file) << "\"/>\n";
    out << "  </PUnstructuredGrid>\n"
        << "</VTKFile>\n";
    out.close();
    if (!out) throw std::runtime_error("cannot write PVTU file '" + path + "'");
  }
  // rename() replaces an old header in one step, as for the .pvd collections.
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write PVTU file '" + path + "'");
  }
}

}  // namespace tightfit
