// Constraints on named vertex groups as the backends apply them, and the ring circumference
// that replaced the garment's own field.
#include "core/constrained_directions.h"
#include "core/tube_garment.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace tightfit {
namespace {

SimulationMesh tube_mesh() {
  return weld(make_tube_garment("T", 0.157, 0.24, 2, MeshSpacing{}));
}

TEST(ConstrainedDirections, HeldVerticesLoseOnlyTheComponentAlongTheDirection) {
  const SimulationMesh mesh = tube_mesh();
  const Vec3 axis = Vec3(1, 2, 2) / 3.0;  // unit
  const ConstrainedDirections c({held_along(mesh, "bottom", 3.0 * axis)}, mesh.n_vertices);
  const std::vector<int>& bottom = mesh.vertex_groups.at("bottom");
  const Vec3 force(0.3, -1.0, 2.0);
  for (int v = 0; v < mesh.n_vertices; ++v) {
    Vec3 f = force;
    c.remove_constrained(v, f);
    const bool held = std::binary_search(bottom.begin(), bottom.end(), v);
    EXPECT_EQ(c.constrained(v), held);
    // Held: the component along the axis is gone, the rest kept (a projection).
    EXPECT_NEAR(f.dot(axis), held ? 0.0 : force.dot(axis), 1e-15);
    EXPECT_NEAR((f - force).cross(axis).norm(), 0.0, 1e-15);
  }
}

TEST(ConstrainedDirections, FixedVerticesLoseEveryComponentAndOverlapsAddNothing) {
  const SimulationMesh mesh = tube_mesh();
  // "top" held along z and fixed as well: every top vertex gets three independent
  // directions, not four.
  const ConstrainedDirections c({held_along(mesh, "top", Vec3::UnitZ()), fixed_group(mesh, "top")},
                                mesh.n_vertices);
  for (int v : mesh.vertex_groups.at("top")) {
    EXPECT_EQ(c.directions(v).size(), 3u);
    Vec3 f(1.0, -2.0, 3.0);
    c.remove_constrained(v, f);
    EXPECT_NEAR(f.norm(), 0.0, 1e-15);
  }
}

TEST(ConstrainedDirections, EdgeMidpointsShareWhatBothEndsHold) {
  const SimulationMesh mesh = tube_mesh();
  const int held = mesh.vertex_groups.at("bottom").front();
  const int fixed = mesh.vertex_groups.at("top").front();
  ConstrainedDirections c({held_along(mesh, "bottom", Vec3::UnitZ()), fixed_group(mesh, "top")},
                          mesh.n_vertices);
  int free_vertex = 0;
  while (c.constrained(free_vertex)) ++free_vertex;
  c.add_shared(held, held);          // both ends held along z: held along z
  c.add_shared(held, fixed);         // z is among the fixed end's directions: held along z
  c.add_shared(fixed, free_vertex);  // one end free: free
  ASSERT_EQ(c.size(), mesh.n_vertices + 3);
  for (int k = 0; k < 2; ++k) {
    ASSERT_EQ(c.directions(mesh.n_vertices + k).size(), 1u);
    EXPECT_NEAR(std::abs(c.directions(mesh.n_vertices + k)[0].z()), 1.0, 1e-15);
  }
  EXPECT_FALSE(c.constrained(mesh.n_vertices + 2));
}

TEST(ConstrainedDirections, BadGroupsAndDirectionsAreNamed) {
  const SimulationMesh mesh = tube_mesh();
  try {
    held_along(mesh, "waist", Vec3::UnitZ());
    FAIL() << "an unknown group was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'waist'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bottom"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ConstrainedDirections({held_along(mesh, "top", Vec3::Zero())}, mesh.n_vertices),
               std::invalid_argument);
  VertexConstraint outside = fixed_group(mesh, "top");
  outside.vertices.push_back(mesh.n_vertices);
  EXPECT_THROW(ConstrainedDirections({outside}, mesh.n_vertices), std::invalid_argument);
}

TEST(ConstrainedDirections, GroupAllHoldsEveryVertex) {
  const SimulationMesh mesh = weld(make_tube_garment("T", 0.157, 0.24, 2, MeshSpacing{}));
  const VertexConstraint all = held_along(mesh, "all", Vec3::UnitZ());
  ASSERT_EQ(static_cast<int>(all.vertices.size()), mesh.n_vertices);
  for (int v = 0; v < mesh.n_vertices; ++v) EXPECT_EQ(all.vertices[v], v);
}

TEST(RingCircumference, TubesHaveTheirPanelsWidthsOtherGarmentsNone) {
  EXPECT_NEAR(ring_circumference_m(make_tube_garment("T", 0.157, 0.24, 2, MeshSpacing{})), 0.314,
              1e-12);
  EXPECT_NEAR(ring_circumference_m(make_tube_garment("3", 0.1, 0.2, 3, MeshSpacing{0.01, 0.02})),
              0.3, 1e-12);
  Garment open = make_tube_garment("open", 0.157, 0.24, 2, MeshSpacing{});
  open.seams.pop_back();  // the tube cut open: a flat garment of two panels
  EXPECT_EQ(ring_circumference_m(open), 0.0);
  Garment sheet;
  sheet.panels.push_back(make_rectangle_panel("sheet", 0.2, 0.2, MeshSpacing{0.02, 0.02}));
  EXPECT_EQ(ring_circumference_m(sheet), 0.0);
}

}  // namespace
}  // namespace tightfit
