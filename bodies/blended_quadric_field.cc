#include "bodies/blended_quadric_field.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace tightfit {
namespace {

// A unit vector normal to n.
Vec3 any_normal_to(const Vec3& n) {
  const Vec3 axis = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  return (axis - axis.dot(n) * n).normalized();
}

// The quintic smoothstep S(u) = u^3 (10 - 15 u + 6 u^2) on [0, 1] (0 below, 1 above), C2,
// with its first two derivatives.
struct Smoothstep {
  double value, slope, curvature;
};
Smoothstep smoothstep(double u) {
  if (u <= 0.0) return {0.0, 0.0, 0.0};
  if (u >= 1.0) return {1.0, 0.0, 0.0};
  return {u * u * u * (10 - 15 * u + 6 * u * u), 30 * u * u * (1 - u) * (1 - u),
          60 * u * (1 - u) * (1 - 2 * u)};
}

// One vertex's quadric and weight at x.
// The Hessian of w is alpha I + beta delta delta^T (delta = x - p_i), plus `turned`'s matrix
// for a vertex the facing factor scales (index into the query's list of them, or -1).
struct Term {
  int vertex;
  int turned;
  double distance, q;  // |delta| and 1 - r
  double w;
  double d;  // d_i(x), set with dd in the second pass
  double alpha, beta;
  Vec3 delta;
  Vec3 dw;  // grad w
  Vec3 dd;  // grad d = n + K (x - p)
  // The screen against the flat normal (F, F', F'') and grad b (below): the weight
  // u = w F the vertex gives the facing normal.
  Smoothstep screen;
  Vec3 db;
};

}  // namespace

void BlendedQuadricField::build(const std::vector<Vec3>& vertices_m,
                                const std::vector<Triangle>& triangles,
                                const std::vector<Vec3>& vertex_normals) {
  const int n = static_cast<int>(vertices_m.size());
  std::vector<std::vector<int>> around(n);
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) {
      around[t[k]].push_back(t[(k + 1) % 3]);
      around[t[k]].push_back(t[(k + 2) % 3]);
    }
  quadrics_.assign(n, Quadric{});
  for (int i = 0; i < n; ++i) {
    const Vec3& p = vertices_m[i];
    const Vec3& normal = vertex_normals[i];
    std::vector<int>& ring = around[i];
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    // The osculating quadric through the neighbours: n . e = -(a^2 k11 + 2 a b k12 + b^2 k22)/2
    // with (a, b) the edge's tangential coordinates; least squares over the ring.
    const Vec3 t1 = any_normal_to(normal), t2 = normal.cross(t1);
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Vec3 right = Vec3::Zero();
    double longest = 0.0;
    for (int j : ring) {
      const Vec3 e = vertices_m[j] - p;
      longest = std::max(longest, e.norm());
      const double a = e.dot(t1), b = e.dot(t2);
      const Vec3 row(a * a, 2 * a * b, b * b);
      normal_matrix += row * row.transpose();
      right += row * (-2.0 * e.dot(normal));
    }
    Quadric& q = quadrics_[i];
    q.centre_m = p;
    q.normal = normal;
    q.support_m = support_over_longest_edge * longest;
    q.beyond_squared_m2 = (1.0 + 1e-9) * q.support_m * q.support_m;
    q.over_support_squared = 1.0 / (q.support_m * q.support_m);
    // A ring too thin to fix all three (collinear neighbours) keeps the least-norm part: the
    // small ridge only matters in a direction no neighbour measures.
    normal_matrix += 1e-12 * (normal_matrix.trace() + 1e-300) * Mat3::Identity();
    const Vec3 k = normal_matrix.ldlt().solve(right);
    q.curvature_per_m = k[0] * t1 * t1.transpose() +
                        k[1] * (t1 * t2.transpose() + t2 * t1.transpose()) +
                        k[2] * t2 * t2.transpose();
    q.shift_m = 0.0;
  }
  build_grid();
  // The sweeps need phi alone at each vertex, from the vertices whose support holds it: the
  // same quadrics in the same ascending order as its grid cell's list (vertices_near with a
  // zero radius), so the same value as evaluate() gives, about a third of the cell's list to
  // scan.
  std::vector<int> start(n + 1, 0), holding, near;
  for (int j = 0; j < n; ++j) {
    vertices_near(vertices_m[j], 0.0, near);
    holding.insert(holding.end(), near.begin(), near.end());
    start[j + 1] = static_cast<int>(holding.size());
  }
  std::vector<double> misfit(n, 0.0);
  for (int sweep = 0; sweep < interpolation_sweeps; ++sweep) {
    for (int j = 0; j < n; ++j)
      misfit[j] = evaluate_impl<false>(vertices_m[j], vertex_normals[j], Mat3::Zero(),
                                       holding.data() + start[j], holding.data() + start[j + 1])
                      .phi_m;
    for (int j = 0; j < n; ++j) quadrics_[j].shift_m -= misfit[j];
  }
}

