#pragma once
// Physical constants used across layers (SI).
namespace pound {

/// Standard gravity [m/s^2] (CGPM 1901): converts records in g and gives gravity loads m g.
inline constexpr double kGravity = 9.80665;

}  // namespace pound
