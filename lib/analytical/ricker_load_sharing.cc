#include "analytical/ricker_load_sharing.h"
#include "base/units.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::analytical
{
  namespace
  {
    using units::pi;
  }

  RickerSemiAnalytical::RickerSemiAnalytical(InvoluteTooth p, InvoluteTooth g, const Material &m1,
                                               const Material &m2, double b, const PairLine &line,
                                               double k_mean, const PairModelOptions &o, double c_x)
    : t_{std::move(p), std::move(g)}
    , e_{plane_elastic(m1, o.plane), plane_elastic(m2, o.plane)}
    , b_(b)
    , k_mean_(k_mean)
    , c_x_(c_x)
    , line_(line)
    , opt_(o)
  {
    require_greater("Ricker load-sharing model: mean mesh stiffness", k_mean, 0.0, "N/m");
    for (int i = 0; i < 2; ++i)
      {
        const ToothBeam &bm = t_[i].beam;
        K1_[i] = bm.thickness(0.0);
        // Least squares of ln(t/K1) = -K2 psi over the loaded part of the tooth.
        const double top = 0.9 * bm.height;
        double num = 0, den = 0;
        for (int k = 1; k <= 200; ++k)
          {
            const double psi = top * k / 200.0;
            num += psi * std::log(bm.thickness(psi) / K1_[i]);
            den += psi * psi;
          }
        K2_[i] = -num / den;
        const double r = i == 0 ? std::hypot(line.rb1, line.g_C) : std::hypot(line.rb2, line.length - line.g_C);
        h_C_[i] = involute_load(t_[i], r).depth_to_axis();
      }
  }

  double RickerSemiAnalytical::tooth_compliance(int i, double g) const
  {
    // Load angle on AB (eq. 3.18) and Psi = R_g/cos(phi_F) - R_min.
    const double rb = i == 0 ? line_.rb1 : line_.rb2;
    const double roll = (i == 0 ? g : line_.length - g) / rb;
    const double phi = roll - t_[i].psi_b;
    const double Psi = rb / std::cos(phi) - t_[i].beam.root_radius;
    const double c2 = std::cos(phi) * std::cos(phi);
    const double nu = e_[i].nu, K1 = K1_[i], K2 = K2_[i];
    const double I1 = Psi / K1;                               // eq. 3.22
    const double I2 = 4.0 * Psi / (9.0 * K1 * K1 * K1 * K2 * K2); // eq. 3.23
    const double Cb = 12.0 * (I2 * c2 + (0.2 * (1.0 + nu) + (1.0 - c2) / 12.0) * I1); // eq. 3.24
    const double nps = e_[i].nu_plane_strain();
    const double Cf = odonnell_foundation_coefficient(Psi / K1, phi, nps, opt_.odonnell) / (1.0 - nps * nps);
    return (Cb + Cf) / (e_[i].E * b_);
  }

  double RickerSemiAnalytical::pair_stiffness(double g, double x) const
  {
    require_greater("Ricker load-sharing model: compression", x, 0.0, "m");
    const double F = k_mean_ * x; // eq. 3.30
    const HertzLineContact h = hertz_line_contact(F / b_, line_.g_C, line_.length - line_.g_C, e_[0], e_[1]);
    const double CH = (weber_hertz_approach(F, b_, h.half_width, h_C_[0], e_[0]) +
                       weber_hertz_approach(F, b_, h.half_width, h_C_[1], e_[1])) / F;
    return 1.0 / (tooth_compliance(0, g) + tooth_compliance(1, g) + CH);
  }

  double RickerSemiAnalytical::ricker_weight(double phi1, double x) const
  {
    const double wA = (line_.g_A - line_.g_C) / line_.rb1, wB = (line_.g_E - line_.g_C) / line_.rb1;
    const double pitch = line_.base_pitch / line_.rb1; // 2 pi/z1
    const double fm = std::sqrt(3.0) / (pi * (2.0 * pitch - (wB - wA) - c_x_ * x));
    const double fc = 2.0 * fm;
    const double d = phi1 - 0.5 * (wA + wB);
    return (1.0 - 2.0 * pi * pi * fm * fm * d * d) * std::exp(-pi * pi * fc * fc * d * d);
  }

  double RickerSemiAnalytical::load(double phi1, double x) const
  {
    if (!(x > 0.0))
      return 0.0;
    const double pitch = line_.base_pitch / line_.rb1;
    const double other = phi1 - (phi1 >= 0.0 ? 1.0 : -1.0) * pitch; // eq. 3.45
    const auto K = [&](double phi) { return pair_stiffness(line_.g_C + line_.rb1 * phi, x); };
    return (K(phi1) + (1.0 - ricker_weight(phi1, x)) * K(other)) * x;
  }
} // namespace gearfem::analytical
