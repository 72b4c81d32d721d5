#include "bodies/mesh_body.h"

#include "bodies/body_mesh_error.h"
#include "bodies/polygon_mesh.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace tightfit {
namespace {

// Barycentric coordinates of p (in the triangle's plane, or nearly) in triangle (a, b, c),
// clipped to the triangle: a closest point lies on it up to round-off.
Vec3 barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e0 = b - a, e1 = c - a, ep = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double dp0 = ep.dot(e0), dp1 = ep.dot(e1), denominator = d00 * d11 - d01 * d01;
  const double v = (d11 * dp0 - d01 * dp1) / denominator, w = (d00 * dp1 - d01 * dp0) / denominator;
  Vec3 bary(1.0 - v - w, v, w);
  bary = bary.cwiseMax(0.0);
  return bary / bary.sum();
}

// Barycentric coordinates below this count as zero: the closest point is then on an edge or a
// vertex. CGAL's closest point on an edge has a zero coordinate up to round-off (1e-16), and
// the pseudo-normal of any feature that holds the closest point signs correctly, so the
// tolerance only has to be above round-off; smaller keeps the face's derivative nearer an edge.
constexpr double on_feature_tolerance = 1e-12;

// How far a point may move before its near faces are found again, over the mesh's mean edge
// length: the faces kept are those within d + 2 r of where they were found (d the distance
// there), a few faces for a point on the surface.
constexpr double near_reach_fraction = 0.1;

std::atomic<std::uint64_t> shapes_made{0};

}  // namespace

MeshBody::MeshBody(TriangleSurface surface, const MeshBodyOptions& options, const std::string& what)
    : surface_(std::move(surface)),
      what_(what),
      open_(options.import.allow_open_surface),
      skin_offset_m_(options.skin_offset_m),
      contact_surface_(options.contact_surface) {
  if (!(skin_offset_m_ >= 0))
    throw std::invalid_argument("Body/Skin offset: must not be negative (m)");
  if (surface_.source_face.size() != surface_.triangles.size()) {
    surface_.source_face.resize(surface_.triangles.size());
    for (std::size_t t = 0; t < surface_.triangles.size(); ++t) surface_.source_face[t] = int(t);
  }
  check_body_surface(surface_, open_, what_);
  std::map<std::pair<int, int>, int> triangle_of_directed_edge;
  const int n = static_cast<int>(surface_.triangles.size());
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      triangle_of_directed_edge[{surface_.triangles[t][k], surface_.triangles[t][(k + 1) % 3]}] = t;
  neighbours_.assign(n, {-1, -1, -1});
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      // The checks made the orientation consistent: the neighbour runs the edge backwards.
      const auto it = triangle_of_directed_edge.find(
          {surface_.triangles[t][(k + 1) % 3], surface_.triangles[t][k]});
      if (it != triangle_of_directed_edge.end()) neighbours_[t][k] = it->second;
    }
  update_geometry();
}

void MeshBody::set_vertex_positions(const std::vector<Vec3>& vertices_m) {
  if (vertices_m.size() != surface_.vertices_m.size())
    throw BodyMeshError(what_ + ": a new shape needs " +
                        std::to_string(surface_.vertices_m.size()) + " vertices, not " +
                        std::to_string(vertices_m.size()));
  TriangleSurface moved = surface_;
  moved.vertices_m = vertices_m;
  check_body_geometry(moved, open_, what_);  // the connectivity passed on construction
  surface_ = std::move(moved);
  update_geometry();
}

