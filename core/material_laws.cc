// The three membrane laws of docs/model.md ("Closed forms"), each written once as an energy W(C).
#include "core/dual.h"
#include "core/material.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace tightfit {

void FabricParameters::validate() const {
  auto require = [](bool ok, const char* entry, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("Material/") + entry + " " + what);
  };
  require(stiffness_weft_N_per_m > 0, "Stiffness weft", "must be positive (N/m)");
  require(stiffness_warp_N_per_m > 0, "Stiffness warp", "must be positive (N/m)");
  require(shear_stiffness_N_per_m > 0, "Shear stiffness", "must be positive (N/m)");
  require(thickness_m > 0, "Thickness", "must be positive (m)");
  require(areal_density_kg_per_m2 > 0, "Areal density", "must be positive (kg/m^2)");
  require(neo_hookean_shear_modulus_Pa > 0, "Neo-Hookean shear modulus", "must be positive (Pa)");
  require(poisson_weft_warp >= 0 && poisson_weft_warp * poisson_warp_weft() < 1.0,
          "Poisson ratio weft-warp", "must be >= 0 with nu12 * nu21 < 1 (positive-definite law)");
}

namespace {

// Plane-stress orthotropic stiffness in Voigt order (11, 22, 12) with engineering shear.
struct OrthotropicStiffness {
  double d11, d12, d22, d33;
  explicit OrthotropicStiffness(const FabricParameters& f) {
    const double nu12 = f.poisson_weft_warp;
    const double nu21 = f.poisson_warp_weft();
    const double denominator = 1.0 - nu12 * nu21;
    d11 = f.stiffness_weft_N_per_m / denominator;
    d22 = f.stiffness_warp_N_per_m / denominator;
    d12 = nu21 * f.stiffness_weft_N_per_m / denominator;  // = nu12 Y2 / (1 - nu12 nu21)
    d33 = f.shear_stiffness_N_per_m;
  }
  // W = 1/2 e : D : e for a symmetric strain (e11, e22, e12), engineering shear 2 e12.
  template <class S>
  S quadratic_energy(const S& e11, const S& e22, const S& e12) const {
    return 0.5 * (d11 * e11 * e11 + 2.0 * d12 * e11 * e22 + d22 * e22 * e22) +
           2.0 * d33 * e12 * e12;
  }
  // u : D : v for two strains in Voigt order (11, 22, 12) with engineering shear.
  template <class S>
  S product(const std::array<S, 3>& u, const std::array<S, 3>& v) const {
    return d11 * u[0] * v[0] + d12 * (u[0] * v[1] + u[1] * v[0]) + d22 * u[1] * v[1] +
           d33 * u[2] * v[2];
  }
  double largest() const { return std::max(d11, d22); }
};

// The Biot strain U - I, U = sqrt(C), as (e11, e22, e12).
// In 2D, sqrt(C) = (C + s I) / t with s = sqrt(det C), t = sqrt(tr C + 2 s).
template <class S>
std::array<S, 3> biot_strain(const S& c11, const S& c22, const S& c12) {
  using std::sqrt;  // plain doubles; Dual's overload is found by argument-dependent lookup
  const S s = sqrt(c11 * c22 - c12 * c12);
  const S t = sqrt(c11 + c22 + 2.0 * s);
  return {(c11 + s) / t - 1.0, (c22 + s) / t - 1.0, c12 / t};
}

// Linear Biot: nominal stress linear in the Biot strain.
class LinearBiot {
 public:
  explicit LinearBiot(const FabricParameters& f) : stiffness_(f) {}
  static const char* name() { return "linear biot"; }
  template <class S>
  S energy(const S& c11, const S& c22, const S& c12) const {
    const std::array<S, 3> e = biot_strain(c11, c22, c12);
    return stiffness_.quadratic_energy(e[0], e[1], e[2]);
  }
  double stiffness_scale() const { return stiffness_.largest(); }

