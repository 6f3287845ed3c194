// The mean friction coefficient laws and Ohlendorf's tooth loss factor (analytical/friction.h).
#include "analytical/friction.h"

#include "base/errors.h"
#include "base/units.h"

#include <algorithm>
#include <cmath>

namespace gearfem::analytical::friction
{
  Law law_from_string(const std::string &s)
  {
    if (s == "constant")
      return Law::constant;
    if (s == "ISO/TR 14179-2")
      return Law::iso_14179_2;
    if (s == "AGMA 925")
      return Law::agma_925;
    throw InputError("Contact/Friction law", s, "constant | ISO/TR 14179-2 | AGMA 925");
  }

  const char *to_string(Law law)
  {
    return law == Law::constant ? "constant" : law == Law::iso_14179_2 ? "ISO/TR 14179-2" : "AGMA 925";
  }

  void check(const LawInputs &in)
  {
    require_range("Contact/Friction coefficient", in.mu, 0.0, 1.0);
    require_range("Contact/Pinion speed", in.pinion_speed * 30.0 / units::pi, 1e-3, 1e6, "rpm");
    const std::string why = std::string("required by Friction law = ") + to_string(in.law);
    const auto need = [&](const char *entry, double v, double lo, double hi, const char *unit) {
      if (!(v >= lo && v <= hi))
        throw InputError(entry, to_string_g(v) + " " + unit, "[" + to_string_g(lo) + ", " + to_string_g(hi) + "] " + unit,
                         why);
    };
    if (in.law == Law::iso_14179_2)
      {
        need("Contact/Oil viscosity", in.eta_oil * 1e3, 0.1, 1e5, "mPa s");
        need("Contact/Roughness gear 1", in.Ra1 * 1e6, 0.01, 10.0, "um");
        need("Contact/Roughness gear 2", in.Ra2 * 1e6, 0.01, 10.0, "um");
        need("Contact/Lubricant factor", in.X_L, 0.1, 2.0, "-");
      }
    if (in.law == Law::agma_925)
      {
        need("Contact/Roughness gear 1", in.Ra1 * 1e6, 0.01, 1.0, "um");
        need("Contact/Roughness gear 2", in.Ra2 * 1e6, 0.01, 1.0, "um");
      }
  }

  PitchPoint pitch_point(const geometry::MeshingPair &pair, double T1, double omega1, double b)
  {
    const double aw = pair.working_pressure_angle();
    PitchPoint c;
    c.load_per_width = std::abs(T1) / pair.base_radius(1) / b;
    c.v_sum          = 2.0 * std::abs(omega1) * pair.working_pitch_radius(1) * std::sin(aw);
    const double r1 = pair.base_radius(1) * std::tan(aw), r2 = pair.base_radius(2) * std::tan(aw);
    c.rho_red        = r1 * r2 / (pair.is_internal() ? r2 - r1 : r1 + r2);
    return c;
  }

  double agma_925(double Ra1, double Ra2)
  {
    const double Ravg = 0.5 * (Ra1 + Ra2) * 1e6; // um
    const double C_R  = std::clamp(1.13 / (1.13 - Ravg), 1.0, 3.0);
    return 0.06 * C_R;
  }

  double iso_14179_2(const PitchPoint &c, double eta_oil, double Ra1, double Ra2, double X_L)
  {
    const double w   = c.load_per_width * 1e-3; // N/mm
    const double rho = c.rho_red * 1e3;         // mm
    const double Ra  = 0.5 * (Ra1 + Ra2) * 1e6; // um
    return 0.048 * std::pow(w / (c.v_sum * rho), 0.2) * std::pow(eta_oil * 1e3, -0.05) * std::pow(Ra, 0.25) * X_L;
  }

  double coefficient(const LawInputs &in, const PitchPoint &c)
  {
    check(in);
    switch (in.law)
      {
        case Law::constant:
          return in.mu;
        case Law::iso_14179_2:
          return iso_14179_2(c, in.eta_oil, in.Ra1, in.Ra2, in.X_L);
        case Law::agma_925:
          return agma_925(in.Ra1, in.Ra2);
      }
    return in.mu;
  }

  double ohlendorf_hv(const geometry::GearPair &pair)
  {
    const double pb = pair.base_pitch();
    const double g_A = pair.point("A").g, g_C = pair.point("C").g, g_E = pair.point("E").g;
    const double eps1 = (g_E - g_C) / pb, eps2 = (g_C - g_A) / pb;
    const double z1 = pair.gear(1).teeth(), u = pair.ratio();
    return units::pi * (u + 1.0) / (z1 * u) * (1.0 - (eps1 + eps2) + eps1 * eps1 + eps2 * eps2);
  }
} // namespace gearfem::analytical::friction