void MeshBody::update_geometry() {
  const auto& v = surface_.vertices_m;
  face_normals_.clear();
  vertex_normals_.assign(v.size(), Vec3::Zero());
  for (const Triangle& t : surface_.triangles) {
    const Vec3 normal = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
    face_normals_.push_back(normal);
    // Each face counts with its angle at the vertex: the pseudo-normal of Baerentzen and
    // Aanaes (their eq. 4), independent of how the surface round the vertex is triangulated.
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = v[t[(k + 1) % 3]] - v[t[k]], b = v[t[(k + 2) % 3]] - v[t[k]];
      vertex_normals_[t[k]] += std::atan2(a.cross(b).norm(), a.dot(b)) * normal;
    }
  }
  for (Vec3& n : vertex_normals_)
    if (n.norm() > 0) n.normalize();
  bvh_.build(v, surface_.triangles);
  shape_id_ = ++shapes_made;
  double edges_m = 0.0;
  for (const Triangle& t : surface_.triangles)
    for (int k = 0; k < 3; ++k) edges_m += (v[t[(k + 1) % 3]] - v[t[k]]).norm();
  near_reach_m_ = near_reach_fraction * edges_m / (3.0 * double(surface_.triangles.size()));
  if (contact_surface_ == MeshBodyOptions::ContactSurface::smooth)
    field_.build(v, surface_.triangles, vertex_normals_);
}

Vec3 MeshBody::interpolated_normal(int triangle, const Vec3& b, double* length) const {
  const Triangle& t = surface_.triangles[triangle];
  Vec3 n =
      b[0] * vertex_normals_[t[0]] + b[1] * vertex_normals_[t[1]] + b[2] * vertex_normals_[t[2]];
  const double norm = n.norm();
  if (length) *length = norm;
  // Vertex normals that cancel (a knife edge) leave no direction: fall back on the face's.
  return norm > 1e-12 ? Vec3(n / norm) : face_normals_[triangle];
}

SurfacePoint MeshBody::query(const Vec3& x) const {
  return finished(x, faceted_query(x));
}

SurfacePoint MeshBody::query_parts(const Vec3& x, NearFaces& near, QueryParts parts) const {
  if (!parts.closest_point && !parts.location && near.expansion_shape == shape_id_ &&
      (x - near.expanded_at_m).norm() <= expansion_reach_m())
    return expanded_answer(x, near);
  if (near.shape == shape_id_ && (x - near.centre_m).norm() <= near.reach_m) {
    const TriangleBvh::Hit hit = bvh_.closest_among(x, near.faces, near.last_face);
    near.last_face = hit.triangle;
    return finished(x, faceted_answer(x, hit), parts, &near);
  }
  // For x within r of the centre c, whose closest face is at d from c: x's closest face is no
  // farther from x than c's, d + r, so it lies within d + 2 r of c. (A nanometre more for
  // round-off.)
  const TriangleBvh::Hit hit = bvh_.closest(x);
  near.centre_m = x;
  near.last_face = hit.triangle;
  near.reach_m = near_reach_m_;
  near.shape = shape_id_;
  bvh_.within(x, (x - hit.point_m).norm() + 2.0 * near_reach_m_ + 1e-9, near.faces);
  if (contact_surface_ == MeshBodyOptions::ContactSurface::smooth)
    field_.vertices_near(x, near_reach_m_, near.blend_vertices);
  return finished(x, faceted_answer(x, hit), parts, &near);
}

SurfacePoint MeshBody::faceted_near(const Vec3& x, const NearFaces* near) const {
  if (near && near->shape == shape_id_ && (x - near->centre_m).norm() <= near->reach_m)
    return faceted_answer(x, bvh_.closest_among(x, near->faces, near->last_face));
  return faceted_query(x);
}

