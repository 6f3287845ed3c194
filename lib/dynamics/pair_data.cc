#include "dynamics/pair_data.h"
#include "base/units.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::dynamics
{
  PairData standard_pair(int z1, int z2, double m, double alpha, double ha, double cf1,
                         double cf2, double delta_a)
  {
    if (z1 < 5 || z2 < 5)
      throw InputError("Pinion/gear teeth", std::to_string(z1) + "/" + std::to_string(z2), ">= 5");
    require_greater("Module", m, 0.0, "m");
    require_range("Pressure angle", alpha, 0.1, 0.8, "rad");
    PairData p;
    p.z1 = z1, p.z2 = z2;
    const double r1 = m * z1 / 2, r2 = m * z2 / 2;
    p.r_b1 = r1 * std::cos(alpha), p.r_b2 = r2 * std::cos(alpha);
    p.r_a1 = r1 + ha * m, p.r_a2 = r2 + ha * m;
    p.center_distance = r1 + r2 + delta_a;
    const double ca = (p.r_b1 + p.r_b2) / p.center_distance;
    if (!(ca < 1.0))
      throw InputError("Centre distance change", to_string_g(delta_a / 1e-3) + " mm",
                       "> " + to_string_g((p.r_b1 + p.r_b2 - r1 - r2) / 1e-3) + " mm");
    const double aw = std::acos(ca);
    p.working_pressure_angle = aw;
    const double pb = 2 * units::pi * p.r_b1 / z1;
    const double g1 = std::sqrt(p.r_a1 * p.r_a1 - p.r_b1 * p.r_b1);
    const double g2 = std::sqrt(p.r_a2 * p.r_a2 - p.r_b2 * p.r_b2);
    const double L = p.center_distance * std::sin(aw); // T1T2
    p.contact_ratio = (g1 + g2 - L) / pb;
    if (!(p.contact_ratio >= 1.0 && p.contact_ratio < 2.0))
      throw InputError("contact ratio", to_string_g(p.contact_ratio), "[1, 2)",
                       "the dynamic models support one or two pairs in contact");
    const double gA = L - g2, gC = p.r_b1 * std::tan(aw);
    p.theta_A = (gA - gC) / p.r_b1;
    auto inv = [](double a) { return std::tan(a) - a; };
    p.backlash = std::cos(alpha) * units::pi * m * (1 - cf1 - cf2) +
                 2 * (inv(aw) - inv(alpha)) * (p.r_b1 + p.r_b2);
    p.thickness_angle1 = 2 * units::pi * cf1 / z1 + 2 * (inv(alpha) - inv(aw));
    return p;
  }
} // namespace gearfem::dynamics
