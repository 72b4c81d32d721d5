#include "pattern/edge_division.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace tightfit::pattern {

std::vector<SeamIndices> seam_indices(const Pattern& cut) {
  auto side_of = [&](const EdgeRange& range) {
    SideIndices side;
    for (std::size_t p = 0; p < cut.panels.size(); ++p)
      if (cut.panels[p].name == range.panel) side.panel = static_cast<int>(p);
    for (const std::string& name : range.edges)
      side.edges.push_back(find_edge(cut.panels[side.panel], name));
    side.reversed = range.reversed;
    return side;
  };
  std::vector<SeamIndices> seams;
  for (const SeamSpec& s : cut.seams) seams.push_back({side_of(s.a), side_of(s.b)});
  return seams;
}

namespace {

// Chords no longer than the target (the mesher's size bound), so that it need not split them.
int chords_for(double length_m, double edge_length_m) {
  return std::max(1, static_cast<int>(std::ceil(length_m / edge_length_m - 1e-9)));
}

// Breakpoints `stations` (increasing fractions, 0 and 1 included), interval k cut into
// counts[k] equal parts.
std::vector<double> subdivided(const std::vector<double>& stations,
                               const std::vector<int>& counts) {
  std::vector<double> points{stations.front()};
  for (std::size_t k = 0; k + 1 < stations.size(); ++k)
    for (int i = 1; i <= counts[k]; ++i)
      points.push_back(stations[k] + (stations[k + 1] - stations[k]) * i / counts[k]);
  points.back() = 1.0;
  return points;
}

void insert_sorted(std::vector<double>& list, double value) {
  const auto at = std::lower_bound(list.begin(), list.end(), value);
  if (at != list.end() && std::abs(*at - value) < 1e-12) return;
  if (at != list.begin() && std::abs(*(at - 1) - value) < 1e-12) return;
  list.insert(at, value);
}

}  // namespace

EdgeDivision::EdgeDivision(const Pattern& cut, double edge_length_m)
    : pattern_(cut), seams_(seam_indices(cut)) {
  const std::size_t n_panels = cut.panels.size();
  edge_length_m_.resize(n_panels);
  joints_.resize(n_panels);
  fractions_.resize(n_panels);
  for (std::size_t p = 0; p < n_panels; ++p)
    for (const Edge& edge : cut.panels[p].edges) {
      const ArcLengthCurve curve(edge.segments);
      edge_length_m_[p].push_back(curve.length_m());
      joints_[p].push_back(curve.joint_fractions());
      std::vector<int> counts;
      const auto& joints = joints_[p].back();
      for (std::size_t k = 0; k + 1 < joints.size(); ++k)
        counts.push_back(chords_for((joints[k + 1] - joints[k]) * curve.length_m(), edge_length_m));
      fractions_[p].push_back(subdivided(joints, counts));
    }
  for (const SeamIndices& seam : seams_) divide_seam(seam, edge_length_m);
}

void EdgeDivision::divide_seam(const SeamIndices& seam, double h) {
  // Each side's own breakpoints (corners and joints) as fractions of the side's length.
  auto breakpoints = [&](const SideIndices& side, double& total_m) {
    total_m = 0.0;
    for (int e : side.edges) total_m += edge_length_m_[side.panel][e];
    std::vector<double> u;
    double start_m = 0.0;
    for (int e : side.edges) {
      const double length = edge_length_m_[side.panel][e];
      for (double j : joints_[side.panel][e])
        u.push_back((start_m + (side.reversed ? 1.0 - j : j) * length) / total_m);
      start_m += length;
    }
    std::sort(u.begin(), u.end());
    u.erase(std::unique(u.begin(), u.end(), [](double x, double y) { return y - x < 1e-12; }),
            u.end());
    u.front() = 0.0;
    u.back() = 1.0;
    return u;
  };
  double length_a = 0, length_b = 0;
  const std::vector<double> ua = breakpoints(seam.a, length_a), ub = breakpoints(seam.b, length_b);

  // Stations: breakpoints of either side, one close to the other side's merged with it (each
  // side keeping its own), the rest at the same fraction on both sides.
  const double close = 0.3 * h / std::max(length_a, length_b);
  std::vector<double> sa, sb;
  auto push = [&](double a, double b) {
    if (sa.empty() || (a > sa.back() + 1e-9 && b > sb.back() + 1e-9)) {
      sa.push_back(a);
      sb.push_back(b);
    }
  };
  std::size_t i = 0, j = 0;
  while (i < ua.size() || j < ub.size()) {
    if (i < ua.size() && j < ub.size() && std::abs(ua[i] - ub[j]) < close)
      push(ua[i++], ub[j++]);
    else if (j >= ub.size() || (i < ua.size() && ua[i] < ub[j]))
      push(ua[i], ua[i]), ++i;
    else
      push(ub[j], ub[j]), ++j;
  }
  sa.back() = sb.back() = 1.0;
  std::vector<int> counts;
  for (std::size_t k = 0; k + 1 < sa.size(); ++k)
    counts.push_back(
        chords_for(std::max((sa[k + 1] - sa[k]) * length_a, (sb[k + 1] - sb[k]) * length_b), h));

  // Back from side fractions to each edge's own.
  auto distribute = [&](const SideIndices& side, const std::vector<double>& u, double total_m) {
    double start_m = 0.0;
    for (int e : side.edges) {
      const double length = edge_length_m_[side.panel][e];
      std::vector<double> f;
      for (double x : u) {
        const double local = (x * total_m - start_m) / length;
        if (local < -1e-9 || local > 1 + 1e-9) continue;
        f.push_back(std::clamp(side.reversed ? 1.0 - local : local, 0.0, 1.0));
      }
      std::sort(f.begin(), f.end());
      f.front() = 0.0;
      f.back() = 1.0;
      fractions_[side.panel][e] = f;
      start_m += length;
    }
  };
  distribute(seam.a, subdivided(sa, counts), length_a);
  distribute(seam.b, subdivided(sb, counts), length_b);
}

