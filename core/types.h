// Small fixed-size linear algebra types shared by every module.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, rotations

#include <array>

namespace tightfit {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;
// Membrane deformation gradient F = dx/dX: 3D position per 2D pattern coordinate.
using Mat32 = Eigen::Matrix<double, 3, 2>;

// Three vertex indices of a triangle, counter-clockwise in its panel's plane.
using Triangle = std::array<int, 3>;

}  // namespace tightfit
