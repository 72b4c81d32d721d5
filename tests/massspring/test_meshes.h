// Small meshes and deformed states shared by the mass-spring tests.
#pragma once

#include "core/backend.h"
#include "core/garment.h"
#include "core/material.h"
#include "core/rectangle_panel.h"
#include "core/types.h"

#include <memory>
#include <random>
#include <string>
#include <vector>

namespace tightfit::test {

// One rectangular panel, welded (no seams), optionally with its grain turned.
inline SimulationMesh panel_mesh(double width_m, double height_m, const MeshSpacing& spacing,
                                 double grain_angle_rad = 0.0) {
  Garment g;
  g.name = "panel";
  g.panels.push_back(make_rectangle_panel("p", width_m, height_m, spacing));
  g.panels.back().grain_angle_rad = grain_angle_rad;
  return weld(g);
}

// A panel with its fabric and law, wired into a Problem (no body): the setup most solver tests
// start from. Built in place, since the Problem points at the members.
struct PanelProblem {
  PanelProblem(double width_m, double height_m, const MeshSpacing& spacing,
               const std::string& law_name = "linear biot")
      : mesh(panel_mesh(width_m, height_m, spacing)), law(make_material_law(law_name, fabric)) {
    problem.mesh = &mesh;
    problem.law = law.get();
    problem.fabric = &fabric;
  }
  PanelProblem(const PanelProblem&) = delete;
  PanelProblem& operator=(const PanelProblem&) = delete;

  SimulationMesh mesh;
  FabricParameters fabric;
  std::unique_ptr<MaterialLaw> law;
  Problem problem;
};

// The mesh's flat layout in the z = 0 plane.
inline std::vector<Vec3> flat_positions(const SimulationMesh& mesh) {
  std::vector<Vec3> x(mesh.n_vertices);
  for (int u = 0; u < mesh.n_unwelded_vertices(); ++u)
    x[mesh.welded_index[u]] =
        Vec3(mesh.layout_positions_m[u].x(), mesh.layout_positions_m[u].y(), 0.0);
  return x;
}

// A stretched, sheared and randomly perturbed 3D state of the flat layout (`jitter_m` the
// amplitude of the random part).
inline std::vector<Vec3> deformed_positions(const SimulationMesh& mesh, double jitter_m,
                                            unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Mat3 stretch;
  stretch << 1.3, 0.15, 0.0, -0.05, 1.1, 0.0, 0.1, 0.2, 1.0;
  std::vector<Vec3> x = flat_positions(mesh);
  for (Vec3& p : x) {
    p = stretch * p;
    p += jitter_m * Vec3(uniform(random), uniform(random), uniform(random));
  }
  return x;
}

inline Mat3 some_rotation() {
  return (Eigen::AngleAxisd(0.7, Vec3(1.0, -2.0, 0.5).normalized()) *
          Eigen::AngleAxisd(-1.1, Vec3::UnitZ()))
      .toRotationMatrix();
}

}  // namespace tightfit::test
