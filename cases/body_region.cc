#include "cases/body_region.h"
#include "core/closest_names.h"
#include "core/number_text.h"
#include "core/plain_text.h"

#include <cmath>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace tightfit {

bool RegionShape::contains(const Vec3& x) const {
  switch (kind) {
    case Kind::slab: {
      const double height = a.dot(x);
      return height >= low && height <= high;
    }
    case Kind::box:
      return (x.array() >= a.array()).all() && (x.array() <= b.array()).all();
    case Kind::ball:
      return (x - a).squaredNorm() <= low * low;
    case Kind::tube: {
      const Vec3 d = x - a;
      const double along = b.dot(d);
      return along >= tube_low && along <= tube_high && (d - along * b).squaredNorm() <= low * low;
    }
    case Kind::named:
      throw std::logic_error("region shape '" + text + "' is used before the body resolved it");
  }
  return false;
}

bool BodyRegion::contains(const Vec3& x) const {
  for (const RegionShape& s : shapes)
    if (s.contains(x)) return true;
  return false;
}

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(trimmed(part));
  return parts;
}

double number(const std::string& word, const std::string& what) {
  const std::optional<double> value = whole_number(word);
  if (!value) throw std::invalid_argument(what + " '" + word + "' is not a number");
  return *value;
}

Vec3 vector3(const std::string& word, const std::string& what) {
  const std::vector<std::string> parts = split(word, ',');
  if (parts.size() != 3)
    throw std::invalid_argument(what + " '" + word + "' is not three numbers x,y,z");
  return Vec3(number(parts[0], what), number(parts[1], what), number(parts[2], what));
}

Vec3 slab_axis(const std::string& word) {
  if (word == "x") return Vec3::UnitX();
  if (word == "y") return Vec3::UnitY();
  if (word == "z") return Vec3::UnitZ();
  const Vec3 axis = vector3(word, "the axis");
  if (!(axis.norm() > 0)) throw std::invalid_argument("the axis '" + word + "' is zero");
  return axis.normalized();
}

std::string format(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string known_shapes() {
  std::string list = "slab, box, ball";
  for (const std::string& n : anatomical_region_names()) list += ", " + n;
  return list;
}

// "; did you mean 'waist band'?" for a shape whose first words are close to a known one
// ("waist bnd front", "bst", "slb z 0 1"): of the names near the first one, two or three words,
// the one fewest edits away.
std::string closest_shape(const std::vector<std::string>& words) {
  std::vector<std::string> known{"slab", "box", "ball"};
  for (const std::string& n : anatomical_region_names()) known.push_back(n);
  std::string best, leading;
  std::size_t fewest = std::string::npos;
  for (std::size_t n = 0; n < words.size() && n < 3; ++n) {
    leading += (n == 0 ? "" : " ") + words[n];
    for (const std::string& name : closest_names(leading, known)) {
      const std::size_t edits = edit_distance(leading, name);
      if (edits < fewest) fewest = edits, best = name;
    }
  }
  return best.empty() ? "" : "; did you mean '" + best + "'?";
}

// "under-bust band front 0.04", "B left": the longest known name the words start with, then a
// side, a facing and a width, each optional.
RegionShape parse_named_shape(const std::vector<std::string>& words, const std::string& text) {
  RegionShape s;
  s.kind = RegionShape::Kind::named;
  s.text = text;
  std::size_t used = 0;
  for (const std::string& name : anatomical_region_names()) {
    std::istringstream in(name);
    std::size_t n = 0;
    bool match = true;
    for (std::string w; in >> w; ++n)
      if (n >= words.size() || words[n] != w) match = false;
    if (match && n > used) {
      used = n;
      s.named.name = name;
    }
  }
  if (used == 0)
    throw std::invalid_argument("unknown shape '" + words.front() + "' (known: " + known_shapes() +
                                ")" + closest_shape(words));
  for (std::size_t i = used; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (w == "left" || w == "right") {
      s.named.side = w == "left" ? 0 : 1;
    } else if (w == "front" || w == "back") {
      s.named.facing = w == "front" ? 1 : -1;
    } else if (!whole_number(w)) {
      throw std::invalid_argument("'" + w + "' after '" + s.named.name +
                                  "' is neither a side (left, right), a facing (front, back) nor a "
                                  "width in m" +
                                  did_you_mean(w, {"left", "right", "front", "back"}, 0));
    } else {
      s.named.width_m = number(w, "the width");
      if (!(s.named.width_m > 0))
        throw std::invalid_argument("the width " + w + " m is not positive");
    }
  }
  return s;
}

// One shape from its words: "slab x 0.1 0.2", "box 0,0,0 1,1,1", "ball 0,0,0 0.1".
RegionShape parse_shape(const std::vector<std::string>& words, const std::string& text) {
  RegionShape s;
  s.text = text;
  const std::string& kind = words.front();
  const auto expect_words = [&](std::size_t n, const char* form) {
    if (words.size() != n) throw std::invalid_argument("expected '" + std::string(form) + "'");
  };
  if (kind == "slab") {
    expect_words(4, "slab AXIS LOW HIGH");
    s.kind = RegionShape::Kind::slab;
    s.a = slab_axis(words[1]);
    s.low = number(words[2], "the lower height");
    s.high = number(words[3], "the upper height");
    if (s.low > s.high)
      throw std::invalid_argument("the lower height " + format(s.low) +
                                  " m is above the upper height " + format(s.high) + " m");
    if (s.low == s.high)
      throw std::invalid_argument("the slab is empty: both heights are " + format(s.low) + " m");
  } else if (kind == "box") {
    expect_words(3, "box XMIN,YMIN,ZMIN XMAX,YMAX,ZMAX");
    s.kind = RegionShape::Kind::box;
    s.a = vector3(words[1], "the minimum corner");
    s.b = vector3(words[2], "the maximum corner");
    for (int i = 0; i < 3; ++i) {
      const std::string axis(1, "xyz"[i]);
      if (s.a[i] > s.b[i])
        throw std::invalid_argument("the minimum " + axis + " " + format(s.a[i]) +
                                    " m is above the maximum " + format(s.b[i]) + " m");
      if (s.a[i] == s.b[i])
        throw std::invalid_argument("the box is empty: its " + axis + " extent is zero");
    }
  } else if (kind == "ball") {
    expect_words(3, "ball X,Y,Z RADIUS");
    s.kind = RegionShape::Kind::ball;
    s.a = vector3(words[1], "the centre");
    s.low = number(words[2], "the radius");
    if (s.low < 0) throw std::invalid_argument("the radius " + format(s.low) + " m is negative");
    if (s.low == 0) throw std::invalid_argument("the ball is empty: its radius is zero");
  } else {
    return parse_named_shape(words, text);
  }
  return s;
}

}  // namespace

