#include "body/body_report.h"

#include "io/csv_table.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace tightfit {

namespace {

std::string json_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string json_point(const Vec3& p) {
  return "[" + json_number(p.x()) + ", " + json_number(p.y()) + ", " + json_number(p.z()) + "]";
}

// Names hold letters, digits, spaces, '-' and '(': nothing to escape but quotes and
// backslashes, which do not occur; escaped all the same.
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::vector<TextTable> measurement_tables(const BodyMeasurements& m) {
  TextTable girths("Girths: the convex hull of the section, as a tape pulled tight",
                   {"girth", "tape [cm]", "section [cm]", "level above floor [cm]"});
  for (const BodyGirth& g : m.girths)
    girths.add_row({g.name, format_fixed(100 * g.girth_m, 1), format_fixed(100 * g.section_m, 1),
                    format_fixed(100 * g.level_m, 1)});
  TextTable lengths("Lengths", {"length", "[cm]"});
  for (const BodyLength& l : m.lengths)
    lengths.add_row({l.name, format_fixed(100 * l.length_m, 1)});
  TextTable landmarks(
      std::string("Landmarks (z up, front -y, left +x)") +
          (m.bust_points_present ? "" : "; no bust points (no hollow between breasts)"),
      {"landmark", "x [m]", "y [m]", "z [m]"});
  for (const BodyLandmark& l : m.landmarks)
    landmarks.add_row({l.name, format_fixed(l.point_m.x(), 4), format_fixed(l.point_m.y(), 4),
                       format_fixed(l.point_m.z(), 4)});
  TextTable parts("Body parts: the axis through the centroids of their sections",
                  {"part", "origin x,y,z [m]", "direction", "length [cm]"});
  for (const PartFrame& p : m.parts)
    parts.add_row({p.name,
                   format_fixed(p.origin_m.x(), 3) + ", " + format_fixed(p.origin_m.y(), 3) + ", " +
                       format_fixed(p.origin_m.z(), 3),
                   format_fixed(p.along.x(), 3) + ", " + format_fixed(p.along.y(), 3) + ", " +
                       format_fixed(p.along.z(), 3),
                   format_fixed(100 * p.length_m, 1)});
  return {girths, lengths, landmarks, parts};
}

void write_measurements_json(const std::string& path, const BodyMeasurements& m,
                             const std::string& source) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
  out << "{\n  \"body\": " << json_string(source) << ",\n  \"units\": \"m\",\n"
      << "  \"frame\": \"z up, front -y, left +x\",\n"
      << "  \"floor_z_m\": " << json_number(m.floor_m) << ",\n"
      << "  \"bust_points_present\": " << (m.bust_points_present ? "true" : "false") << ",\n"
      << "  \"girths\": {";
  for (std::size_t i = 0; i < m.girths.size(); ++i) {
    const BodyGirth& g = m.girths[i];
    out << (i ? "," : "") << "\n    " << json_string(g.name)
        << ": {\"girth_m\": " << json_number(g.girth_m)
        << ", \"section_m\": " << json_number(g.section_m)
        << ", \"level_m\": " << json_number(g.level_m)
        << ", \"centre_m\": " << json_point(g.centre_m) << ", \"normal\": " << json_point(g.normal)
        << "}";
  }
  out << "\n  },\n  \"lengths\": {";
  for (std::size_t i = 0; i < m.lengths.size(); ++i)
    out << (i ? "," : "") << "\n    " << json_string(m.lengths[i].name) << ": "
        << json_number(m.lengths[i].length_m);
  out << "\n  },\n  \"landmarks\": {";
  for (std::size_t i = 0; i < m.landmarks.size(); ++i)
    out << (i ? "," : "") << "\n    " << json_string(m.landmarks[i].name) << ": "
        << json_point(m.landmarks[i].point_m);
  out << "\n  },\n  \"parts\": {";
  for (std::size_t i = 0; i < m.parts.size(); ++i) {
    const PartFrame& p = m.parts[i];
    out << (i ? "," : "") << "\n    " << json_string(p.name)
        << ": {\"origin_m\": " << json_point(p.origin_m) << ", \"along\": " << json_point(p.along)
        << ", \"lateral\": " << json_point(p.lateral) << ", \"front\": " << json_point(p.front)
        << ", \"length_m\": " << json_number(p.length_m) << "}";
  }
  out << "\n  }\n}\n";
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
}

void write_measurements_csv(const std::string& path, const BodyMeasurements& m) {
  CsvTable csv(path, {"kind", "name", "value_m", "x_m", "y_m", "z_m"});
  for (const BodyGirth& g : m.girths)
    csv.write_row({"girth", g.name, g.girth_m, g.centre_m.x(), g.centre_m.y(), g.centre_m.z()});
  for (const BodyLength& l : m.lengths) csv.write_row({"length", l.name, l.length_m, "", "", ""});
  for (const BodyLandmark& l : m.landmarks)
    csv.write_row({"landmark", l.name, "", l.point_m.x(), l.point_m.y(), l.point_m.z()});
}

}  // namespace tightfit
