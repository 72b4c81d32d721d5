// The held turn in Newton's system (fem/held_turn_system.h) on the paper's tube round a
// cylinder, every vertex held along the axis z. Closed forms: the residual loses exactly the
// part along the turn's reaction M t (a pure torque about the axis) and keeps a torque-free
// force (a radial stretch, a slide across the axis) unchanged; the bordered increment has no
// mean turn, and with a tangent K = M (so that K^-1 M t = t) a rigid turn's increment is removed
// whole while a stretch and a slide pass unchanged.
#include "fem/fem_constraints.h"
#include "fem/held_turn_system.h"
#include "tube_problem.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <functional>

namespace tightfit {
namespace {

int start_mpi() {
  static int argc = 1;
  static char program[] = "test_held_turn_system";
  static char* arguments[] = {program, nullptr};
  static char** argv = arguments;
  static dealii::Utilities::MPI::MPI_InitFinalize runtime(argc, argv, 1);
  return 0;
}

using PetscVector = dealii::PETScWrappers::MPI::Vector;
using Field = std::function<Vec3(const Vec3& x)>;

struct HeldTube {
  int started = start_mpi();  // before the PETSc objects below
  testing::TubeCase tube{"linear biot", EndCondition::free_ends};
  std::unique_ptr<ReferenceMesh> pattern;
  NewtonSystem system;
  DofVector x;
  std::vector<Vec3> positions;

  HeldTube() {
    VertexConstraint all;
    all.group = "all";
    all.direction = Vec3::UnitZ();
    for (int v = 0; v < tube.mesh.n_vertices; ++v) all.vertices.push_back(v);
    tube.problem.constraints = {all};
    pattern = std::make_unique<ReferenceMesh>(tube.problem, 1, MPI_COMM_WORLD);
    positions = tube.placed(1.02 * tube.rest_radius_m);
    build_constraints_and_system(*pattern, tube.problem, positions, MPI_COMM_WORLD, system);
    x = pattern->dof_positions(positions);
  }

  // The nodes' centre weighted by their rest areas (the held turn's masses).
  Vec3 centre() const {
    Vec3 c = Vec3::Zero();
    double w = 0.0;
    for (const int node : pattern->owned_nodes()) {
      c += pattern->node_contact_area_m2()[node] * pattern->node_position(x, node);
      w += pattern->node_contact_area_m2()[node];
    }
    return c / w;
  }

  // The nodal forces `force` (scaled by each node's rest area when `per_area`) on the free DoFs,
  // as the assembly sums them: C^T f.
  PetscVector forces(const Field& force) const {
    PetscVector rhs(pattern->owned_dofs(), MPI_COMM_WORLD);
    for (const int node : pattern->owned_nodes()) {
      const Vec3 f = pattern->node_contact_area_m2()[node] * force(pattern->node_position(x, node));
      const DofTriple& d = pattern->carrier(node);
      dealii::Vector<double> local(3);
      for (int c = 0; c < 3; ++c) local[c] = f[c];
      system.constraints.distribute_local_to_global(
          local, std::vector<GlobalDof>(d.begin(), d.end()), rhs);
    }
    rhs.compress(dealii::VectorOperation::add);
    return rhs;
  }

  // A displacement field on the free DoFs (the constrained ones follow from them).
  PetscVector displacement(const Field& u) const {
    PetscVector v(pattern->owned_dofs(), MPI_COMM_WORLD);
    for (const int node : pattern->owned_nodes()) {
      const Vec3 value = u(pattern->node_position(x, node));
      const DofTriple& d = pattern->carrier(node);
      for (int c = 0; c < 3; ++c)
        if (!system.constraints.is_constrained(d[c])) v(d[c]) = value[c];
    }
    v.compress(dealii::VectorOperation::insert);
    return v;
  }

