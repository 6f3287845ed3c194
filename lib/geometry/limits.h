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
  /// Young's modulus [Pa] of a gear material: 0.1 GPa (soft polymers) to 1500 GPa (above
  /// diamond's 1050 GPa), the range every contact and rating model of gearfem is meant for.
  void check_youngs_modulus(const std::string &entry, double E);

  /// The small-strain bound of every linear-elastic contact model of gearfem: the line-contact
  /// Hertz pressure at the pitch point with the whole torque on one pair (Johnson 1985, eq.
  /// 4.45), p0 = sqrt(w E* / (pi R*)), w = T / (r_b1 b), must keep p0 / E* <= 5 % (p0 ~ 5 GPa
  /// for steel, several times any yield stress). Throws InputError naming `entry` (a torque,
  /// [N m]) and the largest torque allowed. E* [Pa] of the pair (1/E* = 1/E'_1 + 1/E'_2),
  /// `curvature` = 1/R* at the pitch point [1/m].
  void check_small_strain(const std::string &entry, double torque, double base_radius1, double face_width,
                          double E_star, double curvature);
} // namespace gearfem::geometry::limits
