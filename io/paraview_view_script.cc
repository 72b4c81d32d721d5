#include "io/paraview_view_script.h"

#include "core/units.h"
#include "paraview_view_code.h"  // generated from io/paraview_view.py

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace tightfit {

namespace {

// A Python string literal holding `text` (any bytes; quotes, backslashes and control
// characters escaped).
std::string python_string(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\\' || c == '\'') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(c));
      quoted += escaped;
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

// A Python float literal (a decimal point even for whole numbers).
std::string python_float(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%.12g", x);
  std::string s = text;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string python_vector(const Vec3& v) {
  return "(" + python_float(v.x()) + ", " + python_float(v.y()) + ", " + python_float(v.z()) + ")";
}

}  // namespace

std::string paraview_view_script(const ViewScriptSettings& s,
                                 const std::string& written_to_directory) {
  const Vec3 d = s.view_direction;
  if (!(d.norm() > 0)) throw std::invalid_argument("view script: the view direction is zero");
  if (!(d.cross(s.view_up).norm() > 1e-9 * d.norm() * s.view_up.norm()))
    throw std::invalid_argument("view script: the up direction is zero or along the view");
  const auto py_bool = [](bool b) { return b ? "True" : "False"; };
  std::string text =
      "# The ParaView view of a tightfit run (docs/reading-output.md): the garment and the body\n"
      "# coloured by pressure, the load steps as time, the angular profile of a cylinder case.\n"
      "#   pvpython view.py                      an interactive window\n"
      "#   pvpython view.py --screenshot v.png   a picture\n"
      "#   paraview --script=view.py             in ParaView's window; or in a running ParaView:\n"
      "#                                         View > Python Shell > Run Script, this file\n"
      "# Written by tightfit with its run; the settings below are what the run knows.\n"
      "SETTINGS = {\n";
  text += "    'title': " + python_string(s.title) + ",\n";
  text += "    'garment': " + python_string(s.garment_series) + ",\n";
  text += "    'body': " + python_string(s.body_series) + ",\n";
  text += std::string("    'body_has_pressure': ") + py_bool(s.body_has_pressure) + ",\n";
  text += std::string("    'in_mmHg': ") + py_bool(s.in_mmHg) + ",\n";
  text +=
      "    'angular_profile': " +
      (s.angular_profile_csv.empty() ? std::string("None") : python_string(s.angular_profile_csv)) +
      ",\n";
  text += "    'view_direction': " + python_vector(d.normalized()) + ",\n";
  text += "    'view_up': " + python_vector(s.view_up.normalized()) + ",\n";
  text += "    'pascal_per_mmHg': " + python_float(units::pascal_per_mmHg) + ",\n";
  text += "    'written_to': " + python_string(written_to_directory) + ",\n";
  text += "}\n";
  return text + paraview_view_code;
}

void write_paraview_view_script(const std::string& path, const ViewScriptSettings& settings) {
  namespace fs = std::filesystem;
  std::error_code error;
  fs::path folder = fs::absolute(fs::path(path).parent_path(), error);
  const std::string text = paraview_view_script(settings, folder.lexically_normal().string());
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw std::runtime_error("cannot write the view script '" + path + "'");
}

}  // namespace tightfit