  // dW/dv, v = (C11, C22, C12), by hand: the stress every force evaluation asks for, at a
  // third of the cost of differentiating energy() with dual numbers (which gives the same to
  // round-off). With s = sqrt(det C), t = sqrt(tr C + 2 s), p_a = C_aa + s, e_a = p_a / t - 1,
  // e_3 = C12 / t and g = dW/de = (D11 e1 + D12 e2, D12 e1 + D22 e2, 4 D33 e3):
  //   dW/dv = (g1 dp1/dv + g2 dp2/dv + g3 dC12/dv) / t - (g . (p1, p2, C12)) / t^2 dt/dv.
  std::array<double, 3> energy_gradient(double c11, double c22, double c12) const {
    const double s = std::sqrt(c11 * c22 - c12 * c12);
    const double t = std::sqrt(c11 + c22 + 2.0 * s);
    const double p1 = c11 + s, p2 = c22 + s;
    const double e1 = p1 / t - 1.0, e2 = p2 / t - 1.0, e3 = c12 / t;
    const OrthotropicStiffness& d = stiffness_;
    const double g1 = d.d11 * e1 + d.d12 * e2, g2 = d.d12 * e1 + d.d22 * e2, g3 = 4.0 * d.d33 * e3;
    const double ds[3] = {0.5 * c22 / s, 0.5 * c11 / s, -c12 / s};
    const double dt[3] = {(1.0 + 2.0 * ds[0]) / (2.0 * t), (1.0 + 2.0 * ds[1]) / (2.0 * t),
                          ds[2] / t};
    const double q = (g1 * p1 + g2 * p2 + g3 * c12) / (t * t);
    return {(g1 * (1.0 + ds[0]) + g2 * ds[0]) / t - q * dt[0],
            (g1 * ds[1] + g2 * (1.0 + ds[1])) / t - q * dt[1],
            ((g1 + g2) * ds[2] + g3) / t - q * dt[2]};
  }

 private:
  OrthotropicStiffness stiffness_;
};

// Linear Biot relaxed for slack (docs/model.md, "Slack: the tension field"): a membrane takes
// no compression, so the fabric's own strain e' may exceed the apparent strain e of the
// mid-surface (the excess is taken up by wrinkles) and the energy is the least over it,
//   W_rel(e) = min { 1/2 e' : D : e'  |  e' = Q diag(e1', e2') Q^T,  e1' >= e1, e2' >= e2 },
// Q the principal directions of e (those of C) and e1 >= e2 its principal strains. On that
// plane the energy is 1/2 [e1' e2'] A [e1' e2']^T, A_ij = (n_i n_i) : D : (n_j n_j), and the
// box-constrained minimum has three cases:
//   taut     (sigma_1, sigma_2 >= 0, sigma = A [e1 e2]^T): W_rel = W, the law unchanged;
//   slack    (e1 <= 0, so both <= 0): e' = 0, W_rel = 0;
//   wrinkled (tension along n_i, sigma_j < 0): e_j' = -A_ij e_i / A_jj, the free lateral
//            contraction, W_rel = 1/2 (A_ii - A_ij^2 / A_jj) e_i^2.
// It is C1 across the cases, and the normal stress across the wrinkles is zero. Holding the
// principal frame's shear at zero is the approximation: exact when the wrinkles follow the
// grain (or for an isotropic law), stiffer than the true relaxation otherwise.
class TensionFieldLinearBiot {
 public:
  TensionFieldLinearBiot(const FabricParameters& f, double compression_fraction)
      : stiffness_(f), compression_fraction_(compression_fraction) {}
  static const char* name() { return "linear biot, tension field"; }
  // W_eps = W_rel + eps (W - W_rel): the fraction eps of the law's own stiffness is kept
  // where the fabric is wrinkled or slack, so that a state with no tension across (a tube with
  // free ends) still has one equilibrium.
  template <class S>
  S energy(const S& c11, const S& c22, const S& c12) const {
    const std::array<S, 3> e = biot_strain(c11, c22, c12);
    const S w = full(e);
    const S relaxed = relaxed_energy(e, w);
    return compression_fraction_ == 0.0 ? relaxed : relaxed + compression_fraction_ * (w - relaxed);
  }
  double stiffness_scale() const { return stiffness_.largest(); }

