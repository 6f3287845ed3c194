#include "analytical/elastic.h"
#include "base/units.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::analytical
{
  namespace
  {
    using units::pi;
  }

  PlaneElastic plane_elastic(const Material &m, PlaneCondition c)
  {
    require_greater("Material/Young's modulus", m.E, 0.0, "Pa");
    if (!(m.nu > -1.0 && m.nu < 0.5))
      throw InputError("Material/Poisson's ratio", to_string_g(m.nu), "(-1, 0.5)");
    if (c == PlaneCondition::plane_stress)
      return {m.E, m.nu};
    return {m.E / (1.0 - m.nu * m.nu), m.nu / (1.0 - m.nu)};
  }

  double contact_modulus(const PlaneElastic &b1, const PlaneElastic &b2)
  {
    return 1.0 / (1.0 / b1.E + 1.0 / b2.E);
  }

  double HertzLineContact::pressure(double s) const
  {
    const double r = s / half_width;
    return std::abs(r) >= 1.0 ? 0.0 : peak_pressure * std::sqrt(1.0 - r * r);
  }

  HertzLineContact hertz_line_contact(double w, double R1, double R2, const PlaneElastic &b1,
                                      const PlaneElastic &b2)
  {
    require_greater("Hertz line contact/load per unit width", w, 0.0, "N/m");
    const double inv_R = 1.0 / R1 + 1.0 / R2;
    if (!(inv_R > 0.0) || !std::isfinite(inv_R))
      throw InputError("Hertz line contact/radii of curvature",
                       to_string_g(R1) + ", " + to_string_g(R2) + " m",
                       "1/R1 + 1/R2 > 0 (convex-convex or convex in a larger concave)");
    HertzLineContact h;
    h.reduced_radius = 1.0 / inv_R;
    const double Es = contact_modulus(b1, b2);
    h.half_width = std::sqrt(4.0 * w * h.reduced_radius / (pi * Es));
    h.peak_pressure = 2.0 * w / (pi * h.half_width);
    h.max_shear = 0.300 * h.peak_pressure;
    h.max_shear_depth = 0.786 * h.half_width;
    return h;
  }

  double weber_hertz_approach(double F, double b, double a, double h, const PlaneElastic &body)
  {
    return 2.0 * F / (pi * b * body.E) * (std::log(2.0 * h / a) - 0.5 * body.nu);
  }

  double hertz_stiffness_pe(const PlaneElastic &b1, const PlaneElastic &b2, double b)
  {
    return 0.5 * pi * b * contact_modulus(b1, b2);
  }
} // namespace gearfem::analytical
