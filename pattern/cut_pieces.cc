// Pieces cut on the fold and mirrored pairs (pattern.h, cut_pieces).
#include "pattern/pattern.h"

namespace tightfit::pattern {

namespace {

// The edge mirrored by x -> A x + b and walked the other way.
Edge mirrored_reversed(const Edge& edge, const Mat2& A, const Vec2& b, const std::string& name) {
  Edge m;
  m.name = name;
  for (auto s = edge.segments.rbegin(); s != edge.segments.rend(); ++s)
    m.segments.push_back(reversed(transformed(*s, A, b)));
  return m;
}

Edge joined(Edge first, const Edge& second, const std::string& name) {
  first.name = name;
  first.segments.insert(first.segments.end(), second.segments.begin(), second.segments.end());
  return first;
}

// The reflection x -> A x + b across the line through p with direction d.
std::pair<Mat2, Vec2> reflection_across(const Vec2& p, const Vec2& d) {
  const Vec2 u = d.normalized();
  const Mat2 A = 2.0 * u * u.transpose() - Mat2::Identity();
  return {A, p - A * p};
}

PanelOutline unfolded(const PanelOutline& piece) {
  const int n = static_cast<int>(piece.edges.size());
  const int f = find_edge(piece, piece.fold_edge);
  if (n < 3)
    throw PatternError("panel '" + piece.name + "': a piece cut on the fold needs three edges");
  const Vec2 a = piece.edges[f].segments.front().start;
  const Vec2 b = piece.edges[f].segments.back().end;
  // Named references, not a structured binding: C++17 lambdas cannot capture those.
  const auto reflection = reflection_across(a, b - a);
  const Mat2& A = reflection.first;
  const Vec2& shift = reflection.second;
  // Walking from the fold's end B round to its start A: e_1 ... e_m; the mirror image walks
  // back from A to B. e_1 and e_m touch the fold and join their own mirror images.
  std::vector<const Edge*> chain;
  for (int k = 1; k < n; ++k) chain.push_back(&piece.edges[(f + k) % n]);
  const int m = static_cast<int>(chain.size());
  auto mirror = [&](int k, const std::string& name) {
    return mirrored_reversed(*chain[k], A, shift, name);
  };
  PanelOutline whole = piece;
  whole.fold_edge.clear();
  whole.edges.clear();
  whole.edges.push_back(joined(mirror(0, ""), *chain[0], chain[0]->name));
  for (int k = 1; k + 1 < m; ++k) whole.edges.push_back(*chain[k]);
  whole.edges.push_back(joined(*chain[m - 1], mirror(m - 1, ""), chain[m - 1]->name));
  for (int k = m - 2; k >= 1; --k) whole.edges.push_back(mirror(k, chain[k]->name + " mirrored"));
  for (const Vec2& notch : piece.notches_m) whole.notches_m.push_back(A * notch + shift);
  return whole;
}

// The piece mirrored left to right (x -> -x), still counter-clockwise.
PanelOutline mirror_image(const PanelOutline& piece) {
  const Mat2 A = Eigen::Vector2d(-1.0, 1.0).asDiagonal();
  PanelOutline m = piece;
  m.name = piece.name + " mirrored";
  m.mirrored_copy = false;
  m.placement.reset();
  m.grain_angle_rad = -piece.grain_angle_rad;
  m.edges.clear();
  for (auto e = piece.edges.rbegin(); e != piece.edges.rend(); ++e)
    m.edges.push_back(mirrored_reversed(*e, A, Vec2::Zero(), e->name));
  for (Vec2& notch : m.notches_m) notch = A * notch;
  return m;
}

}  // namespace

Pattern cut_pieces(const Pattern& pattern) {
  Pattern cut = pattern;
  cut.panels.clear();
  for (const PanelOutline& piece : pattern.panels) {
    PanelOutline whole = piece.fold_edge.empty() ? piece : unfolded(piece);
    whole.mirrored_copy = false;
    // A file's 3D placement holds for the piece as drawn, not unfolded or mirrored.
    if (!piece.fold_edge.empty()) whole.placement.reset();
    cut.panels.push_back(whole);
    if (piece.mirrored_copy) cut.panels.push_back(mirror_image(whole));
  }
  return cut;
}

}  // namespace tightfit::pattern
