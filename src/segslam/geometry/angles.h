#pragma once

#include <numbers>

namespace segslam::geometry {

inline constexpr double kPi = std::numbers::pi;
// Multiply degrees by this to get radians.
inline constexpr double kDegree = kPi / 180.0;

}  // namespace segslam::geometry
