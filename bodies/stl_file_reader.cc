#include "bodies/stl_file_reader.h"

#include "bodies/body_mesh_error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <unordered_map>
#include <vector>

namespace tightfit {
namespace {

using Corner = std::array<float, 3>;

// The facets' corners welded into vertices: equal single-precision coordinates are one vertex
// (0 and -0 alike, as VTK's point merging compared them with ==), numbered as they first
// appear, keeping the first one's coordinates. A corner with a NaN coordinate equals nothing and
// stays a vertex of its own, refused after reading.
class CornerWelder {
 public:
  explicit CornerWelder(std::size_t facets) { index_.reserve(facets); }

  // A facet whose corners weld onto fewer than three vertices has no area: dropped, as VTK's
  // reader dropped it (its corners still count as vertices).
  void add_facet(const Corner (&corners)[3]) {
    const int a = vertex(corners[0]), b = vertex(corners[1]), c = vertex(corners[2]);
    if (a != b && a != c && b != c) mesh_.faces.push_back({a, b, c});
  }
  PolygonMesh take() { return std::move(mesh_); }

 private:
  struct KeyHash {
    std::size_t operator()(const std::array<std::uint32_t, 3>& k) const {
      return (std::size_t(k[0]) * 73856093u) ^ (std::size_t(k[1]) * 19349663u) ^
             (std::size_t(k[2]) * 83492791u);
    }
  };

  int vertex(const Corner& x) {
    const int next = static_cast<int>(mesh_.vertices.size());
    bool has_nan = false;
    std::array<std::uint32_t, 3> key;
    for (int k = 0; k < 3; ++k) {
      has_nan = has_nan || std::isnan(x[k]);
      const float positive_zero = x[k] + 0.0f;  // -0 + 0 is +0 when rounding to nearest
      std::memcpy(&key[k], &positive_zero, sizeof(float));
    }
    if (!has_nan) {
      const auto [found, added] = index_.try_emplace(key, next);
      if (!added) return found->second;
    }
    mesh_.vertices.emplace_back(x[0], x[1], x[2]);
    return next;
  }

