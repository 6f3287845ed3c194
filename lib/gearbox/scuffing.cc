#include "gearbox/scuffing.h"
#include "analytical/friction.h"
#include "base/units.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>

namespace gearfem::gearbox::scuffing
{
  namespace
  {
    using units::pi;
    constexpr double blok_K = 0.80;       ///< Blok's constant for a Hertzian band (AGMA 925)
    double lg(double x) { return std::log10(x); }
  } // namespace

  void pressure_viscosity_constants(const std::string &type, double &k, double &s)
  {
    if (type == "mineral")
      k = 0.010471, s = 0.13480;
    else if (type == "PAO")
      k = 0.010326, s = 0.05070;
    else if (type == "PAG")
      k = 0.004700, s = 0.15720;
    else if (type == "MIL-L-7808K")
      k = 0.005492, s = 0.25472;
    else if (type == "MIL-L-23699E")
      k = 0.006515, s = 0.16350;
    else
      throw InputError("Lubricant/Oil type", type, "mineral|PAO|PAG|MIL-L-7808K|MIL-L-23699E");
  }

  double viscosity(const Lubricant &oil, double theta)
  {
    const double e40 = oil.eta40 * 1e3, e100 = oil.eta100 * 1e3; // mPa s
    const double d = 13.13525 * lg(lg(e100 + 0.9) / lg(e40 + 0.9));
    const double c = lg(lg(e40 + 0.9)) - 2.495752 * d;
    const double g = std::pow(10.0, c) * std::pow(theta + 273.15, d);
    return (std::pow(10.0, g) - 0.9) * 1e-3;
  }

  double pressure_viscosity(const Lubricant &oil, double eta)
  {
    double k = 0, s = 0;
    pressure_viscosity_constants(oil.type, k, s);
    return k * std::pow(eta * 1e3, s) * 1e-6; // mm^2/N -> 1/Pa
  }

  double scuffing_temperature(const Lubricant &oil)
  {
    return (oil.extreme_pressure ? 118.0 : 63.0) + 33.0 * std::log(oil.nu40);
  }

  double probability_unclamped(double theta_B, double theta_S)
  {
    const double z = (theta_B - theta_S) / (0.15 * theta_S);
    return 0.5 * std::erfc(-z / std::sqrt(2.0));
  }

  double probability(double theta_B, double theta_S)
  {
    return std::clamp(probability_unclamped(theta_B, theta_S), 0.05, 0.95);
  }

  std::string risk(double P) { return P < 0.10 ? "low" : P <= 0.30 ? "medium" : "high"; }

  void check(const Conditions &c, const Lubricant &oil)
  {
    require_range("Lubricant/Oil temperature", c.theta_oil, -40.0, 200.0, "C");
    require_range("Lubricant/Sump factor", c.k_sump, 1.0, 1.2);
    require_range("Scuffing/Points along the path", c.points, 25, 50);
    // The range of lubricating oils (ISO VG 2 to VG 3200 and beyond), where the Walther
    // viscosity-temperature relation (log log (nu + 0.7)) holds: below 1 mm^2/s it has no real value.
    require_range("Lubricant/Kinematic viscosity at 40 C", oil.nu40, 2.0, 1e5, "mm^2/s");
    require_range("Lubricant/Dynamic viscosity at 100 C", oil.eta100 * 1e3, 0.5, 1e5, "mPa s");
    require_range("Lubricant/Dynamic viscosity at 40 C", oil.eta40 * 1e3, 0.5, 1e5, "mPa s");
    if (!(oil.eta40 > oil.eta100))
      throw InputError("Lubricant/Dynamic viscosity at 40 C", to_string_g(oil.eta40 * 1e3) + " mPa s",
                       "> the value at 100 C (" + to_string_g(oil.eta100 * 1e3) + " mPa s)");
    double k = 0, s = 0;
    pressure_viscosity_constants(oil.type, k, s);
  }

