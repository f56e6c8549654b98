// types.h - the names every stage of the core shares: Eigen's fixed-size vectors and matrices under
// short names, and the mathematical constants, defined once.
#pragma once

#include <Eigen/Dense>

namespace uc {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

constexpr double kPi = 3.14159265358979323846;

}  // namespace uc
