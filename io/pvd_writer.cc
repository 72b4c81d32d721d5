#include "io/pvd_writer.h"

#include "io/xml_text.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>
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
  const std::string temporary = path_ + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write ParaView collection '" + path_ + "'");
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const Entry& e : entries_)
      out << "    <DataSet timestep=\"" << time_text(e.time) << "\" group=\"\" part=\"" << e.part
          << "\" file=\"" << xml_escaped(e.file) << "\"/>\n";
    out << "  </Collection>\n"
        << "</VTKFile>\n";
    out.close();
    if (!out) throw std::runtime_error("cannot write ParaView collection '" + path_ + "'");
  }
  // rename() replaces the old file in one step: a reader never sees half a collection.
  if (std::rename(temporary.c_str(), path_.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write ParaView collection '" + path_ + "'");
  }
}

}  // namespace tightfit
