#include "bodies/ply_file_reader.h"

#include "bodies/body_mesh_error.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

// VTK reads a line into a 4096-byte buffer and takes what does not fit for the next line.
constexpr std::size_t longest_line = 4000;

struct PlyType {
  int bytes = 0;  // 0: not a PLY type
  bool floating = false;
  bool is_signed = false;
};

PlyType type_named(const std::string& name) {
  static const std::map<std::string, PlyType> types = {
      {"char", {1, false, true}},    {"int8", {1, false, true}},    {"uchar", {1, false, false}},
      {"uint8", {1, false, false}},  {"short", {2, false, true}},   {"int16", {2, false, true}},
      {"ushort", {2, false, false}}, {"uint16", {2, false, false}}, {"int", {4, false, true}},
      {"int32", {4, false, true}},   {"uint", {4, false, false}},   {"uint32", {4, false, false}},
      {"float", {4, true, true}},    {"float32", {4, true, true}},  {"double", {8, true, true}},
      {"float64", {8, true, true}}};
  const auto it = types.find(name);
  return it == types.end() ? PlyType{} : it->second;
}

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType count;  // lists only
  PlyType value;
};

struct PlyElement {
  std::string name;
  long count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  std::string format;  // ascii, binary_little_endian or binary_big_endian
  std::vector<PlyElement> elements;
  long vertices = 0, faces = 0;
  int lines = 0;
};

bool is_face_indices(const PlyElement& element, const PlyProperty& property) {
  return element.name == "face" && property.name == "vertex_indices";
}

PlyHeader read_header(std::istream& in, const std::string& path) {
  PlyHeader header;
  std::string line;
  bool ended = false;
  while (!ended && std::getline(in, line)) {
    const int number = ++header.lines;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // VTK splits words at spaces and tabs only: "z\v" (found by fuzz_body_mesh_ply) names no
    // coordinate for VTK, which reports it, closes the file and reads on (a use after free).
    const bool control = std::any_of(line.begin(), line.end(), [](unsigned char c) {
      return (c < 32 && c != '\t') || c == 127;
    });
    if (line.size() > longest_line || control)
      throw body_mesh_line_error(path, number,
                                 "a header line longer than " + std::to_string(longest_line) +
                                     " characters or holding a control character");
    // VTK's reader renames "vertex_index" (some exporters' word) to "vertex_indices" and ends
    // the line there.
    const auto renamed = line.find("vertex_index");
    if (renamed != std::string::npos) line = line.substr(0, renamed) + "vertex_indices";
    std::istringstream words(line);
    std::string keyword, more;
    words >> keyword;
    if (number == 1 && keyword != "ply")
      throw body_mesh_line_error(path, 1, "not a PLY file: the first line is not 'ply'");
    if (keyword == "end_header") ended = true;
    // VTK's reader dereferences a null element on a header line it does not know (found by
    // fuzz_body_mesh_ply: "pr`perty float y").
    if (keyword != "ply" && keyword != "format" && keyword != "comment" && keyword != "obj_info" &&
        keyword != "element" && keyword != "property" && keyword != "end_header" &&
        !keyword.empty())
      throw body_mesh_line_error(path, number,
                                 "'" + keyword + "' is not a PLY header keyword: '" + line + "'");
    if ((keyword == "ply" && number > 1) || (keyword == "format" && !header.format.empty()))
      throw body_mesh_line_error(path, number, "a second '" + keyword + "' line: '" + line + "'");
    if (keyword == "format") {
      std::string version;
      words >> header.format >> version;
      if (version != "1.0")
        throw body_mesh_line_error(path, number, "the format's version is 1.0: '" + line + "'");
      if (header.format != "ascii" && header.format != "binary_little_endian" &&
          header.format != "binary_big_endian")
        throw body_mesh_line_error(path, number,
                                   "the format is ascii, binary_little_endian or "
                                   "binary_big_endian: '" +
                                       line + "'");
    }
    if (keyword == "element") {
      PlyElement element;
      if (!(words >> element.name >> element.count) || (words >> more))
        throw body_mesh_line_error(path, number,
                                   "an element is 'element NAME COUNT': '" + line + "'");
      if (element.count < 0)
        throw body_mesh_line_error(path, number, "a negative element count: '" + line + "'");
      if (element.count > INT_MAX)
        throw body_mesh_line_error(path, number, "more than 2^31 elements: '" + line + "'");
      for (const PlyElement& earlier : header.elements)
        if (earlier.name == element.name)
          throw body_mesh_line_error(path, number,
                                     "a second element '" + element.name + "': '" + line + "'");
      if (element.name == "vertex") header.vertices = element.count;
      if (element.name == "face") header.faces = element.count;
      header.elements.push_back(element);
    }
    if (keyword == "property") {
      // VTK's reader adds a property to the last element without checking there is one, and
      // takes the words it expects without counting them (found by fuzz_body_mesh_ply:
      // "property list uchar vertex_indices" read past the line).
      if (header.elements.empty())
        throw body_mesh_line_error(path, number, "a property before any element: '" + line + "'");
      PlyProperty property;
      std::string type, count_type;
      words >> type;
      property.list = type == "list";
      if (property.list) words >> count_type >> type;
      property.count = type_named(count_type);
      property.value = type_named(type);
      if (!(words >> property.name) || (words >> more) || property.value.bytes == 0 ||
          (property.list && (property.count.bytes == 0 || property.count.floating)))
        throw body_mesh_line_error(path, number,
                                   "a property is 'property TYPE NAME' or 'property list "
                                   "COUNT_TYPE INDEX_TYPE NAME' with known types (an integer "
                                   "count): '" +
                                       line + "'");
      header.elements.back().properties.push_back(property);
    }
  }
  if (!ended) throw body_mesh_line_error(path, header.lines, "the header has no end_header");
  if (header.format.empty())
    throw body_mesh_line_error(path, header.lines, "the header has no format line");
  return header;
}

