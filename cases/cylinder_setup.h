// Builds what a cylinder case simulates from its parameters: the garment, its mesh, the law,
// the growing cylinder, and the Problem both backends solve.
#pragma once

#include "cases/case_parameters.h"
#include "contact/cylinder.h"
#include "core/backend.h"
#include "core/garment.h"

#include <memory>
#include <vector>

namespace tightfit {

struct CylinderSetup {
  CaseParameters parameters;
  Garment garment;
  SimulationMesh mesh;
  std::unique_ptr<MaterialLaw> law;
  std::unique_ptr<Cylinder> body;
  Problem problem;             // points into the members above: the setup never moves
  double rest_radius_m = 0.0;  // R0 = circumference / 2 pi
  double mean_edge_length_m = 0.0;
  std::vector<double> alphas;  // every load step's r / R0, the first the settling one

  double radius_at(double alpha) const { return alpha * rest_radius_m; }
  // The start: the sewn tube round the cylinder, at R0 or just outside the body.
  std::vector<Vec3> initial_positions() const;
  // Sets the body for load step `step` and returns that step's description.
  LoadStep prepare_step(int step);
};

// Throws std::invalid_argument with a message naming the parameter at fault (a garment that
// can never press on the body, a bad value).
std::unique_ptr<CylinderSetup> make_cylinder_setup(const CaseParameters& parameters);

}  // namespace tightfit
