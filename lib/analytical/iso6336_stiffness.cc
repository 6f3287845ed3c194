#include "analytical/iso6336_stiffness.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace gearfem::analytical::iso6336
{
  namespace
  {
    constexpr double deg = units::deg;
  } // namespace

  double q_prime(double zn1, double zn2, double x1, double x2)
  {
    const double i1 = 1.0 / zn1, i2 = std::isfinite(zn2) ? 1.0 / zn2 : 0.0;
    return 0.04723 + 0.15551 * i1 + 0.25791 * i2 - 0.00635 * x1 - 0.11654 * x1 * i1 -
           0.00193 * x2 - 0.24188 * x2 * i2 + 0.00529 * x1 * x1 + 0.00182 * x2 * x2;
  }

  Stiffness mesh_stiffness(const StiffnessInput &in)
  {
    if (in.z1 < 5)
      throw InputError("Gear 1/Number of teeth", std::to_string(in.z1), ">= 5");
    if (in.z2 > -5 && in.z2 < 5)
      throw InputError("Gear 2/Number of teeth", std::to_string(in.z2), ">= 5 (or <= -5 internal)");
    require_range("Rack/Pressure angle", in.alpha_n / deg, 10.0, 35.0, "deg");
    require_range("Helix angle", in.beta / deg, 0.0, 45.0, "deg");
    require_range("Rating/Rim ratio b_s/b", in.rim_ratio, 0.0, 1.0);
    // Virtual numbers of teeth z_n = z / (cos^2 beta_b cos beta) (ISO 21771; the ISO/TR 6336-30
    // example 1 values of c'_th follow from it, not from z / cos^3 beta).
    const double alpha_t = std::atan(std::tan(in.alpha_n) / std::cos(in.beta));
    const double beta_b  = std::atan(std::tan(in.beta) * std::cos(alpha_t));
    const double cz  = std::pow(std::cos(beta_b), 2) * std::cos(in.beta);
    const double zn1 = in.z1 / cz;
    const double zn2 = in.z2 < 0 ? std::numeric_limits<double>::infinity() : in.z2 / cz;
    Stiffness s;
    s.q_prime = q_prime(zn1, zn2, in.x1, in.x2);
    s.c_th = 1.0 / s.q_prime;
    s.C_M = in.C_M;
    // C_R (ISO 6336-1 eq. 73): 1 for solid gears, else 1 + ln(b_s/b)/(5 exp(s_R/(5 m_n))).
    s.C_R = 1.0;
    if (in.rim_ratio < 1.0)
      {
        const double bs = std::max(0.2, in.rim_ratio);
        const double sr = std::max(1.0, in.rim_thickness / in.module);
        s.C_R = 1.0 + std::log(bs) / (5.0 * std::exp(sr / 5.0));
      }
    // C_B (eq. 74), mean of the two basic racks.
    auto cb = [&](double hfp) {
      return (1.0 + 0.5 * (1.2 - hfp)) * (1.0 - 0.02 * (20.0 - in.alpha_n / deg));
    };
    s.C_B = 0.5 * (cb(in.h_fP1) + cb(in.h_fP2));
    // Load correction (eq. 70) below F_t K_A/b = 100 N/mm.
    const double w = in.load_per_width / 1e3; // N/mm
    s.load_factor = (in.load_per_width > 0.0 && w < 100.0) ? std::pow(w / 100.0, 0.25) : 1.0;
    s.c_prime = s.c_th * s.C_M * s.C_R * s.C_B * std::cos(in.beta) * s.load_factor;
    require_greater("contact ratio eps_alpha", in.eps_alpha, 0.0);
    s.c_gamma_alpha = s.c_prime * (0.75 * in.eps_alpha + 0.25);
    s.c_gamma_beta = 0.85 * s.c_gamma_alpha;
    return s;
  }

  double face_load_factor_method_c(double F_beta_y, double c_gamma_beta, double F_m_over_b)
  {
    if (!(F_m_over_b > 0) || !(F_beta_y >= 0) || !(c_gamma_beta > 0))
      throw InputError("face load factor", to_string_g(F_beta_y) + ", " + to_string_g(c_gamma_beta) + ", " +
                                             to_string_g(F_m_over_b),
                       "F_beta_y >= 0, c_gamma_beta > 0 and F_m/b > 0");
    const double r = F_beta_y * c_gamma_beta / F_m_over_b;
    const double k = 1 + 0.5 * r;
    return k <= 2 ? k : std::sqrt(2 * r);
  }
} // namespace gearfem::analytical::iso6336