// What VTK's reader needs of the elements: vertices with scalar x, y, z, faces with a list
// vertex_indices; every other property of the two a scalar (VTK reads colours, normals and
// texture coordinates by name into fixed fields); no other element before the two (VTK does
// not step over its data).
void check_elements(const PlyHeader& header, const std::string& path) {
  const auto refuse = [&](const std::string& message) {
    return BodyMeshError("body mesh '" + path + "': " + message);
  };
  std::size_t last_read = 0;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    // VTK allocates an element's property list with its first property and frees it when it
    // closes the file: with none it frees an address it never set (found by
    // fuzz_body_mesh_ply).
    if (element.properties.empty())
      throw refuse("the element '" + element.name + "' has no properties");
    if (element.name != "vertex" && element.name != "face") continue;
    last_read = e;
    for (const std::string coordinate : {"x", "y", "z"}) {
      if (element.name != "vertex") break;
      bool found = false;
      for (const PlyProperty& p : element.properties) found = found || p.name == coordinate;
      if (!found) throw refuse("the vertex element has no property '" + coordinate + "'");
    }
    bool indices = false;
    for (const PlyProperty& p : element.properties) {
      indices = indices || is_face_indices(element, p);
      if (p.list != is_face_indices(element, p) && p.name != "texcoord")
        throw refuse("the " + element.name + " property '" + p.name + "' " +
                     (p.list ? "is a list, VTK reads it as a number"
                             : "is a number, VTK reads it as a list"));
    }
    if (element.name == "face" && !indices)
      throw refuse("the face element has no list property 'vertex_indices'");
  }
  bool has_vertices = false;
  for (const PlyElement& element : header.elements)
    has_vertices = has_vertices || element.name == "vertex";
  // Without one VTK's reader reports it, closes the file and reads on.
  if (!has_vertices) throw refuse("no vertex element");
  for (std::size_t e = 0; e < last_read; ++e)
    if (header.elements[e].name != "vertex" && header.elements[e].name != "face")
      throw refuse("the element '" + header.elements[e].name +
                   "' comes before the vertices or faces; VTK's reader does not step over it");
}

// The data after the header, value by value, as VTK reads it: in ASCII the words of one line
// per element instance, in binary the bytes in the file's order.
class PlyValues {
 public:
  PlyValues(std::istream& in, const PlyHeader& header)
      : in_(in),
        ascii_(header.format == "ascii"),
        big_endian_(header.format == "binary_big_endian"),
        line_(header.lines) {}

  // Starts an element instance: reads its line (ASCII). False at the end of the file.
  bool start_instance() {
    if (!ascii_) return true;
    std::string text;
    if (!std::getline(in_, text)) return false;
    ++line_;
    if (text.size() > longest_line) {
      words_.clear();
      return true;  // read() then reports the line
    }
    // Words as VTK splits them: at spaces, tabs and carriage returns only.
    for (char& c : text)
      if (c == '\t' || c == '\r') c = ' ';
    words_.clear();
    std::istringstream split(text);
    for (std::string word; std::getline(split, word, ' ');)
      if (!word.empty()) words_.push_back(word);
    next_word_ = 0;
    return true;
  }