bool has_named_shapes(const std::vector<BodyRegion>& regions) {
  for (const BodyRegion& r : regions)
    for (const RegionShape& s : r.shapes)
      if (s.kind == RegionShape::Kind::named) return true;
  return false;
}

void resolve_named_regions(std::vector<BodyRegion>& regions, const BodyMeasurements& body) {
  for (BodyRegion& region : regions) {
    std::vector<RegionShape> shapes;
    for (const RegionShape& s : region.shapes) {
      if (s.kind != RegionShape::Kind::named) {
        shapes.push_back(s);
        continue;
      }
      std::vector<RegionPiece> pieces;
      try {
        pieces = anatomical_region(body, s.named);
      } catch (const std::exception& e) {
        throw BodyMeasureError("region '" + region.name + "', shape '" + s.text + "': " + e.what());
      }
      for (const RegionPiece& p : pieces) {
        RegionShape r;
        std::ostringstream text;
        text.precision(4);
        if (p.kind == RegionPiece::Kind::box) {
          r.kind = RegionShape::Kind::box;
          r.a = p.min_m;
          r.b = p.max_m;
          text << "box " << r.a.x() << "," << r.a.y() << "," << r.a.z() << " " << r.b.x() << ","
               << r.b.y() << "," << r.b.z();
        } else {
          r.kind = RegionShape::Kind::tube;
          r.a = p.point_m;
          r.b = p.axis.normalized();
          r.low = p.radius_m;
          r.tube_low = p.low_m;
          r.tube_high = p.high_m;
          text << "tube round " << r.a.x() << "," << r.a.y() << "," << r.a.z() << " along "
               << r.b.x() << "," << r.b.y() << "," << r.b.z() << " from " << r.tube_low << " to "
               << r.tube_high << " radius " << r.low;
        }
        r.text = s.text + " = " + text.str();
        shapes.push_back(r);
      }
    }
    region.shapes = std::move(shapes);
  }
}

std::vector<BodyRegion> parse_body_regions(const std::string& definitions) {
  // "0.1, 0, 0.5" reads as one word "0.1,0,0.5".
  const std::string text = std::regex_replace(definitions, std::regex("\\s*,\\s*"), ",");
  std::vector<BodyRegion> regions;
  for (const std::string& definition : split(text, ';')) {
    if (definition.empty()) continue;
    const auto colon = definition.find(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("'" + definition + "': expected 'NAME: SHAPE [+ SHAPE ...]'");
    BodyRegion region;
    region.name = trimmed(definition.substr(0, colon));
    const std::string where = "region '" + region.name + "'";
    if (region.name.empty())
      throw std::invalid_argument("'" + definition + "': the region has no name");
    for (const BodyRegion& other : regions)
      if (other.name == region.name) throw std::invalid_argument(where + " is defined twice");
    // Shapes are separated by a '+' standing alone (so 1e+3 stays a number).
    std::istringstream words(definition.substr(colon + 1));
    std::vector<std::vector<std::string>> shapes(1);
    for (std::string word; words >> word;) {
      if (word == "+")
        shapes.emplace_back();
      else
        shapes.back().push_back(word);
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      std::string shape_text;
      for (const std::string& w : shapes[i]) shape_text += (shape_text.empty() ? "" : " ") + w;
      if (shapes[i].empty())
        throw std::invalid_argument(where + ": shape " + std::to_string(i + 1) +
                                    " is missing (the region is empty)");
      try {
        region.shapes.push_back(parse_shape(shapes[i], shape_text));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(where + ", shape '" + shape_text + "': " + e.what());
      }
    }
    regions.push_back(std::move(region));
  }
  if (regions.empty()) throw std::invalid_argument("no region defined");
  return regions;
}

}  // namespace tightfit
