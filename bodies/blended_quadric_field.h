// A smooth signed-distance field over a triangle mesh body: each vertex i carries the quadric
// that osculates the surface there,
//   d_i(x) = n_i . (x - p_i) + (x - p_i)^T K_i (x - p_i) / 2
// (n_i the vertex's unit normal, K_i its curvature tensor fitted to its one-ring, positive where
// the body is convex), which is the signed distance to the surface up to third order in
// |x - p_i|, and the field blends them with compactly supported weights,
//   phi(x) = sum w_i(x) d_i(x) / sum w_i(x),   w_i = psi(|x - p_i| / s_i),
// psi(r) = (1 - r)^4 (4 r + 1) Wendland's C2 kernel (Wendland, "Piecewise polynomial, positive
// definite and compactly supported radial functions of minimal degree", Adv. Comput. Math. 4,
// 1995), s_i a multiple of the longest edge at vertex i. This is the moving-least-squares
// implicit surface of Shen, O'Brien and Shewchuk ("Interpolating and approximating implicit
// surfaces from polygon soup", SIGGRAPH 2004) with the planes raised to osculating quadrics, so
// its zero set passes within third order of the vertices' smooth surface rather than bulging
// out to the tangent planes. phi is C2 in x: its gradient and Hessian are exact (below), and a
// force along the gradient derives from an energy (docs/bodies.md "The smooth contact surface").
#pragma once

#include "core/types.h"

#include <array>
#include <vector>

namespace tightfit {

class BlendedQuadricField {
 public:
  // The support radius s_i over the longest edge at vertex i: large enough that every point
  // of a triangle lies within 0.39 s_i of a corner (W >= 0.35 on the flat surface), small
  // enough that few quadrics reach a quarter turn round a limb, where their third-order error
  // grows.
  static constexpr double support_over_longest_edge = 1.5;
  // Jacobi sweeps that make the field vanish at the vertices (below).
  static constexpr int interpolation_sweeps = 30;
  // The screen of the facing normal (eq. F1 below): a vertex whose normal lies within 140
  // degrees of the flat surface's normal adds fully, beyond 160 not at all. On a limb the
  // vertices within a support turn at most about 120 degrees from each other (the coarse ankle
  // of MakeHuman's bodies); the other side of a fold (a thigh across the crotch) faces about
  // 180 degrees away.
  static constexpr double screen_cosine_in = -0.76604444311897801;   // cos 140 degrees
  static constexpr double screen_cosine_out = -0.93969262078590832;  // cos 160 degrees

  // Fits each vertex's curvature tensor to the positions of its edge neighbours (least squares
  // for n_i . e_j = -e_j^T K_i e_j / 2 over the edges e_j from p_i, K_i in the tangent plane),
  // then shifts each quadric by a constant c_i so that the field vanishes at every vertex (the
  // blend of curved quadrics is not interpolating by itself: on a coarse limb, nine vertices
  // round an ankle, it passed 1.7 mm outside them). The shifts solve sum_i w_i(p_j) (d_i(p_j)
  // + c_i) = 0 by Jacobi sweeps c_j <- c_j - phi(p_j): the Wendland kernel matrix is positive
  // definite, so the sweeps converge, fastest for the smooth part of the misfit.
  void build(const std::vector<Vec3>& vertices_m, const std::vector<Triangle>& triangles,
             const std::vector<Vec3>& vertex_normals);