SurfacePoint MeshBody::finished(const Vec3& x, SurfacePoint s, QueryParts parts,
                                NearFaces* near) const {
  if (contact_surface_ == MeshBodyOptions::ContactSurface::faceted) {
    // The skin: the surface moved out along the normal.
    s.closest_point_m += skin_offset_m_ * s.outward_normal;
    s.signed_distance_m -= skin_offset_m_;
    return s;
  }
  // A frame's force (no closest point, no location) is kept for its expansion where the blend
  // alone answers; elsewhere (half an edge off the surface) the faceted gap, only C0 across the
  // faces' edges, is blended in, and nothing is kept.
  const bool keep = near && !parts.closest_point && !parts.location;
  Mat3 gap_hessian = Mat3::Zero();
  // The closest point on the skin's level set.
  const bool covered = smooth_query(x, s, parts.closest_point, near, keep ? &gap_hessian : nullptr);
  if (parts.location) s.location = smooth_location(s.closest_point_m, s.location.face);
  s.signed_distance_m -= skin_offset_m_;
  if (keep) {
    // Only where the normal turns by at most a milliradian over the reach (a radius of curvature
    // above 1 cm at 10 micrometres): where the field's gradient shrinks (a part thinner than the
    // blend's support, a finger), Hg = H / |grad phi| grows and the expansion's d^2 term with it.
    const bool gentle = gap_hessian.norm() * expansion_reach_m() <= 1e-3;
    near->expansion_shape = covered && gentle ? shape_id_ : 0;
    near->expanded_at_m = x;
    near->expanded = s;
    near->expanded_gap_hessian_per_m = gap_hessian;
  }
  return s;
}

SurfacePoint MeshBody::expanded_answer(const Vec3& x, const NearFaces& near) const {
  const Vec3 d = x - near.expanded_at_m;
  SurfacePoint s = near.expanded;
  const Vec3 Hd = near.expanded_gap_hessian_per_m * d;
  s.signed_distance_m += s.gap_gradient.dot(d) + 0.5 * d.dot(Hd);
  s.gap_gradient += Hd;
  s.outward_normal = (s.outward_normal + s.normal_derivative_per_m * d).normalized();
  // As smooth_field's: one Newton step x - g n onto the skin's level set.
  s.closest_point_m = x - s.signed_distance_m * s.outward_normal;
  return s;
}

SurfacePoint MeshBody::faceted_answer(const Vec3& x, const TriangleBvh::Hit& hit) const {
  const int t = hit.triangle;
  const Triangle& tri = surface_.triangles[t];
  const auto& v = surface_.vertices_m;
  Vec3 b = barycentric(hit.point_m, v[tri[0]], v[tri[1]], v[tri[2]]);
  const int n_zero = (b.array() <= on_feature_tolerance).count();

  // The feature the closest point lies on gives the sign's pseudo-normal and how the closest
  // point moves with x, hence the derivative dN/dx of the interpolated normal N = sum b_i n_i.
  Vec3 pseudo_normal;
  Mat3 dN_dx = Mat3::Zero();
  if (n_zero == 0) {
    // Inside the face: the closest point is x's projection, and db_i/dx is the in-plane gradient
    // of b_i, nf x (p_{i+2} - p_{i+1}) / (2 A).
    pseudo_normal = face_normals_[t];
    const double twice_area = (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).norm();
    for (int i = 0; i < 3; ++i) {
      const Vec3 gradient =
          face_normals_[t].cross(v[tri[(i + 2) % 3]] - v[tri[(i + 1) % 3]]) / twice_area;
      dN_dx += vertex_normals_[tri[i]] * gradient.transpose();
    }
  } else if (n_zero == 1) {
    // On the edge from corner i to corner j (local edge i): the closest point slides along it,
    // c = p_i + s (p_j - p_i) with ds/dx = e^T / |e|^2; the pseudo-normal is the sum of the two
    // faces' normals.
    int zero = 0;
    b.minCoeff(&zero);
    const int i = (zero + 1) % 3, j = (zero + 2) % 3;
    b[zero] = 0.0;
    b /= b.sum();
    const int across = neighbours_[t][i];
    pseudo_normal = face_normals_[t] + face_normals_[across >= 0 ? across : t];
    const Vec3 e = v[tri[j]] - v[tri[i]];
    dN_dx = (vertex_normals_[tri[j]] - vertex_normals_[tri[i]]) * e.transpose() / e.squaredNorm();
  } else {
    // At a vertex the closest point stays put while x moves: dN/dx = 0.
    int corner = 0;
    b.maxCoeff(&corner);
    b = Vec3::Unit(corner);
    pseudo_normal = vertex_normals_[tri[corner]];
  }
  const Vec3 foot = b[0] * v[tri[0]] + b[1] * v[tri[1]] + b[2] * v[tri[2]];
  const Vec3 to_x = x - foot;
  const double distance = to_x.norm();
  SurfacePoint s;
  s.signed_distance_m = to_x.dot(pseudo_normal) >= 0 ? distance : -distance;
  // dg/dx of the distance to the flat faces: the face normal over a face, the unit direction
  // from the foot over an edge or a vertex (the pseudo-normal's direction when x is on it).
  if (n_zero == 0)
    s.gap_gradient = face_normals_[t];
  else if (distance > 1e-12)
    s.gap_gradient = to_x / s.signed_distance_m;
  else
    s.gap_gradient = pseudo_normal.normalized();

  double length = 1.0;
  s.outward_normal = interpolated_normal(t, b, &length);
  // n = N / |N|: dn/dx = (I - n n^T) dN/dx / |N|.
  if (length > 1e-12)
    s.normal_derivative_per_m =
        (Mat3::Identity() - s.outward_normal * s.outward_normal.transpose()) * dN_dx / length;
  s.location.face = t;
  s.location.coordinates = b;
  s.closest_point_m = foot;
  return s;
}

