#include "bodies/blended_quadric_field.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstring>

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

// Two doubles in one SSE2 register (the GCC and Clang vector extension; every x86-64 has
// SSE2): the query's terms are worked two at a time, lane 0 the even terms, lane 1 the odd
// ones, and the lanes of each sum added at the end. The order is fixed by the terms' order, so
// a point gets the same value to the last bit whichever list its terms come from.
typedef double Pair __attribute__((vector_size(16)));
Pair pair_at(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
void store(double* p, Pair v) {
  std::memcpy(p, &v, sizeof v);
}
Pair both(double s) {
  return Pair{s, s};
}
double total(Pair v) {
  return v[0] + v[1];
}

// What the query keeps of a term (a vertex whose support holds x), two terms side by side
// field by field (term k's field f at pair k / 2, lane k % 2), in a buffer that only grows (no
// allocation once warm): so that a term's fields are written with one address and a pair's
// field is read in one load.
// The fields: delta = x - p_i; w_i (scaled by the facing factor once m is known); alpha, beta
// (H w = alpha I + beta delta delta^T); grad w; the screen F (eq. F1) and its two derivatives;
// the facing argument a_i (eq. F3); n_i; |delta|, r, s_i, 1 / s_i^2; d_i; grad d_i = n_i + K_i
// delta.
enum Field {
  delta_x,
  delta_y,
  delta_z,
  weight,
  alpha,
  beta,
  dw_x,
  dw_y,
  dw_z,
  screen,
  screen_slope,
  screen_curvature,
  facing,
  normal_x,
  normal_y,
  normal_z,
  distance_m,
  ratio,
  support_length,
  inverse_support_squared,
  quadric_d,
  dd_x,
  dd_y,
  dd_z,
  field_count
};
constexpr std::size_t pair_stride = 2 * field_count;
struct Terms {
  std::vector<double> storage;
  std::vector<int> vertex;
  std::size_t capacity = 0;  // terms, even
  void reserve(std::size_t terms) {
    const std::size_t needed = terms + 2 - terms % 2;  // one more for an odd count's padding
    if (needed <= capacity) return;
    capacity = needed;
    storage.assign(field_count * capacity, 0.0);
    vertex.assign(capacity, 0);
  }
  // Term k's field f is term(k)[2 f]; the next term's fields follow at next(term(k), k).
  double* term(std::size_t k) { return storage.data() + (k >> 1) * pair_stride + (k & 1); }
  static double* next(double* t, std::size_t k) { return k & 1 ? t + pair_stride - 1 : t + 1; }
  // Pair p's field f.
  const double* pair(std::size_t p, Field f) const {
    return storage.data() + p * pair_stride + 2 * f;
  }
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
    const Mat3 K = k[0] * t1 * t1.transpose() + k[1] * (t1 * t2.transpose() + t2 * t1.transpose()) +
                   k[2] * t2 * t2.transpose();
    const double entries[6] = {K(0, 0), K(1, 1), K(2, 2), K(0, 1), K(0, 2), K(1, 2)};
    std::copy(entries, entries + 6, q.curvature_per_m);
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
  thread_local Terms terms;
  // The facing factor's Hessian terms of the vertices it scales (0 < a_i < 1), and their terms.
  thread_local std::vector<Mat3> turned;
  thread_local std::vector<std::size_t> turned_term;
  terms.reserve(static_cast<std::size_t>(listed_end - listed));
  int* const V = terms.vertex.data();
  const Quadric* const quadric = quadrics_.data();
  // The first pass: every vertex whose support holds x and whose normal lies within 160 degrees
  // of the flat normal m0 (eq. F1 in the header), with what its weight needs.
  constexpr double screen_width = screen_cosine_in - screen_cosine_out;
  std::size_t count = 0;
  bool screened = false;  // some vertex whose support holds x screened out, fully or partly
  double* slot = terms.term(0);
  // The vertices a few places ahead asked for early: a query's vertices lie scattered over the
  // quadrics' array, and their loads, not the arithmetic, set the pace of this loop.
  constexpr std::ptrdiff_t ahead = 4;
  for (const int* early = listed; early != listed_end && early - listed < ahead; ++early)
    __builtin_prefetch(reinterpret_cast<const char*>(quadric + *early) + 64);
  for (; listed != listed_end; ++listed) {
    if (listed_end - listed > ahead) {
      const char* later = reinterpret_cast<const char*>(quadric + listed[ahead]);
      __builtin_prefetch(later);
      __builtin_prefetch(later + 64);
    }
    const int i = *listed;
    const Quadric& vertex = quadric[i];
    const double ax = x[0] - vertex.centre_m[0], ay = x[1] - vertex.centre_m[1],
                 az = x[2] - vertex.centre_m[2];
    // Most vertices of the list lie beyond their support of x: their squared distance tells so
    // without the root and the division (a margin of 1e-9 keeps the test below exact).
    const double squared = ax * ax + ay * ay + az * az;
    if (squared > vertex.beyond_squared_m2) continue;
    const double s = vertex.support_m, distance = std::sqrt(squared), r = distance / s;
    const Vec3& n = vertex.normal;
    // The screen is 1 within 140 degrees of m0 (most vertices), 0 beyond 160.
    const double cosine = n[0] * m0[0] + n[1] * m0[1] + n[2] * m0[2];
    const Smoothstep F = cosine >= screen_cosine_in
                             ? Smoothstep{1.0, 0.0, 0.0}
                             : smoothstep((cosine - screen_cosine_out) / screen_width);
    // A vertex the screen drops adds nothing: it faces more than 160 degrees from m0, and m
    // lies within a few degrees of m0 wherever the flat surface has an answer (both are the
    // surface's normal), beyond the 120 degrees of the facing factor (F3).
    screened |= r < 1.0 && F.value < 1.0;
    if (!(r < 1.0 && F.value > 0.0)) continue;
    V[count] = i;
    double* const t = slot;
    t[2 * delta_x] = ax, t[2 * delta_y] = ay, t[2 * delta_z] = az;
    t[2 * normal_x] = n[0], t[2 * normal_y] = n[1], t[2 * normal_z] = n[2];
    t[2 * distance_m] = distance, t[2 * ratio] = r;
    t[2 * support_length] = s, t[2 * inverse_support_squared] = vertex.over_support_squared;
    t[2 * screen] = F.value, t[2 * screen_slope] = F.slope, t[2 * screen_curvature] = F.curvature;
    slot = Terms::next(slot, count);
    ++count;
  }
  if (count == 0) return Value{};
  // An odd count's last pair padded with a term of no weight (r = 1, at its neighbour's vertex).
  if (count % 2) {
    for (int f = 0; f < field_count; ++f) slot[2 * f] = 0.0;
    slot[2 * ratio] = 1.0;
    V[count] = V[count - 1];
  }
  const std::size_t pairs = (count + 1) / 2;
  // The Wendland weights, two terms at a time, and v = sum u_j n_j with u = w F. With the
  // derivatives, the weight's gradient and Hessian, psi(r) = (1-r)^4 (4r+1): psi' = -20 r
  // (1-r)^3, so grad w = -20 (1-r)^3 delta / s^2 and its Hessian -20/s^2 [(1-r)^3 I - 3
  // (1-r)^2 delta delta^T / (|delta| s)] (0 at delta = 0, where it is -20/s^2 I alone).
  Pair v_lanes[3] = {};
  for (std::size_t p = 0; p < pairs; ++p) {
    double* const P = terms.storage.data() + p * pair_stride;
    const Pair r = pair_at(P + 2 * ratio), q = 1.0 - r, q2 = q * q;
    const Pair w = q2 * q2 * (4 * r + 1);
    store(P + 2 * weight, w);
    const Pair u = w * pair_at(P + 2 * screen);
    v_lanes[0] += u * pair_at(P + 2 * normal_x);
    v_lanes[1] += u * pair_at(P + 2 * normal_y);
    v_lanes[2] += u * pair_at(P + 2 * normal_z);
    if constexpr (derivatives) {
      const Pair over_s2 = pair_at(P + 2 * inverse_support_squared),
                 grows = -20.0 * over_s2 * q2 * q;
      const Pair distance = pair_at(P + 2 * distance_m);
      store(P + 2 * alpha, grows);
      store(P + 2 * dw_x, grows * pair_at(P + 2 * delta_x));
      store(P + 2 * dw_y, grows * pair_at(P + 2 * delta_y));
      store(P + 2 * dw_z, grows * pair_at(P + 2 * delta_z));
      const Pair curving = 60.0 * over_s2 * q2 / (distance * pair_at(P + 2 * support_length));
      store(P + 2 * beta, distance > 0.0 ? curving : Pair{0.0, 0.0});
    }
  }
  const double vx = total(v_lanes[0]), vy = total(v_lanes[1]), vz = total(v_lanes[2]);
  const double length = std::sqrt(vx * vx + vy * vy + vz * vz);
  if (!(length > 0.0)) return Value{};
  // The facing normal m = v / |v| and dm/dx = (I - m m^T) dv / |v| (eq. F2), and each term's
  // facing argument a_i = 2 (n_i . m + 1/2) (eq. F3).
  const Vec3 v(vx, vy, vz), m = v / length;
  bool partly_facing = false, not_facing = false;
  slot = terms.term(0);
  for (std::size_t k = 0; k < count; slot = Terms::next(slot, k), ++k) {
    double* const t = slot;
    const double a =
        2.0 * (t[2 * normal_x] * m[0] + t[2 * normal_y] * m[1] + t[2 * normal_z] * m[2] + 0.5);
    t[2 * facing] = a;
    partly_facing |= a > 0.0 && a < 1.0;
    not_facing |= !(a > 0.0);
  }
  // The Hessian of n . m for a unit vector n (eq. F4), with rho = 1 / |v|:
  //   H(n . m) = rho Q(n) + g_n g_rho^T + g_rho g_n^T + (n . v) H rho,
  //   g_n = dv^T n, g_rho = -rho^3 dv^T v,
  //   H rho = 3 rho^5 (dv^T v)(dv^T v)^T - rho^3 (dv^T dv + Q(v)),
  // Q(c) = sum_j (c . n_j) H u_j; Q's three matrices Q_k = sum_j n_jk H u_j are summed once,
  // when some vertex is partly facing: each in its six distinct entries (each H u_j is
  // symmetric) as three pairs, (0,0) (1,1) | (2,2) (0,1) | (0,2) (1,2).
  Mat3 dv = Mat3::Zero(), dm_dx = Mat3::Zero(), H_rho = Mat3::Zero();
  Vec3 dv_v = Vec3::Zero();
  const double rho = 1.0 / length, rho3 = rho * rho * rho;
  Pair Qk[3][3] = {};
  const auto Q_of = [&](const Vec3& c) -> Mat3 {
    Pair e[3];
    for (int k = 0; k < 3; ++k) e[k] = c[0] * Qk[0][k] + c[1] * Qk[1][k] + c[2] * Qk[2][k];
    Mat3 matrix;
    matrix << e[0][0], e[1][1], e[2][0], e[1][1], e[0][1], e[2][1], e[2][0], e[2][1], e[1][0];
    return matrix;
  };
  // The screen's argument's gradient grad b = (dm0/dx)^T n_j / width, where the screen varies.
  const auto screen_gradient = [&](const double* t, const Vec3& n) -> Vec3 {
    return t[2 * screen] < 1.0 ? Vec3(dm0_dx.transpose() * n / screen_width) : Vec3::Zero();
  };
  if (derivatives && partly_facing) {
    // dv = sum n_j (grad u_j)^T, grad u = F grad w + w F' grad b; the Hessian of u, F H w + F'
    // (grad w grad b^T + grad b grad w^T) + w F'' grad b grad b^T, goes into Q (m0's second
    // derivative left out: it acts only on vertices 140 to 160 degrees from m0, the far side
    // of a fold).
    slot = terms.term(0);
    for (std::size_t k = 0; k < count; slot = Terms::next(slot, k), ++k) {
      const double* const t = slot;
      const Vec3 n(t[2 * normal_x], t[2 * normal_y], t[2 * normal_z]);
      const Vec3 dw(t[2 * dw_x], t[2 * dw_y], t[2 * dw_z]);
      dv += n * (t[2 * screen] * dw + t[2 * weight] * t[2 * screen_slope] * screen_gradient(t, n))
                    .transpose();
    }
    dm_dx = (Mat3::Identity() - m * m.transpose()) * dv / length;
    dv_v = dv.transpose() * v;
    slot = terms.term(0);
    for (std::size_t k = 0; k < count; slot = Terms::next(slot, k), ++k) {
      const double* const t = slot;
      const double fa = t[2 * screen] * t[2 * alpha], fb = t[2 * screen] * t[2 * beta];
      const double ax = t[2 * delta_x], ay = t[2 * delta_y], az = t[2 * delta_z];
      Pair h[3] = {Pair{fa + fb * ax * ax, fa + fb * ay * ay},
                   Pair{fa + fb * az * az, fb * ax * ay}, Pair{fb * ax * az, fb * ay * az}};
      const double n[3] = {t[2 * normal_x], t[2 * normal_y], t[2 * normal_z]};
      if (t[2 * screen_slope] != 0.0 || t[2 * screen_curvature] != 0.0) {
        const Vec3 dw(t[2 * dw_x], t[2 * dw_y], t[2 * dw_z]);
        const Vec3 db = screen_gradient(t, Vec3(n[0], n[1], n[2]));
        const Mat3 screened = t[2 * screen_slope] * (dw * db.transpose() + db * dw.transpose()) +
                              t[2 * weight] * t[2 * screen_curvature] * db * db.transpose();
        h[0] += Pair{screened(0, 0), screened(1, 1)};
        h[1] += Pair{screened(2, 2), screened(0, 1)};
        h[2] += Pair{screened(0, 2), screened(1, 2)};
      }
      for (int c = 0; c < 3; ++c)
        for (int e = 0; e < 3; ++e) Qk[c][e] += n[c] * h[e];
    }
    H_rho = 3 * rho3 * rho * rho * dv_v * dv_v.transpose() - rho3 * (dv.transpose() * dv + Q_of(v));
  }
  // Each weight scaled by the facing factor S(a_i) (eq. F3), C2 in x as m is: the vertices
  // turned beyond 120 degrees from m weigh nothing (a term of no weight, gradient or Hessian
  // adds exactly nothing below).
  turned.clear();
  turned_term.clear();
  slot = terms.term(0);
  if (partly_facing || not_facing)
    for (std::size_t k = 0; k < count; slot = Terms::next(slot, k), ++k) {
      double* const t = slot;
      const double a = t[2 * facing];
      if (a >= 1.0) continue;
      if (!(a > 0.0)) {
        for (Field f : {weight, alpha, beta, dw_x, dw_y, dw_z}) t[2 * f] = 0.0;
        continue;
      }
      // w <- w S(a): grad (w S) = S grad w + w S' grad a, grad a = 2 (dm/dx)^T n_i; its
      // Hessian S H w + S' (grad w grad a^T + grad a grad w^T) + w S'' grad a grad a^T
      // + w S' H a, H a = 2 H(n_i . m).
      const Smoothstep S = smoothstep(a);
      const double w = t[2 * weight];
      if constexpr (derivatives) {
        const Vec3 n(t[2 * normal_x], t[2 * normal_y], t[2 * normal_z]);
        const Vec3 dw(t[2 * dw_x], t[2 * dw_y], t[2 * dw_z]);
        const Vec3 da = 2.0 * dm_dx.transpose() * n;
        const Vec3 g_n = dv.transpose() * n, g_rho = -rho3 * dv_v;
        const Mat3 H_a = 2.0 * (rho * Q_of(n) + g_n * g_rho.transpose() + g_rho * g_n.transpose() +
                                n.dot(v) * H_rho);
        turned_term.push_back(k);
        turned.push_back(S.slope * (dw * da.transpose() + da * dw.transpose()) +
                         w * S.curvature * da * da.transpose() + w * S.slope * H_a);
        t[2 * alpha] *= S.value;
        t[2 * beta] *= S.value;
        const Vec3 scaled = S.value * dw + w * S.slope * da;
        t[2 * dw_x] = scaled[0], t[2 * dw_y] = scaled[1], t[2 * dw_z] = scaled[2];
      }
      t[2 * weight] = w * S.value;
    }
  // The quadrics d_i = n_i . delta + delta^T K_i delta / 2 + c_i and grad d_i = n_i + K_i
  // delta, two terms at a time, and the sums W = sum w_i, sum w_i d_i, grad W, sum w_i K_i.
  Pair weight_sum = {0, 0}, weighted = {0, 0}, weight_gradient[3] = {}, weighted_curvature[6] = {};
  for (std::size_t p = 0; p < pairs; ++p) {
    double* const P = terms.storage.data() + p * pair_stride;
    const Quadric &first = quadric[V[2 * p]], &second = quadric[V[2 * p + 1]];
    const double *K0 = first.curvature_per_m, *K1 = second.curvature_per_m;
    Pair K[6];
    for (int e = 0; e < 6; ++e) K[e] = Pair{K0[e], K1[e]};
    const Pair ax = pair_at(P + 2 * delta_x), ay = pair_at(P + 2 * delta_y),
               az = pair_at(P + 2 * delta_z);
    const Pair nx = pair_at(P + 2 * normal_x), ny = pair_at(P + 2 * normal_y),
               nz = pair_at(P + 2 * normal_z);
    const Pair cx = K[0] * ax + K[3] * ay + K[4] * az, cy = K[3] * ax + K[1] * ay + K[5] * az,
               cz = K[4] * ax + K[5] * ay + K[2] * az;
    const Pair d = nx * ax + ny * ay + nz * az + 0.5 * (ax * cx + ay * cy + az * cz) +
                   Pair{first.shift_m, second.shift_m};
    const Pair w = pair_at(P + 2 * weight);
    weight_sum += w;
    weighted += w * d;
    if constexpr (derivatives) {
      store(P + 2 * quadric_d, d);
      store(P + 2 * dd_x, nx + cx), store(P + 2 * dd_y, ny + cy), store(P + 2 * dd_z, nz + cz);
      weight_gradient[0] += pair_at(P + 2 * dw_x);
      weight_gradient[1] += pair_at(P + 2 * dw_y);
      weight_gradient[2] += pair_at(P + 2 * dw_z);
      for (int e = 0; e < 6; ++e) weighted_curvature[e] += w * K[e];
    }
  }
  Value f;
  f.every_vertex_facing = !(screened || partly_facing || not_facing);
  f.facing_normal = m;
  f.weight_sum = total(weight_sum);
  if constexpr (derivatives)
    f.weight_gradient_per_m =
        Vec3(total(weight_gradient[0]), total(weight_gradient[1]), total(weight_gradient[2]));
  if (!(f.weight_sum > 0)) return f;
  const double W = f.weight_sum;
  f.phi_m = total(weighted) / W;
  if constexpr (!derivatives) return f;
  // grad phi = sum [w_i grad d_i + (d_i - phi) grad w_i] / W.
  const Pair phi = both(f.phi_m);
  Pair gradient[3] = {};
  for (std::size_t p = 0; p < pairs; ++p) {
    const double* const P = terms.storage.data() + p * pair_stride;
    const Pair w = pair_at(P + 2 * weight), off = pair_at(P + 2 * quadric_d) - phi;
    gradient[0] += w * pair_at(P + 2 * dd_x) + off * pair_at(P + 2 * dw_x);
    gradient[1] += w * pair_at(P + 2 * dd_y) + off * pair_at(P + 2 * dw_y);
    gradient[2] += w * pair_at(P + 2 * dd_z) + off * pair_at(P + 2 * dw_z);
  }
  f.gradient = Vec3(total(gradient[0]), total(gradient[1]), total(gradient[2])) / W;
  // From W phi = S differentiated twice:
  // H phi = sum [(d_i - phi) H w_i + grad w_i (grad d_i - grad phi)^T
  //              + (grad d_i - grad phi) grad w_i^T + w_i K_i] / W,
  // summed in its six distinct entries (every term is symmetric), H w_i = alpha I + beta delta
  // delta^T, and for the terms the facing factor scales their matrix above.
  const Pair Gx = both(f.gradient[0]), Gy = both(f.gradient[1]), Gz = both(f.gradient[2]);
  Pair h[6] = {}, diagonal = {0, 0};  // (0,0) (1,1) (2,2) (0,1) (0,2) (1,2)
  for (std::size_t p = 0; p < pairs; ++p) {
    const double* const P = terms.storage.data() + p * pair_stride;
    const Pair off = pair_at(P + 2 * quadric_d) - phi, c = off * pair_at(P + 2 * beta);
    const Pair qx = pair_at(P + 2 * delta_x), qy = pair_at(P + 2 * delta_y),
               qz = pair_at(P + 2 * delta_z);
    const Pair gx = pair_at(P + 2 * dw_x), gy = pair_at(P + 2 * dw_y), gz = pair_at(P + 2 * dw_z);
    const Pair ex = pair_at(P + 2 * dd_x) - Gx, ey = pair_at(P + 2 * dd_y) - Gy,
               ez = pair_at(P + 2 * dd_z) - Gz;
    diagonal += off * pair_at(P + 2 * alpha);
    h[0] += c * qx * qx + 2 * gx * ex;
    h[1] += c * qy * qy + 2 * gy * ey;
    h[2] += c * qz * qz + 2 * gz * ez;
    h[3] += c * qx * qy + gx * ey + ex * gy;
    h[4] += c * qx * qz + gx * ez + ex * gz;
    h[5] += c * qy * qz + gy * ez + ey * gz;
  }
  Mat3& H = f.hessian_per_m;
  for (std::size_t j = 0; j < turned.size(); ++j)
    H += (terms.term(turned_term[j])[2 * quadric_d] - f.phi_m) * turned[j];
  const double diagonal_sum = total(diagonal);
  double e[6];
  for (int k = 0; k < 6; ++k) e[k] = total(h[k]) + total(weighted_curvature[k]);
  H(0, 0) += e[0] + diagonal_sum;
  H(1, 1) += e[1] + diagonal_sum;
  H(2, 2) += e[2] + diagonal_sum;
  H(0, 1) += e[3], H(1, 0) += e[3];
  H(0, 2) += e[4], H(2, 0) += e[4];
  H(1, 2) += e[5], H(2, 1) += e[5];
  H /= W;
  return f;
}

}  // namespace tightfit