 private:
  template <class S>
  S full(const std::array<S, 3>& e) const {
    return stiffness_.quadratic_energy(e[0], e[1], e[2]);
  }
  // W_rel of the Biot strain e, given the law's own energy w there.
  template <class S>
  S relaxed_energy(const std::array<S, 3>& e, const S& w) const {
    using std::sqrt;
    const S mean = 0.5 * (e[0] + e[1]);
    const S half_difference = 0.5 * (e[0] - e[1]);
    const double r2 = scalar_value(half_difference * half_difference + e[2] * e[2]);
    // An isotropic strain has no principal frame: taut when stretched, slack when shortened.
    if (r2 < 1e-24) return scalar_value(mean) > 0.0 ? w : S(0.0);
    const S r = sqrt(half_difference * half_difference + e[2] * e[2]);
    const S e1 = mean + r, e2 = mean - r;
    if (scalar_value(e1) <= 0.0) return S(0.0);
    // n1 at angle phi from the weft: cos 2 phi = (e11 - e22) / 2 r, sin 2 phi = e12 / r.
    // In Voigt order (11, 22, 2*12): n1 n1 = ((1 + c)/2, (1 - c)/2, s), n2 n2 = ((1 - c)/2,
    // (1 + c)/2, -s).
    const S c = half_difference / r, s = e[2] / r;
    const std::array<S, 3> v1 = {0.5 * (1.0 + c), 0.5 * (1.0 - c), s};
    const std::array<S, 3> v2 = {0.5 * (1.0 - c), 0.5 * (1.0 + c), -s};
    const S a11 = stiffness_.product(v1, v1), a12 = stiffness_.product(v1, v2),
            a22 = stiffness_.product(v2, v2);
    const double sigma1 = scalar_value(a11 * e1 + a12 * e2);
    const double sigma2 = scalar_value(a12 * e1 + a22 * e2);
    if (sigma1 >= 0.0 && sigma2 >= 0.0) return w;
    if (sigma2 < 0.0) return 0.5 * (a11 - a12 * a12 / a22) * e1 * e1;  // tension along n1
    // Tension along n2 with e1 > 0 > sigma1: only where A12 < 0 (a shear-stiff fabric).
    return 0.5 * (a22 - a12 * a12 / a11) * e2 * e2;
  }
  OrthotropicStiffness stiffness_;
  double compression_fraction_;
};

// St. Venant-Kirchhoff: second Piola-Kirchhoff stress linear in the Green strain (C - I)/2.
class StVenantKirchhoff {
 public:
  explicit StVenantKirchhoff(const FabricParameters& f) : stiffness_(f) {}
  static const char* name() { return "st venant kirchhoff"; }
  template <class S>
  S energy(const S& c11, const S& c22, const S& c12) const {
    return stiffness_.quadratic_energy(0.5 * (c11 - 1.0), 0.5 * (c22 - 1.0), 0.5 * c12);
  }
  double stiffness_scale() const { return stiffness_.largest(); }

 private:
  OrthotropicStiffness stiffness_;
};

// Incompressible neo-Hookean membrane: W = G t0 / 2 (tr C + 1/det C - 3); the thickness
// stretch 1/sqrt(det C) is eliminated by incompressibility (the law behind the paper's Eq. 8).
class IncompressibleNeoHookean {
 public:
  explicit IncompressibleNeoHookean(const FabricParameters& f)
      : modulus_N_per_m_(f.neo_hookean_shear_modulus_Pa * f.thickness_m) {}
  static const char* name() { return "neo hookean"; }
  template <class S>
  S energy(const S& c11, const S& c22, const S& c12) const {
    return 0.5 * modulus_N_per_m_ * (c11 + c22 + 1.0 / (c11 * c22 - c12 * c12) - 3.0);
  }
  // Small-strain uniaxial membrane stiffness of an incompressible solid: 3 G t0.
  double stiffness_scale() const { return 3.0 * modulus_N_per_m_; }

 private:
  double modulus_N_per_m_;
};

// Tensile curves (core/tensile_curves.h): the energy of measured force-strain curves, on the
// Biot strain as the linear Biot law, which it equals for straight curves.
class TensileCurveLaw {
 public:
  explicit TensileCurveLaw(const FabricParameters& f) : curves_(f.tensile_curves()) {}
  static const char* name() { return "tensile curves"; }
  template <class S>
  S energy(const S& c11, const S& c22, const S& c12) const {
    const std::array<S, 3> e = biot_strain(c11, c22, c12);
    return curves_.energy(e[0], e[1], e[2]);
  }
  double stiffness_scale() const { return curves_.stiffness_scale(); }