  Result evaluate(const agma::LineOfAction &l, double m, bool internal, double b, double n1, double F,
                  const Lubricant &oil, const Conditions &c)
  {
    check(c, oil);
    require_greater("scuffing: pinion speed", std::abs(n1), 0.0, "rpm");
    require_greater("scuffing: load", F, 0.0, "N");
    Result r;
    r.E_r = 2.0 / ((1 - c.nu1 * c.nu1) / c.E1 + (1 - c.nu2 * c.nu2) / c.E2); // eq. 4.4-36
    r.mu_m = analytical::friction::agma_925(c.Ra1, c.Ra2); // eqs. 4.4-53/54, the one definition
    r.w_n = F / std::cos(l.phi_r) / b; // eqs. 4.4-31/32, L_min = b for spur gears
    const double rb1 = l.Rb1 * m, C6 = l.C6 * m;
    const double A = l.C1 * m, Bp = l.C2 * m, D = l.C4 * m, E = l.C5 * m;
    const double w1 = pi * std::abs(n1) / 30.0, w2 = w1 / l.mG;
    const double sigma_x = std::hypot(c.Ra1, c.Ra2);
    for (int j = 0; j < c.points; ++j)
      {
        PathPoint p;
        const double C = A + (E - A) * j / (c.points - 1);
        p.roll = C / rb1;
        p.rho1 = C;
        p.rho2 = internal ? C6 + C : C6 - C;                                          // eq. 4.4-19
        p.rho_n = internal ? p.rho1 * p.rho2 / (p.rho2 - p.rho1) : p.rho1 * p.rho2 / (p.rho1 + p.rho2);
        const double rho_n = p.rho_n;
        if (C < Bp)
          p.X = 1.0 / 3.0 + (C - A) / (Bp - A) / 3.0; // eq. 4.4-33
        else if (C <= D)
          p.X = 1.0;                                  // eq. 4.4-34
        else
          p.X = 2.0 / 3.0 - (C - D) / (E - D) / 3.0;  // eq. 4.4-35
        p.v1 = w1 * p.rho1, p.v2 = w2 * p.rho2;
        p.b_H = std::sqrt(8.0 * p.X * r.w_n * rho_n / (pi * r.E_r));
        // Blok (eq. 4.4-52) in the standard's units: w_n [N/mm], v [m/s], b_H [mm].
        p.theta_fl = 31.62 * blok_K * r.mu_m * p.X * r.w_n * 1e-3 * std::abs(p.v1 - p.v2) /
                     ((c.B_M1 * std::sqrt(p.v1) + c.B_M2 * std::sqrt(p.v2)) * std::sqrt(p.b_H * 1e3));
        r.theta_fl_max = std::max(r.theta_fl_max, p.theta_fl);
        r.path.push_back(p);
      }
    r.theta_M = c.k_sump * c.theta_oil + 0.56 * r.theta_fl_max; // eq. 4.4-55
    r.eta_M = viscosity(oil, r.theta_M);
    r.alpha = pressure_viscosity(oil, r.eta_M);
    r.theta_S = scuffing_temperature(oil);
    r.h_c_min = r.lambda_min = 1e300;
    for (PathPoint &p : r.path)
      {
        const double rho_n = p.rho_n;
        const double G = r.alpha * r.E_r, U = r.eta_M * (p.v1 + p.v2) / (2.0 * r.E_r * rho_n),
                     W = p.X * r.w_n / (r.E_r * rho_n);
        p.h_c = 3.06 * std::pow(G, 0.56) * std::pow(U, 0.69) * std::pow(W, -0.10) * rho_n; // 4.4-41, -49
        p.lambda = p.h_c / sigma_x * std::sqrt(c.L_x / (2.0 * p.b_H));                    // 4.4-50/51
        p.theta_B = r.theta_M + p.theta_fl;                                                // 4.4-57
        r.theta_B_max = std::max(r.theta_B_max, p.theta_B);
        r.h_c_min = std::min(r.h_c_min, p.h_c);
        r.lambda_min = std::min(r.lambda_min, p.lambda);
      }
    r.P_unclamped = probability_unclamped(r.theta_B_max, r.theta_S);
    r.P = probability(r.theta_B_max, r.theta_S);
    r.risk = risk(r.P);
    return r;
  }
} // namespace gearfem::gearbox::scuffing