  PolygonMesh mesh_;
  std::unordered_map<std::array<std::uint32_t, 3>, int, KeyHash> index_;
};

// Printable text, tabs, line feeds and carriage returns: an ASCII STL; anything else binary,
// its facet count checked against its size. Not a form feed: VTK's reader took a file with one
// for binary (found by fuzz_body_mesh_stl: a text file announcing 168 million facets in bytes
// 80 to 83, 6 GB allocated), and so does this one, so that every file is read as it was there.
bool plain_text(const std::string& bytes) {
  return std::all_of(bytes.begin(), bytes.end(), [](unsigned char c) {
    return c == '\t' || c == '\n' || c == '\r' || (c >= 32 && c < 127);
  });
}

std::uint32_t little_endian_u32(const char* p) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = value << 8 | static_cast<unsigned char>(p[k]);
  return value;
}

float little_endian_float(const char* p) {
  const std::uint32_t bits = little_endian_u32(p);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// A binary STL: an 80-byte header, a facet count n and 50 bytes per facet (a normal and three
// corners, 12 floats, then 2 attribute bytes).
PolygonMesh read_binary(const std::string& path, const std::string& bytes) {
  if (bytes.size() < 84)
    throw BodyMeshError("body mesh '" + path + "': a binary STL of " +
                        std::to_string(bytes.size()) +
                        " bytes, shorter than its 84-byte header and facet count");
  const std::uint32_t count = little_endian_u32(bytes.data() + 80);
  const double needed = 84.0 + 50.0 * count;
  if (needed > static_cast<double>(bytes.size()))
    throw BodyMeshError("body mesh '" + path + "': truncated binary STL: the header announces " +
                        std::to_string(count) + " facets, " +
                        std::to_string(static_cast<long long>(needed)) + " bytes, the file has " +
                        std::to_string(bytes.size()));
  const std::size_t facets = (bytes.size() - 84) / 50;
  require_body_memory(path, (bytes.size() - 84) / 50.0, "facets");
  CornerWelder welder(facets);
  for (std::size_t f = 0; f < facets; ++f) {
    const char* record = bytes.data() + 84 + 50 * f;
    Corner corners[3];
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        corners[c][k] = little_endian_float(record + 12 * (c + 1) + 4 * k);
    welder.add_facet(corners);
  }
  return welder.take();
}

// The words of one line of an ASCII STL.
std::vector<std::string> words_of(const char* begin, const char* end) {
  std::vector<std::string> words;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (begin != end) {
    begin = std::find_if_not(begin, end, blank);
    const char* word_end = std::find_if(begin, end, blank);
    if (word_end != begin) words.emplace_back(begin, word_end);
    begin = word_end;
  }
  return words;
}

// A vertex line's coordinate: read in double precision and rounded to single, as VTK's reader
// read it (which differs from reading in single precision by one unit in the last place for a
// number next to the midpoint of two floats).
float coordinate(const std::string& path, int line, const std::string& word) {
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0')
    throw body_mesh_line_error(path, line, "'" + word + "' is not a number");
  if (!std::isfinite(value))
    throw body_mesh_line_error(path, line, "'" + word + "' is not a finite number");
  if (std::abs(value) > FLT_MAX)
    throw body_mesh_line_error(path, line,
                               "'" + word + "' is beyond single precision's largest number");
  return static_cast<float>(value);
}

// An ASCII STL: "solid NAME", facets ("facet normal ...", "outer loop", three "vertex X Y Z",
// "endloop", "endfacet"), "endsolid NAME"; more solids may follow. Keywords in any case.
PolygonMesh read_ascii(const std::string& path, const std::string& text) {
  // An ASCII facet takes at least about 100 bytes ("facet normal", a loop of 3 vertices).
  require_body_memory(path, text.size() / 100.0, "facets (ASCII STL)");
  enum class Next { solid, facet, outer_loop, vertex, endloop, endfacet };
  const char* const expected[] = {
      "solid", "facet' or 'endsolid", "outer loop", "vertex", "endloop", "endfacet"};
  Next next = Next::solid;
  CornerWelder welder(text.size() / 100);
  Corner corners[3];
  int corner = 0;
  int line = 0;
  int facet_line = 0;
  for (const char* at = text.data(); at != text.data() + text.size();) {
    const char* line_end = std::find(at, text.data() + text.size(), '\n');
    const std::vector<std::string> words = words_of(at, line_end);
    at = line_end == text.data() + text.size() ? line_end : line_end + 1;
    ++line;
    if (words.empty()) continue;
    std::string keyword = words[0];
    std::transform(keyword.begin(), keyword.end(), keyword.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    const auto out_of_order = [&] {
      return body_mesh_line_error(path, line,
                                  "expected '" + std::string(expected[int(next)]) + "', found '" +
                                      words[0] + "' (an ASCII STL)");
    };
    switch (next) {
      case Next::solid:
        if (keyword != "solid") throw out_of_order();
        next = Next::facet;
        break;
      case Next::facet:
        if (keyword == "color") break;  // a colour between facets, not read
        if (keyword == "endsolid")
          next = Next::solid;
        else if (keyword == "facet") {
          next = Next::outer_loop;
          facet_line = line;
        } else
          throw out_of_order();
        break;
      case Next::outer_loop:
        if (keyword != "outer") throw out_of_order();
        next = Next::vertex;
        break;
      case Next::vertex:
        if (keyword != "vertex") throw out_of_order();
        if (words.size() != 4)
          throw body_mesh_line_error(path, line,
                                     "a vertex line holds three coordinates, this one " +
                                         std::to_string(words.size() - 1));
        for (int k = 0; k < 3; ++k) corners[corner][k] = coordinate(path, line, words[k + 1]);
        if (++corner == 3) {
          corner = 0;
          welder.add_facet(corners);
          next = Next::endloop;
        }
        break;
      case Next::endloop:
        if (keyword != "endloop") throw out_of_order();
        next = Next::endfacet;
        break;
      case Next::endfacet:
        if (keyword != "endfacet") throw out_of_order();
        next = Next::facet;
        break;
    }
  }
  if (next != Next::solid)
    throw body_mesh_line_error(path, line,
                               next == Next::facet
                                   ? std::string("the file ends before 'endsolid'")
                                   : "the file ends inside the facet begun on line " +
                                         std::to_string(facet_line) + ", before '" +
                                         expected[int(next)] + "'");
  return welder.take();
}

}  // namespace

PolygonMesh read_stl_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return plain_text(bytes) ? read_ascii(path, bytes) : read_binary(path, bytes);
}

}  // namespace tightfit