  struct Value {
    double weight_sum = 0.0;  // W = sum w_i: 0 where no vertex's support reaches x
    Vec3 weight_gradient_per_m = Vec3::Zero();
    double phi_m = 0.0;
    Vec3 gradient = Vec3::Zero();       // d phi / dx
    Mat3 hessian_per_m = Mat3::Zero();  // d2 phi / dx2, symmetric
    Vec3 facing_normal = Vec3::Zero();  // m of (F2), which the facing factors read
    // Every vertex whose support holds x passes the screen (F1) and faces m (F3) fully: the
    // field is the plain blend of the quadrics there, without the factors' steeper derivatives
    // (or m0's kinks, through the screen).
    bool every_vertex_facing = true;
  };
  // The field at x: every vertex whose support holds x adds its quadric, its weight scaled by
  // a facing factor, so that the other side of a thin gap (the inner thigh across the crotch)
  // never enters the blend. The factor reads a facing normal m that is C2 in x, so that the
  // gap and the contact force along its gradient are C1 wherever the factor acts
  // (docs/bodies.md, "The smooth contact surface"):
  //   (F1) v = sum_j w_j F_j n_j,  F_j = S((n_j . m0 - cos 160) / (cos 140 - cos 160)),
  //   (F2) m = v / |v|,  dm/dx = (I - m m^T) (dv/dx) / |v|,
  //   (F3) w_i <- w_i S(a_i),  a_i = 2 (n_i . m + 1/2),
  // S the quintic smoothstep, m0 = `reference_normal` the flat surface's interpolated normal
  // at x (derivative `reference_normal_derivative`): a vertex within 90 degrees of m adds
  // fully, one beyond 120 not at all. m0 only screens out the far side of a fold (F1); its
  // derivative jumps where the flat closest point passes from a face onto an edge, so a factor
  // read from m0 itself put kinks into the gap. The Hessian of a_i (F4 in the .cc) is exact
  // up to m0's second derivative, which acts only on vertices 140 to 160 degrees from m0.
  // The vertices are found in a uniform grid whose cells list the vertices
  // whose support reaches into them (built with the field): a query scans one cell's list
  // (about 100 vertices on the MakeHuman female, 27 of which add), whichever face is closest.
  // `candidates` (when given) replaces the cell's list: ascending vertex numbers that hold every
  // vertex whose support holds x (vertices_near's list for a ball round x), so that the same
  // quadrics add in the same order and the value is the grid's to the last bit.
  Value evaluate(const Vec3& x_m, const Vec3& reference_normal,
                 const Mat3& reference_normal_derivative,
                 const std::vector<int>* candidates = nullptr) const;
  // Every vertex whose support reaches within `radius_m` of x, ascending, into `vertices`: the
  // candidates of every point of that ball (a garment vertex keeps them while it moves less).
  // About 30 on the MakeHuman female at a tenth of its mean edge, against a cell's 100.
  void vertices_near(const Vec3& x_m, double radius_m, std::vector<int>& vertices) const;

  // K_i, 1/m (symmetric, zero along n_i).
  Mat3 curvature(int vertex) const {
    const double* k = quadrics_[vertex].curvature_per_m;
    Mat3 K;
    K << k[0], k[3], k[4], k[3], k[1], k[5], k[4], k[5], k[2];
    return K;
  }
  // The other parts of vertex i's quadric and weight: p_i, n_i, c_i (m) and s_i (m).
  int vertex_count() const { return static_cast<int>(quadrics_.size()); }
  const Vec3& position(int vertex) const { return quadrics_[vertex].centre_m; }
  const Vec3& normal(int vertex) const { return quadrics_[vertex].normal; }
  double shift_m(int vertex) const { return quadrics_[vertex].shift_m; }
  double support_m(int vertex) const { return quadrics_[vertex].support_m; }

 private:
  // Everything a vertex's term reads, side by side (16 doubles, two cache lines), so that a
  // query's scan of its 30 to 100 candidates loads each vertex once (docs/performance.md, "The
  // body query alone"). beyond_squared_m2 = s_i^2 (1 + 1e-9): a vertex farther than its root
  // from x has r >= 1 and adds nothing; over_support_squared = 1 / s_i^2. K_i is symmetric:
  // its six distinct entries (0,0) (1,1) (2,2) (0,1) (0,2) (1,2).
  struct Quadric {
    Vec3 centre_m;
    double beyond_squared_m2;
    Vec3 normal;
    double support_m;
    double curvature_per_m[6];
    double shift_m;  // c_i
    double over_support_squared;
  };
  std::vector<Quadric> quadrics_;
  // evaluate(), with the derivatives (gradient, Hessian, the facing normal's derivative) only
  // when `derivatives`; phi and W are the same to the last bit either way.
  template <bool derivatives>
  Value evaluate_impl(const Vec3& x_m, const Vec3& reference_normal,
                      const Mat3& reference_normal_derivative, const int* listed,
                      const int* listed_end) const;
  // The candidates of the grid's cell holding x (an empty range outside the grid).
  bool cell_list(const Vec3& x_m, const int*& listed, const int*& listed_end) const;
  // Lists, for each cell of a uniform grid, the vertices whose support ball reaches into it.
  void build_grid();
  Vec3 grid_origin_m_ = Vec3::Zero();
  double cell_m_ = 1.0;
  std::array<int, 3> cells_{0, 0, 0};
  std::vector<int> cell_start_, cell_vertices_;  // CSR, cells numbered x fastest
};

}  // namespace tightfit
