#include "io/xml_file.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace tightfit {

namespace {

// The pieces are written by VTK in this machine's byte order; the headers say the same.
const char* host_byte_order() {
  const std::uint16_t one = 1;
  unsigned char first_byte;
  std::memcpy(&first_byte, &one, 1);
  return first_byte == 1 ? "LittleEndian" : "BigEndian";
}

}  // namespace

pugi::xml_node add_vtk_file_root(pugi::xml_document& document, const char* type,
                                 const char* version) {
  pugi::xml_node declaration = document.append_child(pugi::node_declaration);
  declaration.append_attribute("version") = "1.0";
  pugi::xml_node root = document.append_child("VTKFile");
  root.append_attribute("type") = type;
  root.append_attribute("version") = version;
  root.append_attribute("byte_order") = host_byte_order();
  return root;
}

void save_xml_in_one_step(const pugi::xml_document& document, const std::string& path,
                          const std::string& what) {
  const std::string temporary = path + ".tmp";
  if (!document.save_file(temporary.c_str(), "  ")) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + what + " '" + path + "'");
  }
  // rename() replaces the old file in one step.
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write " + what + " '" + path + "'");
  }
}

}  // namespace tightfit