void BlendedQuadricField::build_grid() {
  const int n = vertex_count();
  cell_start_.assign(1, 0);
  cell_vertices_.clear();
  cells_ = {0, 0, 0};
  if (n == 0) return;
  // The grid spans the vertices' support balls. Cells of the median support keep a cell's
  // list to two to three times the vertices that add to a point in it (on the MakeHuman
  // female: 27 of 61 with cells half that size, for eight times the memory); a body whose
  // bounding box would need more than 2^22 cells of that size gets larger ones.
  Vec3 low = position(0), high = position(0);
  std::vector<double> supports(n);
  for (int i = 0; i < n; ++i) {
    low = low.cwiseMin(position(i) - Vec3::Constant(support_m(i)));
    high = high.cwiseMax(position(i) + Vec3::Constant(support_m(i)));
    supports[i] = support_m(i);
  }
  std::nth_element(supports.begin(), supports.begin() + n / 2, supports.end());
  const Vec3 extent = high - low;
  cell_m_ = std::max(supports[n / 2], 1e-12);
  constexpr double most_cells = 4194304.0;
  while ((std::floor(extent.x() / cell_m_) + 1) * (std::floor(extent.y() / cell_m_) + 1) *
             (std::floor(extent.z() / cell_m_) + 1) >
         most_cells)
    cell_m_ *= 1.25;
  grid_origin_m_ = low;
  for (int k = 0; k < 3; ++k) cells_[k] = static_cast<int>(std::floor(extent[k] / cell_m_)) + 1;
  // Each vertex goes into every cell its ball meets (the cell's nearest point to p_i within
  // s_i, with the same margin as the scan's), counted first, then filled in vertex
  // order, so that a cell sums its quadrics in one fixed order.
  const auto for_each_cell_of = [&](int i, auto&& visit) {
    const Vec3 relative = position(i) - grid_origin_m_;
    std::array<int, 3> first, last;
    for (int k = 0; k < 3; ++k) {
      first[k] = std::max(0, static_cast<int>(std::floor((relative[k] - support_m(i)) / cell_m_)));
      last[k] = std::min(cells_[k] - 1,
                         static_cast<int>(std::floor((relative[k] + support_m(i)) / cell_m_)));
    }
    for (int c = first[2]; c <= last[2]; ++c)
      for (int b = first[1]; b <= last[1]; ++b)
        for (int a = first[0]; a <= last[0]; ++a) {
          const Vec3 corner = Vec3(a, b, c) * cell_m_;
          const Vec3 nearest = relative.cwiseMax(corner).cwiseMin(corner + Vec3::Constant(cell_m_));
          if ((relative - nearest).squaredNorm() <= quadrics_[i].beyond_squared_m2)
            visit(a + cells_[0] * (b + cells_[1] * c));
        }
  };
  const std::size_t cell_count = std::size_t(cells_[0]) * cells_[1] * cells_[2];
  cell_start_.assign(cell_count + 1, 0);
  for (int i = 0; i < n; ++i) for_each_cell_of(i, [&](int cell) { ++cell_start_[cell + 1]; });
  for (std::size_t c = 0; c < cell_count; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_vertices_.resize(cell_start_[cell_count]);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (int i = 0; i < n; ++i)
    for_each_cell_of(i, [&](int cell) { cell_vertices_[fill[cell]++] = i; });
}

void BlendedQuadricField::vertices_near(const Vec3& x, double radius_m,
                                        std::vector<int>& vertices) const {
  vertices.clear();
  if (cells_[0] == 0) return;
  // The cells the ball's box meets hold every vertex whose support reaches into the ball.
  const Vec3 relative = (x - grid_origin_m_) / cell_m_;
  const double r_cells = radius_m / cell_m_;
  std::array<int, 3> first, last;
  for (int k = 0; k < 3; ++k) {
    const double low = std::floor(relative[k] - r_cells), high = std::floor(relative[k] + r_cells);
    if (!(high >= 0.0 && low < cells_[k])) return;  // the ball misses the grid (or x is NaN)
    first[k] = static_cast<int>(std::max(0.0, low));
    last[k] = static_cast<int>(std::min(double(cells_[k] - 1), high));
  }
  for (int c = first[2]; c <= last[2]; ++c)
    for (int b = first[1]; b <= last[1]; ++b)
      for (int a = first[0]; a <= last[0]; ++a) {
        const int cell = a + cells_[0] * (b + cells_[1] * c);
        for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
          const int i = cell_vertices_[k];
          // Within s_i (1 + 1e-9) + radius of x, as the scan's test below (its margin, and a
          // nanometre for round-off).
          const double reach = std::sqrt(quadrics_[i].beyond_squared_m2) + radius_m + 1e-9;
          if ((x - quadrics_[i].centre_m).squaredNorm() <= reach * reach) vertices.push_back(i);
        }
      }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
}