  // The next value of the instance; false when its line (ASCII) or the file (binary) ends
  // first, or when an ASCII word is not a number.
  bool read(const PlyType& type, double& value) {
    if (ascii_) {
      if (next_word_ >= words_.size()) return false;
      const std::string& word = words_[next_word_++];
      char* end = nullptr;
      value = std::strtod(word.c_str(), &end);
      return end != word.c_str() && *end == '\0';
    }
    unsigned char bytes[8];
    if (!in_.read(reinterpret_cast<char*>(bytes), type.bytes)) return false;
    std::uint64_t bits = 0;
    for (int k = 0; k < type.bytes; ++k)
      bits |= static_cast<std::uint64_t>(bytes[big_endian_ ? type.bytes - 1 - k : k]) << (8 * k);
    if (type.floating && type.bytes == 4) {
      float f;
      const auto b32 = static_cast<std::uint32_t>(bits);
      std::memcpy(&f, &b32, 4);
      value = f;
    } else if (type.floating) {
      std::memcpy(&value, &bits, 8);
    } else if (type.is_signed && (bits >> (8 * type.bytes - 1)) != 0) {
      value = static_cast<double>(bits) - std::ldexp(1.0, 8 * type.bytes);  // two's complement
    } else {
      value = static_cast<double>(bits);
    }
    return true;
  }

  bool ascii() const { return ascii_; }
  int line() const { return line_; }

 private:
  std::istream& in_;
  bool ascii_, big_endian_;
  int line_;
  std::vector<std::string> words_;
  std::size_t next_word_ = 0;
};

// 0, 1, 2 for the coordinates x, y, z; -1 for any other property.
int coordinate_axis(const std::string& name) {
  return name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
}

bool is_whole(double value) {
  return std::isfinite(value) && value == std::floor(value);
}

}  // namespace

PolygonMesh read_ply_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const PlyHeader header = read_header(in, path);
  check_elements(header, path);
  require_body_memory(path, static_cast<double>(header.faces), "faces announced");
  const std::string announced = "the header announces " + std::to_string(header.vertices) +
                                " vertices and " + std::to_string(header.faces) + " faces";
  PlyValues values(in, header);
  // Vertices and faces are stored as the file proves to hold them, never allocated for the
  // header's counts alone.
  PolygonMesh mesh;
  for (const PlyElement& element : header.elements) {
    const bool vertex = element.name == "vertex";
    for (long i = 0; i < element.count; ++i) {
      const std::string where = element.name + " " + std::to_string(i);
      const auto fault = [&](const std::string& message) {
        return values.ascii()
                   ? body_mesh_line_error(path, values.line(), where + ": " + message)
                   : BodyMeshError("body mesh '" + path + "': " + where + ": " + message);
      };
      const auto short_of_values = [&] {
        return values.ascii() ? fault(
                                    "fewer values than the element's properties, a word that "
                                    "is not a number or a line too long (" +
                                    announced + ")")
                              : BodyMeshError("body mesh '" + path + "': truncated: " + announced +
                                              ", the data ends in " + where);
      };
      if (!values.start_instance())
        throw BodyMeshError("body mesh '" + path + "': truncated: " + announced +
                            ", the file ends before " + where);
      if (vertex) mesh.vertices.push_back(Vec3::Zero());
      for (const PlyProperty& property : element.properties) {
        double value = 0;
        if (!property.list) {
          if (!values.read(property.value, value)) throw short_of_values();
          const int axis = !vertex ? -1 : coordinate_axis(property.name);
          if (axis < 0) continue;
          if (!std::isfinite(value))
            throw fault("the coordinate " + property.name + " is not a finite number");
          // VTK's reader kept coordinates in single precision: read as it did.
          mesh.vertices.back()[axis] = static_cast<double>(static_cast<float>(value));
          continue;
        }
        double count = 0;
        if (!values.read(property.count, count)) throw short_of_values();
        if (!is_whole(count) || count < 0)
          throw fault("a list of " + std::to_string(count) + " values");
        const bool indices = is_face_indices(element, property);
        // PolygonMesh holds triangles and quads; VTK copies a face into 256 slots.
        if (indices && (count < 3 || count > 4))
          throw fault("has " + std::to_string(static_cast<long>(count)) +
                      " vertices (triangles and quads only)");
        if (indices) mesh.faces.emplace_back();
        for (long k = 0; k < static_cast<long>(count); ++k) {
          if (!values.read(property.value, value)) throw short_of_values();
          if (!indices) continue;
          if (!is_whole(value) || value < 0 || value >= header.vertices) {
            std::ostringstream index;
            index << std::setprecision(17) << value;  // a whole index in full, not 1.7e+07
            throw fault("names vertex " + index.str() + " (counted from 0) of " +
                        std::to_string(header.vertices));
          }
          mesh.faces.back().push_back(static_cast<int>(value));
        }
      }
    }
  }
  return mesh;
}

}  // namespace tightfit
