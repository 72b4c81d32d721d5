#include "bodies/triangle_surface.h"

#include "bodies/body_mesh_error.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

namespace tightfit {

namespace {

std::string face_text(const TriangleSurface& s, int t) {
  std::ostringstream out;
  const Triangle& tri = s.triangles[t];
  out << "face " << s.source_face[t] << " (vertices " << tri[0] << ", " << tri[1] << ", " << tri[2]
      << ")";
  return out.str();
}

[[noreturn]] void fail(const std::string& what, const std::string& message) {
  throw BodyMeshError(what + ": " + message);
}

void check_areas(const TriangleSurface& s, const std::string& what) {
  for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t) {
    const Triangle& tri = s.triangles[t];
    const Vec3 &a = s.vertices_m[tri[0]], &b = s.vertices_m[tri[1]], &c = s.vertices_m[tri[2]];
    const double longest =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (!((b - a).cross(c - a).norm() > 1e-10 * longest))
      fail(what,
           face_text(s, t) + " is degenerate: it has no area (repeated or collinear vertices)");
  }
}

// The faces face outwards when the enclosed volume is positive (closed surfaces only).
void check_volume(const TriangleSurface& s, bool allow_open_surface, const std::string& what) {
  if (allow_open_surface) return;
  const double volume = enclosed_volume_m3(s.vertices_m, s.triangles);
  if (!(volume > 0)) {
    std::ostringstream out;
    out << "oriented inwards: the enclosed volume is " << volume
        << " m^3 (the faces must run counter-clockwise seen from outside)";
    fail(what, out.str());
  }
}

// Union-find over the triangles' corners, to count the fans round each vertex.
struct CornerSets {
  std::vector<int> parent;
  explicit CornerSets(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int root(int c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  }
  void join(int a, int b) { parent[root(a)] = root(b); }
};

int corner_of(const Triangle& tri, int t, int vertex) {
  for (int k = 0; k < 3; ++k)
    if (tri[k] == vertex) return 3 * t + k;
  return -1;
}

}  // namespace

void check_body_surface(const TriangleSurface& s, bool allow_open_surface,
                        const std::string& what) {
  if (s.triangles.empty()) fail(what, "no faces");
  check_areas(s, what);
  // Each undirected edge with the triangles that use it, and in which direction.
  struct Use {
    int triangle;
    bool forward;  // runs from the smaller vertex index to the larger
  };
  std::map<std::pair<int, int>, std::vector<Use>> edges;
  const int n_triangles = static_cast<int>(s.triangles.size());
  for (int t = 0; t < n_triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back({t, a < b});
    }
  CornerSets corners(3 * n_triangles);
  for (const auto& [edge, uses] : edges) {
    const std::string edge_text = "the edge between vertices " + std::to_string(edge.first) +
                                  " and " + std::to_string(edge.second);
    if (uses.size() > 2) {
      std::string faces;
      for (const Use& u : uses)
        faces += (faces.empty() ? "" : ", ") + std::to_string(s.source_face[u.triangle]);
      fail(what, "non-manifold: " + edge_text + " belongs to " + std::to_string(uses.size()) +
                     " faces (" + faces + "); each edge must join exactly two");
    }
    if (uses.size() == 1 && !allow_open_surface)
      fail(what, "not closed: " + edge_text + " belongs to " + face_text(s, uses[0].triangle) +
                     " only (a hole or a border); allow an open surface to accept it");
    if (uses.size() == 2) {
      if (uses[0].forward == uses[1].forward)
        fail(what, "inconsistent orientation: " + face_text(s, uses[0].triangle) + " and " +
                       face_text(s, uses[1].triangle) + " run through " + edge_text +
                       " in the same direction (one of them is flipped)");
      for (int v : {edge.first, edge.second})
        corners.join(corner_of(s.triangles[uses[0].triangle], uses[0].triangle, v),
                     corner_of(s.triangles[uses[1].triangle], uses[1].triangle, v));
    }
  }
  // Corners joined across shared edges: a vertex whose corners fall into more than one set has
  // its triangles in separate fans (two surfaces touching at a point).
  std::vector<int> fan_root(s.vertices_m.size(), -1);
  for (int c = 0; c < 3 * n_triangles; ++c) {
    const int v = s.triangles[c / 3][c % 3], r = corners.root(c);
    if (fan_root[v] < 0)
      fan_root[v] = r;
    else if (fan_root[v] != r)
      fail(what, "non-manifold: the faces round vertex " + std::to_string(v) +
                     " form more than one fan (surfaces touching at a point), e.g. " +
                     face_text(s, c / 3));
  }
  check_volume(s, allow_open_surface, what);
}

void check_body_geometry(const TriangleSurface& s, bool allow_open_surface,
                         const std::string& what) {
  check_areas(s, what);
  check_volume(s, allow_open_surface, what);
}

double enclosed_volume_m3(const std::vector<Vec3>& v, const std::vector<Triangle>& triangles) {
  double six_volume = 0.0;
  for (const Triangle& t : triangles) six_volume += v[t[0]].dot(v[t[1]].cross(v[t[2]]));
  return six_volume / 6.0;
}

double surface_area_m2(const std::vector<Vec3>& v, const std::vector<Triangle>& triangles) {
  double twice_area = 0.0;
  for (const Triangle& t : triangles)
    twice_area += (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm();
  return twice_area / 2.0;
}

}  // namespace tightfit
