#pragma once
// The allowed ranges of the gear-geometry inputs, stated once for every command that reads a
// gear (profile, solve, rate, calibrate, dynamics, optimise, gearbox): the checks throw an
// InputError naming the entry the caller passes (its own section path), with the same range
// text everywhere, and the parameter descriptions print the same ranges (geometry/parameters.h,
// declare_* entries). Light layer. SI values.
#include <string>

namespace gearfem::geometry::limits
{
  inline constexpr int min_teeth = 5, max_teeth = 10000;
  inline constexpr double min_pressure_angle_deg = 10, max_pressure_angle_deg = 35;
  inline constexpr double min_addendum = 0.5, max_addendum = 1.5; ///< h_aP* [module]
  inline constexpr double min_profile_shift = -5, max_profile_shift = 5;

  void check_teeth(const std::string &entry, int z);
  void check_module(const std::string &entry, double m);             ///< [m], > 0
  void check_pressure_angle(const std::string &entry, double alpha); ///< [rad]
  void check_addendum(const std::string &entry, double h_a);         ///< [module]
  void check_face_width(const std::string &entry, double b);         ///< [m], > 0
  void check_profile_shift(const std::string &entry, double x);      ///< [module]
} // namespace gearfem::geometry::limits