  // K z = b with K = M, the rest areas on each free DoF: z_j = b_j / w(j).
  void solve_with_masses(const PetscVector& b, PetscVector& z) const {
    z = b;
    for (const int node : pattern->owned_nodes())
      for (const GlobalDof j : pattern->carrier(node))
        if (!system.constraints.is_constrained(j))
          z(j) = b(j) / pattern->node_contact_area_m2()[node];
    z.compress(dealii::VectorOperation::insert);
  }
};

double difference(const PetscVector& a, const PetscVector& b) {
  PetscVector d = a;
  d -= b;
  return d.linfty_norm();
}

TEST(HeldTurnSystem, ActiveWhenEveryVertexIsHeldAlongOneDirection) {
  HeldTube held;
  EXPECT_TRUE(HeldTurnSystem(*held.pattern, false).active());
  testing::TubeCase free_tube("linear biot", EndCondition::held_ends);
  const ReferenceMesh ends_only(free_tube.problem, 1, MPI_COMM_WORLD);
  EXPECT_FALSE(HeldTurnSystem(ends_only, false).active());
}

TEST(HeldTurnSystem, TheResidualLosesExactlyItsTorqueAboutTheAxis) {
  HeldTube held;
  HeldTurnSystem turn(*held.pattern, false);
  const Vec3 c = held.centre();
  const Vec3 z = Vec3::UnitZ();
  const Field torque = [&](const Vec3& p) { return Vec3(3.0 * z.cross(p - c)); };
  const Field stretch = [&](const Vec3& p) {
    Vec3 r = p - c;
    r.z() = 0.0;
    return Vec3(2.0 * r);
  };
  const Field slide = [](const Vec3&) { return Vec3(0.7, -0.4, 0.0); };
  const Field all = [&](const Vec3& p) { return Vec3(torque(p) + stretch(p) + slide(p)); };
  const Field kept = [&](const Vec3& p) { return Vec3(stretch(p) + slide(p)); };
  held.system.rhs = held.forces(all);
  turn.project_residual(held.x, false, held.system);
  const PetscVector expected = held.forces(kept);
  // Round-off: the forces are of order 1e-4 N (rest areas ~5e-5 m^2 times 2 to 3 N/m^3 x 5 cm).
  EXPECT_LT(difference(held.system.rhs, expected), 1e-12 * expected.linfty_norm());
  EXPECT_GT(held.forces(torque).linfty_norm(), 0.1 * expected.linfty_norm());
}

TEST(HeldTurnSystem, TheIncrementHasNoMeanTurn) {
  HeldTube held;
  HeldTurnSystem turn(*held.pattern, false);
  const Vec3 c = held.centre();
  const Vec3 z = Vec3::UnitZ();
  const Field rotation = [&](const Vec3& p) { return Vec3(0.01 * z.cross(p - c)); };
  const Field stretch = [&](const Vec3& p) {
    Vec3 r = p - c;
    r.z() = 0.0;
    return Vec3(0.02 * r);
  };
  const Field slide = [](const Vec3&) { return Vec3(1e-3, 2e-3, 0.0); };
  const Field kept = [&](const Vec3& p) { return Vec3(stretch(p) + slide(p)); };
  const Field all = [&](const Vec3& p) { return Vec3(rotation(p) + kept(p)); };
  held.system.rhs = held.forces(all);  // only for project_residual to build the border
  turn.project_residual(held.x, false, held.system);
  const auto solve = [&](const PetscVector& b, PetscVector& z_out) {
    held.solve_with_masses(b, z_out);
  };
  // Of a turn, a stretch and a slide the rigid turn goes whole (K = M: K^-1 M t = t).
  held.system.increment = held.displacement(all);
  EXPECT_NEAR(turn.mean_turn(held.system.increment), 0.01, 1e-12);
  turn.constrain_increment(held.system, solve);
  const PetscVector expected = held.displacement(kept);
  EXPECT_LT(difference(held.system.increment, expected), 1e-12 * expected.linfty_norm());
  EXPECT_NEAR(turn.mean_turn(held.system.increment), 0.0, 1e-14);
}

}  // namespace
}  // namespace tightfit