Vec3 MeshBody::surface_point_near_m(const SurfaceLocation& location, const NearFaces* near) const {
  const bool smooth = contact_surface_ == MeshBodyOptions::ContactSurface::smooth;
  // The anchor's point found before on this shape (NearFaces::anchor_point_m), before anything
  // else: a frame asks for it at every stage.
  if (smooth && near && near->anchor_shape == shape_id_ && near->anchor.face == location.face &&
      near->anchor.coordinates == location.coordinates)
    return near->anchor_point_m;
  const Triangle& tri = surface_.triangles.at(location.face);
  const Vec3& b = location.coordinates;
  const auto& v = surface_.vertices_m;
  const Vec3 flat = b[0] * v[tri[0]] + b[1] * v[tri[1]] + b[2] * v[tri[2]];
  const Vec3 normal = interpolated_normal(location.face, b);
  if (!smooth) return flat + skin_offset_m_ * normal;
  // Out along the interpolated normal to where the smooth gap is the skin's: the inverse of
  // smooth_location, by Newton's method on g(flat + t N) - skin (dg/dt = grad g . N). The first
  // step starts on the anchor's own face, whose closest point is the flat point itself (the
  // tree's answer, without the search: the flat point lies up to the blend's sagitta off the
  // smooth surface, often beyond the kept faces' reach).
  double t = 0.0;
  for (int iteration = 0; iteration < 8; ++iteration) {
    const Vec3 y = flat + t * normal;
    SurfacePoint s = iteration == 0 ? faceted_answer(y, TriangleBvh::Hit{location.face, flat})
                                    : faceted_near(y, near);
    smooth_field(y, s, near);
    const double residual = s.signed_distance_m - skin_offset_m_;
    const double slope = s.gap_gradient.dot(normal);
    if (!(slope > 0.1)) break;  // the normal field runs nearly along the surface: stop there
    t -= residual / slope;
    if (std::abs(residual) < 1e-13) break;
  }
  const Vec3 point = flat + t * normal;
  if (near) {
    near->anchor_shape = shape_id_;
    near->anchor = location;
    near->anchor_point_m = point;
  }
  return point;
}

DisplayMesh MeshBody::display_mesh() const {
  DisplayMesh mesh;
  mesh.triangles = surface_.triangles;
  mesh.vertices_m = surface_.vertices_m;
  for (std::size_t i = 0; i < mesh.vertices_m.size(); ++i)
    mesh.vertices_m[i] += skin_offset_m_ * vertex_normals_[i];
  return mesh;
}

std::unique_ptr<MeshBody> load_mesh_body(const std::string& path, const MeshBodyOptions& options) {
  return std::make_unique<MeshBody>(import_surface(read_polygon_mesh(path), options.import),
                                    options, "body mesh '" + path + "'");
}

}  // namespace tightfit
