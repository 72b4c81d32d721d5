#include "pattern/dxf_reader.h"

#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <cmath>
#include <fstream>

namespace tightfit::pattern {

namespace {

struct RawVertex {
  Vec2 x;
  double bulge = 0.0;
};

struct RawPiece {
  std::string block, piece_name;
  std::vector<RawVertex> boundary;
  bool boundary_closed = false, boundary_finished = false, has_boundary = false;
  std::vector<Vec2> turn_points, notches;
  std::optional<std::pair<Vec2, Vec2>> grain_line;
};

// dxflib calls these as it reads; pieces are collected raw and checked afterwards.
class AamaCollector : public DL_CreationAdapter {
 public:
  std::vector<RawPiece> pieces;
  int insunits = 0;

  void addBlock(const DL_BlockData& data) override {
    pieces.push_back({});
    pieces.back().block = data.name;
    in_block_ = true;
  }
  void endBlock() override { in_block_ = false; }
  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") insunits = value;
  }
  void addPolyline(const DL_PolylineData& data) override {
    in_boundary_ = in_block_ && layer() == "1" && !current().has_boundary;
    if (!in_boundary_) return;
    current().has_boundary = true;
    current().boundary_closed = (data.flags & 1) != 0;
  }
  void addVertex(const DL_VertexData& data) override {
    if (in_boundary_) current().boundary.push_back({Vec2(data.x, data.y), data.bulge});
  }
  void endSequence() override {
    if (in_boundary_) current().boundary_finished = true;
    in_boundary_ = false;
  }
  void addPoint(const DL_PointData& data) override {
    if (!in_block_) return;
    if (layer() == "2") current().turn_points.emplace_back(data.x, data.y);
    if (layer() == "4") current().notches.emplace_back(data.x, data.y);
  }
  void addLine(const DL_LineData& data) override {
    if (in_block_ && layer() == "7")
      current().grain_line = std::make_pair(Vec2(data.x1, data.y1), Vec2(data.x2, data.y2));
  }
  void addText(const DL_TextData& data) override {
    const std::string key = "PIECE NAME:";
    if (in_block_ && data.text.rfind(key, 0) == 0) {
      std::string name = data.text.substr(key.size());
      name.erase(0, name.find_first_not_of(' '));
      current().piece_name = name;
    }
  }

 private:
  RawPiece& current() { return pieces.back(); }
  std::string layer() { return getAttributes().getLayer(); }
  bool in_block_ = false, in_boundary_ = false;
};

double metres_per_unit(int insunits, const std::string& file) {
  switch (insunits) {
    case 0:
    case 4:
      return 1e-3;
    case 5:
      return 1e-2;
    case 6:
      return 1.0;
    case 1:
      return 0.0254;
    default:
      throw PatternError(file + ": unsupported $INSUNITS " + std::to_string(insunits));
  }
}

PanelOutline panel_of(const RawPiece& raw, double scale, const std::string& file) {
  PanelOutline panel;
  panel.name = raw.piece_name.empty() ? raw.block : raw.piece_name;
  const std::string where = file + ": block '" + raw.block + "'";
  if (!raw.boundary_finished)
    throw PatternError(where + ": the boundary polyline is not finished (no SEQEND)");
  std::vector<RawVertex> v = raw.boundary;
  for (RawVertex& r : v) r.x *= scale;
  if (v.size() >= 2 && (v.front().x - v.back().x).norm() < 1e-9)
    v.pop_back();
  else if (!raw.boundary_closed)
    throw PatternError(where +
                       ": the boundary is open (not flagged closed, ends away from its start)");
  if (v.size() < 2) throw PatternError(where + ": the boundary has fewer than two vertices");
  const int n = static_cast<int>(v.size());
  // Corners: the vertices at turn points.
  std::vector<bool> corner(n, raw.turn_points.empty());
  for (const Vec2& t : raw.turn_points) {
    int nearest = 0;
    for (int k = 1; k < n; ++k)
      if ((v[k].x - t * scale).norm() < (v[nearest].x - t * scale).norm()) nearest = k;
    if ((v[nearest].x - t * scale).norm() > 1e-6)
      throw PatternError(where + ": a turn point is not on the boundary");
    corner[nearest] = true;
  }
  int first = 0;
  while (!corner[first]) ++first;
  Edge edge;
  for (int k = 0; k < n; ++k) {
    const int i = (first + k) % n, j = (i + 1) % n;
    edge.segments.push_back(arc_segment_from_bulge(v[i].x, v[j].x, v[i].bulge));
    if (corner[j]) {
      edge.name = std::to_string(panel.edges.size() + 1);
      panel.edges.push_back(edge);
      edge.segments.clear();
    }
  }
  double twice_area = 0.0;
  for (int k = 0; k < n; ++k)
    twice_area += v[k].x.x() * v[(k + 1) % n].x.y() - v[(k + 1) % n].x.x() * v[k].x.y();
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

}  // namespace

Pattern read_aama_dxf(const std::string& file) {
  if (!std::ifstream(file)) throw PatternError("cannot open the pattern file '" + file + "'");
  AamaCollector collector;
  DL_Dxf dxf;
  if (!dxf.in(file, &collector)) throw PatternError("cannot read the DXF file '" + file + "'");
  const double scale = metres_per_unit(collector.insunits, file);
  Pattern pattern;
  pattern.name = file.substr(file.find_last_of('/') + 1);
  for (const RawPiece& raw : collector.pieces)
    if (raw.has_boundary) pattern.panels.push_back(panel_of(raw, scale, file));
  if (pattern.panels.empty())
    throw PatternError(file + ": no BLOCK with a boundary POLYLINE on layer 1");
  return pattern;
}

}  // namespace tightfit::pattern
