#include "pattern/dxf_reader.h"

#include "core/plain_text.h"
#include "pattern/boundary_chain.h"
#include "pattern/bspline.h"

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace tightfit::pattern {

namespace {

struct RawPiece {
  std::string block, piece_name, size;
  std::vector<BoundaryRun> runs;  // the boundary's entities on layer 1, as written
  std::string problem;            // the first thing wrong with them, reported after reading
  std::vector<Vec2> turn_points, notches;
  std::optional<std::pair<Vec2, Vec2>> grain_line;
};

// A POLYLINE or LWPOLYLINE being read: its vertices (with bulges) until it ends.
struct OpenPolyline {
  std::vector<Vec2> points;
  std::vector<double> bulges;
  bool closed = false, finished = false;
};

// A SPLINE being read: its control points and knots until the entity ends.
struct OpenSpline {
  int degree = 0, flags = 0;
  std::vector<Vec2> points;
  std::vector<double> knots;
  int fit_points = 0;
  bool rational = false;
};

// "KEY: value" -> value when `text` starts with `key`, in any case ("Piece Name:" as ASTM
// D6673 prints it, "PIECE NAME:" as most exports do).
std::optional<std::string> text_value(const std::string& text, const std::string& key) {
  if (text.size() < key.size()) return std::nullopt;
  for (std::size_t k = 0; k < key.size(); ++k)
    if (std::toupper(static_cast<unsigned char>(text[k])) != key[k]) return std::nullopt;
  return trimmed(text.substr(key.size()));
}

// dxflib calls these as it reads; pieces are collected raw and checked afterwards (an
// exception thrown through dxflib would leave its reader half way).
class AamaCollector : public DL_CreationAdapter {
 public:
  std::vector<RawPiece> pieces;
  int insunits = -1;  // -1: no $INSUNITS in the header
  std::string sample_size;

  void processCodeValuePair(unsigned int code, const std::string& value) override {
    // dxflib reports an entity's data once the next entity's "0" pair is read: the entity
    // being reported is the one named by the "0" pair before the latest.
    if (code == 0) reported_ = latest_, latest_ = value;
  }
  void addBlock(const DL_BlockData& data) override {
    finish_entity();
    pieces.push_back({});
    pieces.back().block = data.name;
    in_block_ = true;
  }
  void endBlock() override {
    finish_entity();
    finish_polyline();
    in_block_ = false;
  }
  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") insunits = value;
  }
  void addPolyline(const DL_PolylineData& data) override {
    finish_entity();
    finish_polyline();
    if (!boundary()) return;
    polyline_ = OpenPolyline{};
    polyline_->closed = (data.flags & 1) != 0;
    polyline_what_ = reported_ == "LWPOLYLINE" ? "LWPOLYLINE" : "POLYLINE";
    // An LWPOLYLINE's vertices come with it; a POLYLINE's until its SEQEND.
    lightweight_ = reported_ == "LWPOLYLINE";
  }
  void addVertex(const DL_VertexData& data) override {
    if (!polyline_) return;
    polyline_->points.emplace_back(data.x, data.y);
    polyline_->bulges.push_back(data.bulge);
  }
  void endSequence() override {
    if (polyline_) polyline_->finished = true;
    finish_polyline();
  }
  void endEntity() override {
    if (polyline_ && lightweight_) {
      polyline_->finished = true;
      finish_polyline();
    }
    finish_entity();
  }
  void addLine(const DL_LineData& data) override {
    finish_entity();
    finish_polyline();
    if (in_block_ && layer() == "7")
      current().grain_line = std::make_pair(Vec2(data.x1, data.y1), Vec2(data.x2, data.y2));
    if (boundary()) add_run("LINE", {line_segment(Vec2(data.x1, data.y1), Vec2(data.x2, data.y2))});
  }
  void addArc(const DL_ArcData& data) override {
    finish_entity();
    finish_polyline();
    if (!boundary()) return;
    // Counter-clockwise from angle1 to angle2 (degrees), as DXF draws every ARC.
    const double a1 = data.angle1 * M_PI / 180, a2 = data.angle2 * M_PI / 180;
    double sweep = std::fmod(a2 - a1, 2 * M_PI);
    if (sweep <= 0) sweep += 2 * M_PI;
    const Vec2 c(data.cx, data.cy);
    const Vec2 start = c + data.radius * Vec2(std::cos(a1), std::sin(a1));
    const Vec2 end = c + data.radius * Vec2(std::cos(a2), std::sin(a2));
    if (!(data.radius > 0) || !(sweep < 2 * M_PI - 1e-12))
      return note("ARC " + std::to_string(count() + 1) + " is a whole circle or has no radius");
    add_run("ARC", {arc_segment_from_bulge(start, end, std::tan(sweep / 4))});
  }
  void addSpline(const DL_SplineData& data) override {
    finish_entity();
    finish_polyline();
    if (!boundary()) return;
    spline_ = OpenSpline{};
    spline_->degree = static_cast<int>(data.degree);
    spline_->flags = data.flags;
  }
  void addControlPoint(const DL_ControlPointData& data) override {
    if (!spline_) return;
    spline_->points.emplace_back(data.x, data.y);
    if (data.w != 1.0) spline_->rational = true;
  }
  void addKnot(const DL_KnotData& data) override {
    if (spline_) spline_->knots.push_back(data.k);
  }
  void addFitPoint(const DL_FitPointData&) override {
    if (spline_) ++spline_->fit_points;
  }
  void addPoint(const DL_PointData& data) override {
    finish_entity();
    finish_polyline();
    if (!in_block_) return;
    if (layer() == "2") current().turn_points.emplace_back(data.x, data.y);
    if (layer() == "4") current().notches.emplace_back(data.x, data.y);
  }
  void addText(const DL_TextData& data) override {
    finish_entity();
    finish_polyline();
    if (!in_block_) {
      if (auto value = text_value(data.text, "SAMPLE SIZE:")) sample_size = *value;
      return;
    }
    if (auto value = text_value(data.text, "PIECE NAME:")) current().piece_name = *value;
    if (auto value = text_value(data.text, "SIZE:")) current().size = *value;
  }

  // A POLYLINE still open when the file ends (no SEQEND).
  bool unfinished_polyline() const { return polyline_ && !polyline_->finished; }

 private:
  RawPiece& current() { return pieces.back(); }
  std::string layer() { return getAttributes().getLayer(); }
  bool boundary() { return in_block_ && !pieces.empty() && layer() == "1"; }
  int count() { return static_cast<int>(current().runs.size()); }
  void note(const std::string& problem) {
    if (current().problem.empty()) current().problem = problem;
  }
  void add_run(const std::string& kind, std::vector<Segment> segments, bool closed = false) {
    current().runs.push_back(
        {kind + " " + std::to_string(count() + 1), std::move(segments), closed});
  }

  // Called when another entity starts: a POLYLINE still without its SEQEND is broken.
  void finish_polyline() {
    if (!polyline_) return;
    OpenPolyline p = *polyline_;
    polyline_.reset();
    if (!p.finished)
      return note(polyline_what_ + " " + std::to_string(count() + 1) +
                  ": the boundary polyline is not finished (no SEQEND)");
    // A closed polyline that repeats its first vertex at the end: the repeat is dropped.
    if (p.closed && p.points.size() >= 2 && (p.points.front() - p.points.back()).norm() == 0)
      p.points.pop_back(), p.bulges.pop_back();
    if (p.points.size() < 2)
      return note(polyline_what_ + " " + std::to_string(count() + 1) +
                  " has fewer than two vertices");
    std::vector<Segment> segments;
    const std::size_t n = p.points.size();
    for (std::size_t k = 0; k + 1 < n + (p.closed ? 1 : 0); ++k)
      segments.push_back(arc_segment_from_bulge(p.points[k], p.points[(k + 1) % n], p.bulges[k]));
    add_run(polyline_what_, segments, p.closed);
  }

  void finish_entity() {
    if (!spline_) return;
    OpenSpline s = *spline_;
    spline_.reset();
    const std::string what = "SPLINE " + std::to_string(count() + 1);
    if (s.points.empty())
      return note(what + " is given by fit points only (" + std::to_string(s.fit_points) +
                  "); its control points are needed");
    if (s.rational) return note(what + " is rational (weights other than 1)");
    if (s.flags & 2) return note(what + " is periodic");
    try {
      add_run("SPLINE", bspline_as_bezier_segments(s.degree, s.points, s.knots));
    } catch (const std::invalid_argument& error) {
      note(what + ": " + error.what());
    }
  }

  bool in_block_ = false, lightweight_ = false;
  std::string latest_, reported_, polyline_what_;
  std::optional<OpenPolyline> polyline_;
  std::optional<OpenSpline> spline_;
};

// Metres per drawing unit for $INSUNITS, 0 when the file says "unitless".
double insunits_metres(int insunits, const std::string& file) {
  switch (insunits) {
    case 0:
      return 0.0;
    case 1:
      return 0.0254;
    case 2:
      return 0.3048;
    case 4:
      return 1e-3;
    case 5:
      return 1e-2;
    case 6:
      return 1.0;
    default:
      throw PatternError(file + ": unsupported $INSUNITS " + std::to_string(insunits) +
                         " (read: 1 inch, 2 foot, 4 mm, 5 cm, 6 m)");
  }
}

double named_unit_metres(const std::string& unit, const std::string& file) {
  if (unit == "mm") return 1e-3;
  if (unit == "cm") return 1e-2;
  if (unit == "inch") return 0.0254;
  throw PatternError(file + ": unknown unit '" + unit + "' (mm, cm or inch)");
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

AamaCollector collect(const std::string& file) {
  if (!std::ifstream(file)) throw PatternError("cannot open the pattern file '" + file + "'");
  AamaCollector collector;
  DL_Dxf dxf;
  if (!dxf.in(file, &collector)) throw PatternError("cannot read the DXF file '" + file + "'");
  if (collector.unfinished_polyline() && !collector.pieces.empty())
    collector.pieces.back().problem =
        "the boundary polyline is not finished (no SEQEND before the file ends)";
  return collector;
}

std::vector<std::string> sizes_of(const AamaCollector& collector) {
  std::vector<std::string> sizes;
  for (const RawPiece& raw : collector.pieces)
    if (!raw.runs.empty() && !raw.size.empty() &&
        std::find(sizes.begin(), sizes.end(), raw.size) == sizes.end())
      sizes.push_back(raw.size);
  return sizes;
}

// The piece's outline in file units, chained, and its corners (per segment: starts at one).
struct RawOutline {
  std::vector<Segment> segments;
  std::vector<bool> corner;
};

RawOutline outline_of(const RawPiece& raw, const std::string& where) {
  if (!raw.problem.empty()) throw PatternError(where + ": " + raw.problem);
  const double size = boundary_size(raw.runs);
  const double tolerance = 1e-3 * size;
  const ChainedBoundary chain = chain_boundary(raw.runs, tolerance, where);
  RawOutline outline{chain.segments, {}};
  const std::size_t n = chain.segments.size();
  if (!raw.turn_points.empty()) {
    outline.corner.assign(n, false);
    for (const Vec2& t : raw.turn_points) {
      std::size_t nearest = 0;
      for (std::size_t k = 1; k < n; ++k)
        if ((chain.segments[k].start - t).norm() < (chain.segments[nearest].start - t).norm())
          nearest = k;
      if (!((chain.segments[nearest].start - t).norm() <= tolerance))
        throw PatternError(where + ": the turn point " + point_text(t) +
                           " is not on a vertex of the boundary");
      outline.corner[nearest] = true;
    }
  } else if (raw.runs.size() > 1) {
    outline.corner = chain.starts_run;  // one edge per entity
  } else {
    outline.corner.assign(n, true);  // one polyline: every vertex
  }
  return outline;
}

PanelOutline panel_of(const RawPiece& raw, const RawOutline& outline, double scale) {
  PanelOutline panel;
  panel.name = raw.piece_name.empty() ? raw.block : raw.piece_name;
  const Mat2 to_metres = scale * Mat2::Identity();
  const int n = static_cast<int>(outline.segments.size());
  int first = 0;
  while (!outline.corner[first]) ++first;
  Edge edge;
  for (int k = 0; k < n; ++k) {
    const int i = (first + k) % n, j = (i + 1) % n;
    edge.segments.push_back(transformed(outline.segments[i], to_metres, Vec2::Zero()));
    if (outline.corner[j]) {
      edge.name = std::to_string(panel.edges.size() + 1);
      panel.edges.push_back(edge);
      edge.segments.clear();
    }
  }
  // Orientation by the signed area of the outline sampled along its segments.
  double twice_area = 0.0;
  for (const Segment& s : outline.segments)
    for (int k = 0; k < 8; ++k) {
      const Vec2 a = point_at(s, k / 8.0), b = point_at(s, (k + 1) / 8.0);
      twice_area += a.x() * b.y() - b.x() * a.y();
    }
  if (twice_area < 0) {
    std::vector<Edge> ccw;
    for (auto e = panel.edges.rbegin(); e != panel.edges.rend(); ++e) {
      Edge r{e->name, {}};
      for (auto s = e->segments.rbegin(); s != e->segments.rend(); ++s)
        r.segments.push_back(reversed(*s));
      ccw.push_back(r);
    }
    panel.edges = ccw;
  }
  if (raw.grain_line) {
    const Vec2 warp = raw.grain_line->second - raw.grain_line->first;
    if (warp.norm() > 0) panel.grain_angle_rad = std::atan2(warp.y(), warp.x()) - M_PI / 2;
  }
  for (const Vec2& notch : raw.notches) panel.notches_m.push_back(notch * scale);
  return panel;
}

// The largest extent of an outline (file units), from its segments sampled.
double extent(const RawOutline& outline) {
  Vec2 low = Vec2::Constant(INFINITY), high = -low;
  for (const Segment& s : outline.segments)
    for (int k = 0; k <= 8; ++k) {
      low = low.cwiseMin(point_at(s, k / 8.0));
      high = high.cwiseMax(point_at(s, k / 8.0));
    }
  return (high - low).maxCoeff();
}

}  // namespace

std::vector<std::string> aama_dxf_sizes(const std::string& path) {
  return sizes_of(collect(path));
}

Pattern read_aama_dxf(const std::string& file, const PatternFileOptions& options) {
  const AamaCollector collector = collect(file);
  // The size: every block of it, and the blocks that name none.
  const std::vector<std::string> sizes = sizes_of(collector);
  const std::string sample =
      collector.sample_size.empty() ? "" : " (its sample size is " + collector.sample_size + ")";
  if (options.size.empty() && sizes.size() > 1)
    throw PatternError(file + ": the file holds " + std::to_string(sizes.size()) +
                       " sizes: " + joined(sizes) + sample +
                       "; choose one (Garment/Pattern file/Size, or tightfit pattern --size)");
  if (!options.size.empty() && std::find(sizes.begin(), sizes.end(), options.size) == sizes.end())
    throw PatternError(
        file + ": no size '" + options.size + "' in the file (" +
        (sizes.empty() ? std::string("it names no size") : "its sizes: " + joined(sizes)) + ")");
  std::vector<const RawPiece*> kept;
  std::vector<RawOutline> outlines;
  for (const RawPiece& raw : collector.pieces) {
    if (raw.runs.empty() && raw.problem.empty()) continue;  // a block that is not a piece
    if (!options.size.empty() && !raw.size.empty() && raw.size != options.size) continue;
    kept.push_back(&raw);
    outlines.push_back(outline_of(raw, file + ": block '" + raw.block + "'"));
  }
  if (kept.empty()) throw PatternError(file + ": no BLOCK with a boundary on layer 1");

  // The unit: the file's, else the case's, else mm if the pieces are plausibly sized in mm.
  double scale = collector.insunits >= 0 ? insunits_metres(collector.insunits, file) : 0.0;
  if (scale > 0 && !options.units.empty() && named_unit_metres(options.units, file) != scale)
    throw PatternError(file + ": the file says its unit ($INSUNITS " +
                       std::to_string(collector.insunits) + "), which is not the " + options.units +
                       " asked for; leave Units empty to use the file's");
  if (scale == 0 && !options.units.empty()) scale = named_unit_metres(options.units, file);
  if (scale == 0) {
    // Millimetres, unless the pieces would then be implausible for a garment: any piece under
    // 2 cm or over 3 m across, or the largest under 10 cm (a pattern drawn in inches or cm
    // and read as mm is 25 or 10 times too small: a 60 cm back becomes 24 or 60 mm).
    scale = 1e-3;
    std::size_t largest = 0, smallest = 0;
    for (std::size_t k = 1; k < outlines.size(); ++k) {
      if (extent(outlines[k]) > extent(outlines[largest])) largest = k;
      if (extent(outlines[k]) < extent(outlines[smallest])) smallest = k;
    }
    const double big = extent(outlines[largest]) * scale,
                 small = extent(outlines[smallest]) * scale;
    const std::size_t odd = big > 3.0 || !(big >= 0.10) ? largest : smallest;
    if (big > 3.0 || !(big >= 0.10) || !(small >= 0.02)) {
      const double across = extent(outlines[odd]);
      char text[600];
      std::snprintf(text, sizeof text,
                    ": the file names no unit (no $INSUNITS) and block '%s' is %.4g units "
                    "across: %.4g cm in mm, %.4g cm in cm, %.4g cm in inches; in mm, the unit "
                    "assumed, the pattern is implausible (every piece 2 cm to 3 m across, the "
                    "largest at least 10 cm): say which unit it is drawn in (Garment/Pattern "
                    "file/Units, or tightfit pattern --units: mm, cm or inch)",
                    kept[odd]->block.c_str(), across, across * 0.1, across, across * 2.54);
      throw PatternError(file + text);
    }
  }
  Pattern pattern;
  pattern.name = file.substr(file.find_last_of('/') + 1);
  for (std::size_t k = 0; k < kept.size(); ++k)
    pattern.panels.push_back(panel_of(*kept[k], outlines[k], scale));
  return pattern;
}

}  // namespace tightfit::pattern
