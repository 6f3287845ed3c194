#include "geometry/limits.h"

#include "base/errors.h"
#include "base/units.h"

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
} // namespace gearfem::geometry::limits
