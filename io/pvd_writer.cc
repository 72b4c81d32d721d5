#include "io/pvd_writer.h"

#include "io/xml_file.h"

#include <cstdio>
#include <utility>

namespace tightfit {

namespace {

std::string time_text(double time) {
  // 17 significant digits: the time read back is the double written.
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", time);
  return buffer;
}

}  // namespace

PvdWriter::PvdWriter(std::string path) : path_(std::move(path)) {
  rewrite();
}

void PvdWriter::add(double time, const std::string& file, int part) {
  entries_.push_back({time, file, part});
  rewrite();
}

void PvdWriter::rewrite() const {
  pugi::xml_document document;
  pugi::xml_node collection =
      add_vtk_file_root(document, "Collection", "0.1").append_child("Collection");
  for (const Entry& e : entries_) {
    pugi::xml_node data_set = collection.append_child("DataSet");
    data_set.append_attribute("timestep") = time_text(e.time).c_str();
    data_set.append_attribute("group") = "";
    data_set.append_attribute("part") = e.part;
    data_set.append_attribute("file") = e.file.c_str();
  }
  save_xml_in_one_step(document, path_, "ParaView collection");
}

}  // namespace tightfit