bool BlendedQuadricField::cell_list(const Vec3& x, const int*& listed,
                                    const int*& listed_end) const {
  // The cell holding x; outside the grid no support reaches x.
  const Vec3 relative = (x - grid_origin_m_) / cell_m_;
  std::array<int, 3> at;
  for (int k = 0; k < 3; ++k) {
    if (!(relative[k] >= 0.0 && relative[k] < cells_[k])) return false;
    at[k] = std::min(cells_[k] - 1, static_cast<int>(relative[k]));
  }
  const int cell = at[0] + cells_[0] * (at[1] + cells_[1] * at[2]);
  listed = cell_vertices_.data() + cell_start_[cell];
  listed_end = cell_vertices_.data() + cell_start_[cell + 1];
  return true;
}

BlendedQuadricField::Value BlendedQuadricField::evaluate(const Vec3& x, const Vec3& m0,
                                                         const Mat3& dm0_dx,
                                                         const std::vector<int>* candidates) const {
  const int *listed = nullptr, *listed_end = nullptr;
  if (!cell_list(x, listed, listed_end)) return Value{};
  if (candidates) listed = candidates->data(), listed_end = listed + candidates->size();
  return evaluate_impl<true>(x, m0, dm0_dx, listed, listed_end);
}

template <bool derivatives>
BlendedQuadricField::Value BlendedQuadricField::evaluate_impl(const Vec3& x, const Vec3& m0,
                                                              const Mat3& dm0_dx, const int* listed,
                                                              const int* listed_end) const {
  // The terms in a buffer that only grows (no allocation once warm), `count` of them in use.
  thread_local std::vector<Term> terms_storage;
  thread_local std::vector<Mat3> turned_storage;
  const std::size_t listed_count = static_cast<std::size_t>(listed_end - listed);
  if (terms_storage.size() < listed_count) terms_storage.resize(listed_count);
  Term* const terms = terms_storage.data();
  std::size_t count = 0;
  std::vector<Mat3>& turned = turned_storage;
  turned.clear();
  const Quadric* const quadric = quadrics_.data();
  // The first pass: every vertex whose support holds x and whose normal lies within 160 degrees
  // of the flat normal m0, with its Wendland weight w and the weight u = w F it gives the
  // facing normal m (eq. F1 in the header), and grad u
  // = F grad w + w F' grad b, grad b = (dm0/dx)^T n_i / width, whose Hessian F H w
  // + F' (grad w grad b^T + grad b grad w^T) + w F'' grad b grad b^T is summed below (m0's
  // second derivative left out: it acts only on vertices 140 to 160 degrees from m0, the far
  // side of a fold).
  constexpr double screen_width = screen_cosine_in - screen_cosine_out;
  Vec3 v = Vec3::Zero();   // sum u_j n_j
  Mat3 dv = Mat3::Zero();  // its derivative, sum n_j (grad u_j)^T
  // The first pass finds the terms and the facing normal alone; the weights' derivatives
  // follow once m tells whether any vertex is partly facing (the facing normal's derivative
  // dv is needed only then): a query where every vertex faces fully (about half of them over
  // MakeHuman's female, more on smoother bodies) skips dv's nine products a term.
  for (; listed != listed_end; ++listed) {
    const int i = *listed;
    const Quadric& vertex = quadric[i];
    const Vec3 delta = x - vertex.centre_m;
    // Most vertices of the cell's list lie beyond their support of x: their squared distance
    // tells so without the root and the division (a margin of 1e-9 keeps the test below exact).
    if (delta.squaredNorm() > vertex.beyond_squared_m2) continue;
    const double s = vertex.support_m, distance = delta.norm(), r = distance / s;
    const Smoothstep F = smoothstep((vertex.normal.dot(m0) - screen_cosine_out) / screen_width);
    // A vertex the screen drops adds nothing: it faces more than 160 degrees from m0, and m
    // lies within a few degrees of m0 wherever the flat surface has an answer (both are the
    // surface's normal), beyond the 120 degrees of the facing factor (F3).
    if (!(r < 1.0 && F.value > 0.0)) continue;
    const double q = 1.0 - r;
    Term& t = terms[count++];
    t.vertex = i;
    t.turned = -1;
    t.delta = delta;
    t.distance = distance;
    t.q = q;
    t.w = q * q * q * q * (4 * r + 1);
    t.screen = F;
    v += t.w * F.value * vertex.normal;
  }
  const double length = v.norm();
  if (!(length > 0.0)) return Value{};
  // The Wendland weight's gradient and Hessian (alpha, beta as Term says), psi(r) = (1-r)^4
  // (4r+1): psi' = -20 r (1-r)^3, so grad w = -20 (1-r)^3 delta / s^2 and its Hessian
  // -20/s^2 [(1-r)^3 I - 3 (1-r)^2 delta delta^T / (|delta| s)].
  const auto weight_derivatives = [&](Term& t) {
    const Quadric& vertex = quadric[t.vertex];
    const double s = vertex.support_m, over_s2 = vertex.over_support_squared;
    const double distance = t.distance, q = t.q;
    t.alpha = -20.0 * over_s2 * q * q * q;
    t.dw = t.alpha * t.delta;
    t.beta = distance > 0 ? 60.0 * over_s2 * q * q / (distance * s) : 0.0;
  };
  // The facing normal m = v / |v| and dm/dx = (I - m m^T) dv / |v| (eq. F2).
  const Vec3 m = v / length;
  // The second pass: each weight scaled by the facing factor S(a_i), a_i = 2 (n_i . m + 1/2)
  // (eq. F3), C2 in x as m is; the vertices turned beyond 120 degrees from m dropped.
  // The Hessian of n . m for a unit vector n (eq. F4), with rho = 1 / |v|:
  //   H(n . m) = rho Q(n) + g_n g_rho^T + g_rho g_n^T + (n . v) H rho,
  //   g_n = dv^T n, g_rho = -rho^3 dv^T v,
  //   H rho = 3 rho^5 (dv^T v)(dv^T v)^T - rho^3 (dv^T dv + Q(v)),
  // Q(c) = sum_j (c . n_j) H u_j; Q's three matrices Q_k = sum_j n_jk H u_j are summed once,
  // when some vertex is partly facing.
  Mat3 dm_dx = Mat3::Zero();
  const double rho = 1.0 / length, rho3 = rho * rho * rho;
  Vec3 dv_v = Vec3::Zero();
  // Q_k in their six distinct entries (each H u_j is symmetric): (0,0) (1,1) (2,2) (0,1) (0,2)
  // (1,2).
  double Q[3][6] = {};
  const auto Q_of = [&](const Vec3& c) -> Mat3 {
    double e[6];
    for (int k = 0; k < 6; ++k) e[k] = c[0] * Q[0][k] + c[1] * Q[1][k] + c[2] * Q[2][k];
    Mat3 matrix;
    matrix << e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2];
    return matrix;
  };
  Mat3 H_rho = Mat3::Zero();
  // Some vertex partly facing (0 < a_i < 1, below): its factor's derivatives need dm/dx.
  const bool partly_facing = derivatives && std::any_of(terms, terms + count, [&](const Term& t) {
                               const double a = 2.0 * (quadric[t.vertex].normal.dot(m) + 0.5);
                               return a > 0.0 && a < 1.0;
                             });
  if (partly_facing) {
    // dv = sum n_j (grad u_j)^T, summed in the first pass's order.
    for (std::size_t k = 0; k < count; ++k) {
      Term& t = terms[k];
      const Smoothstep& F = t.screen;
      const Vec3& normal = quadric[t.vertex].normal;
      weight_derivatives(t);
      t.db = F.value < 1.0 ? Vec3(dm0_dx.transpose() * normal / screen_width) : Vec3::Zero();
      dv += normal * (F.value * t.dw + t.w * F.slope * t.db).transpose();
    }
    dm_dx = (Mat3::Identity() - m * m.transpose()) * dv / length;
    dv_v = dv.transpose() * v;
    // Q and H rho from the first pass's weights, before the second pass scales them.
    for (std::size_t k = 0; k < count; ++k) {
      const Term& j = terms[k];
      const Smoothstep& F = j.screen;
      // F H w = F (alpha I + beta delta delta^T), and where the screen varies (F < 1, rare)
      // the terms in F' and F''.
      const Vec3& d = j.delta;
      const double fa = F.value * j.alpha, fb = F.value * j.beta;
      double hu[6] = {fa + fb * d[0] * d[0], fa + fb * d[1] * d[1], fa + fb * d[2] * d[2],
                      fb * d[0] * d[1],      fb * d[0] * d[2],      fb * d[1] * d[2]};
      if (F.slope != 0.0 || F.curvature != 0.0) {
        const Mat3 screened = F.slope * (j.dw * j.db.transpose() + j.db * j.dw.transpose()) +
                              j.w * F.curvature * j.db * j.db.transpose();
        hu[0] += screened(0, 0), hu[1] += screened(1, 1), hu[2] += screened(2, 2);
        hu[3] += screened(0, 1), hu[4] += screened(0, 2), hu[5] += screened(1, 2);
      }
      const Vec3& n = quadric[j.vertex].normal;
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 6; ++k) Q[c][k] += n[c] * hu[k];
    }
    H_rho = 3 * rho3 * rho * rho * dv_v * dv_v.transpose() - rho3 * (dv.transpose() * dv + Q_of(v));
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < count; ++k) {
    Term& t = terms[k];
    const Quadric& vertex = quadric[t.vertex];
    const Vec3& n = vertex.normal;
    const double a = 2.0 * (n.dot(m) + 0.5);
    if (!(a > 0.0)) continue;
    if (derivatives && !partly_facing) weight_derivatives(t);
    if (a < 1.0) {
      // w <- w S(a): grad (w S) = S grad w + w S' grad a, grad a = 2 (dm/dx)^T n_i; its
      // Hessian S H w + S' (grad w grad a^T + grad a grad w^T) + w S'' grad a grad a^T
      // + w S' H a, H a = 2 H(n_i . m).
      const Smoothstep S = smoothstep(a);
      if constexpr (derivatives) {
        const Vec3 da = 2.0 * dm_dx.transpose() * n;
        const Vec3 g_n = dv.transpose() * n, g_rho = -rho3 * dv_v;
        const Mat3 H_a = 2.0 * (rho * Q_of(n) + g_n * g_rho.transpose() + g_rho * g_n.transpose() +
                                n.dot(v) * H_rho);
        t.turned = static_cast<int>(turned.size());
        turned.push_back(S.slope * (t.dw * da.transpose() + da * t.dw.transpose()) +
                         t.w * S.curvature * da * da.transpose() + t.w * S.slope * H_a);
        t.alpha *= S.value;
        t.beta *= S.value;
        t.dw = S.value * t.dw + t.w * S.slope * da;
      }
      t.w *= S.value;
    }
    const Vec3 curved = vertex.curvature_per_m * t.delta;
    t.d = n.dot(t.delta) + 0.5 * t.delta.dot(curved) + vertex.shift_m;
    t.dd = n + curved;
    if (kept != k) terms[kept] = t;
    ++kept;
  }
  count = kept;
  const Term* const terms_end = terms + count;
  Value f;
  f.facing_normal = m;
  double weighted = 0.0;
  for (const Term* t = terms; t != terms_end; ++t) {
    f.weight_sum += t->w;
    if constexpr (derivatives) f.weight_gradient_per_m += t->dw;
    weighted += t->w * t->d;
  }
  if (!(f.weight_sum > 0)) return f;
  const double W = f.weight_sum;
  f.phi_m = weighted / W;
  if constexpr (!derivatives) return f;
  // grad phi = sum [w_i grad d_i + (d_i - phi) grad w_i] / W.
  for (const Term* t = terms; t != terms_end; ++t)
    f.gradient += (t->w * t->dd + (t->d - f.phi_m) * t->dw) / W;
  // From W phi = S differentiated twice:
  // H phi = sum [(d_i - phi) H w_i + grad w_i (grad d_i - grad phi)^T
  //              + (grad d_i - grad phi) grad w_i^T + w_i K_i] / W,
  // summed in its six distinct entries (every term is symmetric), H w_i as Term says.
  double h[6] = {0, 0, 0, 0, 0, 0};  // (0,0) (1,1) (2,2) (0,1) (0,2) (1,2)
  double diagonal = 0.0;
  for (const Term* term = terms; term != terms_end; ++term) {
    const Term& t = *term;
    const double off = t.d - f.phi_m, c = off * t.beta;
    const Vec3 e = t.dd - f.gradient;
    const Vec3& q = t.delta;
    const Vec3& g = t.dw;
    const Mat3& K = quadric[t.vertex].curvature_per_m;
    diagonal += off * t.alpha;
    h[0] += c * q[0] * q[0] + 2 * g[0] * e[0] + t.w * K(0, 0);
    h[1] += c * q[1] * q[1] + 2 * g[1] * e[1] + t.w * K(1, 1);
    h[2] += c * q[2] * q[2] + 2 * g[2] * e[2] + t.w * K(2, 2);
    h[3] += c * q[0] * q[1] + g[0] * e[1] + e[0] * g[1] + t.w * K(0, 1);
    h[4] += c * q[0] * q[2] + g[0] * e[2] + e[0] * g[2] + t.w * K(0, 2);
    h[5] += c * q[1] * q[2] + g[1] * e[2] + e[1] * g[2] + t.w * K(1, 2);
    if (t.turned >= 0) f.hessian_per_m += off * turned[t.turned];
  }
  Mat3& H = f.hessian_per_m;
  H(0, 0) += h[0] + diagonal;
  H(1, 1) += h[1] + diagonal;
  H(2, 2) += h[2] + diagonal;
  H(0, 1) += h[3], H(1, 0) += h[3];
  H(0, 2) += h[4], H(2, 0) += h[4];
  H(1, 2) += h[5], H(2, 1) += h[5];
  H /= W;
  return f;
}

}  // namespace tightfit