 private:
  TensileCurves curves_;
};

// Whether a law gives its energy's gradient by hand (energy_gradient(c11, c22, c12)).
template <class Law, class = void>
struct HasEnergyGradient : std::false_type {};
template <class Law>
struct HasEnergyGradient<
    Law, std::void_t<decltype(std::declval<const Law&>().energy_gradient(0.0, 0.0, 0.0))>>
    : std::true_type {};

// Differentiates a law's energy: variables v = (C11, C22, C12) with C21 = C12, so that
// S = (2 dW/dC11, 2 dW/dC22, dW/dC12) and D = M H M with H the Hessian in v, M = diag(2, 2, 1).
// A law with a hand-written gradient gives the stress from it.
template <class Law>
class DifferentiatedLaw final : public MaterialLaw {
 public:
  template <class... Arguments>
  explicit DifferentiatedLaw(const Arguments&... arguments) : law_(arguments...) {}
  std::string name() const override { return Law::name(); }
  double energy(const Mat2& C) const override { return law_.energy(C(0, 0), C(1, 1), C(0, 1)); }
  Mat2 stress(const Mat2& C) const override {
    if constexpr (HasEnergyGradient<Law>::value) {
      const std::array<double, 3> g = law_.energy_gradient(C(0, 0), C(1, 1), C(0, 1));
      Mat2 S;
      S << 2.0 * g[0], g[2], g[2], 2.0 * g[1];
      return S;
    }
    using D1 = Dual<3>;
    const D1 w =
        law_.energy(D1::variable(C(0, 0), 0), D1::variable(C(1, 1), 1), D1::variable(C(0, 1), 2));
    Mat2 S;
    S << 2.0 * w.grad[0], w.grad[2], w.grad[2], 2.0 * w.grad[1];
    return S;
  }
  Mat3 tangent(const Mat2& C) const override {
    using D1 = Dual<3>;
    using D2 = Dual<3, D1>;
    const double c[3] = {C(0, 0), C(1, 1), C(0, 1)};
    D2 v[3];
    for (int i = 0; i < 3; ++i) v[i] = D2::variable(D1::variable(c[i], i), i);
    const D2 w = law_.energy(v[0], v[1], v[2]);
    const double m[3] = {2.0, 2.0, 1.0};
    Mat3 D;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) D(i, j) = m[i] * m[j] * w.grad[i].grad[j];
    return D;
  }
  double stiffness_scale() const override { return law_.stiffness_scale(); }

 private:
  Law law_;
};

}  // namespace

std::vector<std::string> material_law_names() {
  return {LinearBiot::name(), StVenantKirchhoff::name(), IncompressibleNeoHookean::name(),
          TensileCurveLaw::name()};
}

std::string material_law_descriptions() {
  std::ostringstream out;
  out << "'linear biot': nominal stress linear in the Biot strain U - I (orthotropic; with zero "
         "Poisson ratio the paper's Eq. 7 holds exactly); "
      << "'st venant kirchhoff': 2nd Piola-Kirchhoff stress linear in the Green strain "
         "(orthotropic); "
      << "'neo hookean': incompressible, isotropic, shear modulus and thickness (the paper's "
         "Eq. 8); "
      << "'tensile curves': measured force-strain curves per direction (Tension curve weft, "
         "Tension curve warp), a Poisson coefficient that changes with strain (Poisson curve) "
         "and Shear stiffness; a free strip reproduces each curve";
  return out.str();
}

std::unique_ptr<MaterialLaw> make_material_law(const std::string& name,
                                               const FabricParameters& fabric) {
  fabric.validate();
  if (name == LinearBiot::name()) return std::make_unique<DifferentiatedLaw<LinearBiot>>(fabric);
  if (name == StVenantKirchhoff::name())
    return std::make_unique<DifferentiatedLaw<StVenantKirchhoff>>(fabric);
  if (name == IncompressibleNeoHookean::name())
    return std::make_unique<DifferentiatedLaw<IncompressibleNeoHookean>>(fabric);
  if (name == TensileCurveLaw::name())
    return std::make_unique<DifferentiatedLaw<TensileCurveLaw>>(fabric);
  std::string known;
  for (const auto& n : material_law_names()) known += " '" + n + "'";
  throw std::invalid_argument("Material/Law: unknown law '" + name + "'; known:" + known);
}

std::unique_ptr<MaterialLaw> make_tension_field_law(const std::string& name,
                                                    const FabricParameters& fabric,
                                                    double compression_fraction) {
  fabric.validate();
  if (!(compression_fraction >= 0.0 && compression_fraction <= 1.0))
    throw std::invalid_argument(
        "the fraction of the stiffness kept in compression must be in "
        "[0, 1], not " +
        std::to_string(compression_fraction));
  if (name == LinearBiot::name())
    return std::make_unique<DifferentiatedLaw<TensionFieldLinearBiot>>(fabric,
                                                                       compression_fraction);
  throw std::invalid_argument("the tension field relaxes Material/Law = '" +
                              std::string(LinearBiot::name()) + "' only, not '" + name + "'");
}

}  // namespace tightfit