std::vector<Vec2> EdgeDivision::outline_points(int panel) const {
  std::vector<Vec2> points;
  const auto& edges = pattern_.panels[panel].edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const ArcLengthCurve curve(edges[e].segments);
    const auto& f = fractions_[panel][e];
    for (std::size_t k = 0; k + 1 < f.size(); ++k) points.push_back(curve.point_at_fraction(f[k]));
  }
  return points;
}

std::vector<EdgeDivision::OutlinePoint> EdgeDivision::outline_index(int panel) const {
  std::vector<OutlinePoint> index;
  for (std::size_t e = 0; e < fractions_[panel].size(); ++e)
    for (std::size_t k = 0; k + 1 < fractions_[panel][e].size(); ++k)
      index.push_back({static_cast<int>(e), static_cast<int>(k)});
  return index;
}

void EdgeDivision::add_split(int panel, int edge, int index, double along) {
  pending_.push_back({panel, edge, index, along});
  // The same chord of the seam's other side, counted along the walk.
  for (const SeamIndices& seam : seams_)
    for (int s = 0; s < 2; ++s) {
      const SideIndices& side = s == 0 ? seam.a : seam.b;
      const SideIndices& other = s == 0 ? seam.b : seam.a;
      if (side.panel != panel) continue;
      const auto at = std::find(side.edges.begin(), side.edges.end(), edge);
      if (at == side.edges.end()) continue;
      int chord = 0;
      for (auto e = side.edges.begin(); e != at; ++e)
        chord += static_cast<int>(fractions_[panel][*e].size()) - 1;
      const int n_own = static_cast<int>(fractions_[panel][edge].size()) - 1;
      chord += side.reversed ? n_own - 1 - index : index;
      const double t = side.reversed ? 1.0 - along : along;
      for (int e : other.edges) {
        const int n = static_cast<int>(fractions_[other.panel][e].size()) - 1;
        if (chord < n) {
          const int k = other.reversed ? n - 1 - chord : chord;
          pending_.push_back({other.panel, e, k, other.reversed ? 1.0 - t : t});
          return;
        }
        chord -= n;
      }
    }
}

bool EdgeDivision::apply_splits() {
  // Points closer than this (a fraction of their chord) are one point: the mesher splits the
  // two sides of a seam on its own, and where they are not alike (a dart's legs, two curves
  // of one length meeting at the tip at 42 degrees) it puts the points round the tip at equal
  // distances from it, the copies of which land at equal arc lengths on the other leg, a
  // little apart; kept apart, each round splits the sliver between them again and the
  // outline grows without end. Merged at their mean along the chord, on both sides alike (a
  // copy keeps its chord's parameter, or 1 minus it: the gaps, and so the merging, are the
  // same on both sides).
  constexpr double merge_along = 0.2;
  std::sort(pending_.begin(), pending_.end(), [](const Split& a, const Split& b) {
    return std::tie(a.panel, a.edge, a.chord, a.along) <
           std::tie(b.panel, b.edge, b.chord, b.along);
  });
  std::vector<Split> merged;
  std::size_t count = 0;
  double last_along = 0.0;  // the point before, along the same chord when it joins
  for (const Split& s : pending_) {
    const bool joins = count > 0 && merged.back().panel == s.panel &&
                       merged.back().edge == s.edge && merged.back().chord == s.chord &&
                       s.along - last_along < merge_along;
    if (joins) {
      merged.back().along += (s.along - merged.back().along) / double(++count);
    } else {
      merged.push_back(s);
      count = 1;
    }
    last_along = s.along;
  }
  // Fractions from the chords as they were before this round's points go in.
  std::vector<std::pair<std::pair<int, int>, double>> points;
  for (const Split& s : merged) {
    const auto& f = fractions_[s.panel][s.edge];
    points.push_back({{s.panel, s.edge}, f[s.chord] + s.along * (f[s.chord + 1] - f[s.chord])});
  }
  bool changed = false;
  for (const auto& [where, fraction] : points) {
    auto& f = fractions_[where.first][where.second];
    const std::size_t before = f.size();
    insert_sorted(f, fraction);
    changed = changed || f.size() != before;
  }
  pending_.clear();
  return changed;
}

}  // namespace tightfit::pattern
