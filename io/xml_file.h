// The small XML files that tie VTK pieces together for ParaView (.pvd collections, .pvtu
// headers), written with pugixml so that names with quotes or ampersands are escaped by the
// library, not by hand.
#pragma once

#include <pugixml.hpp>

#include <string>

namespace tightfit {

// A document whose root is <VTKFile type="`type`" ...> with the attributes ParaView's readers
// expect (version, the byte order of this machine); returns the root.
pugi::xml_node add_vtk_file_root(pugi::xml_document& document, const char* type,
                                 const char* version);

// Saves `document` to `path` through a temporary file renamed over it, so a reader never sees
// half a file (a run stopped between two steps still opens). Throws std::runtime_error naming
// `what` and `path` when it cannot be written.
void save_xml_in_one_step(const pugi::xml_document& document, const std::string& path,
                          const std::string& what);

}  // namespace tightfit
