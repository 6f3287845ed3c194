#include "geometry/limits.h"

#include "base/errors.h"
#include "base/units.h"

#include <cmath>

namespace gearfem::geometry::limits
{
  void check_teeth(const std::string &entry, int z) { require_range(entry, z, min_teeth, max_teeth); }

  void check_module(const std::string &entry, double m) { require_greater(entry, m / units::mm, 0.0, "mm"); }

  void check_pressure_angle(const std::string &entry, double alpha)
  {
    require_range(entry, alpha / units::deg, min_pressure_angle_deg, max_pressure_angle_deg, "deg");
  }

  void check_addendum(const std::string &entry, double h_a) { require_range(entry, h_a, min_addendum, max_addendum); }

  void check_face_width(const std::string &entry, double b) { require_greater(entry, b / units::mm, 0.0, "mm"); }

  void check_profile_shift(const std::string &entry, double x)
  {
    require_range(entry, x, min_profile_shift, max_profile_shift);
  }

  void check_youngs_modulus(const std::string &entry, double E)
  {
    require_range(entry, E / units::GPa, 0.1, 1500.0, "GPa");
  }

  void check_small_strain(const std::string &entry, double T, double base_radius1, double face_width, double E_star,
                          double curvature)
  {
    const double limit = 0.05;
    const double w     = T / base_radius1 / face_width;
    const double p0    = std::sqrt(w * E_star * curvature / units::pi);
    if (p0 / E_star <= limit)
      return;
    const double T_max = T * (limit * E_star / p0) * (limit * E_star / p0);
    throw InputError(entry, to_string_g(T) + " N m", "<= " + to_string_g(T_max) + " N m for this pair and material",
                     "The estimated Hertz pressure at the pitch point is p0 = " + to_string_g(p0 / 1e6) +
                       " MPa, p0/E* = " + to_string_g(100 * p0 / E_star) +
                       " %: beyond the small-strain range of the linear-elastic contact model (limit p0/E* <= 5 %)");
  }
} // namespace gearfem::geometry::limits
