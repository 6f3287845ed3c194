#include "rating/iso6336.h"
#include "base/units.h"

#include "base/errors.h"
#include "base/roots.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gearfem::rating::iso6336
{
  namespace
  {
    using units::pi;
    constexpr double deg = pi / 180.0;
  } // namespace

  ContactFactors contact_stress(const ContactInput &in)
  {
    require_greater("face width", in.b, 0.0, "m");
    require_greater("tangential load F_t", in.Ft, 0.0, "N");
    ContactFactors f;
    const double ca = std::cos(in.alpha_t);
    f.Z_H = std::sqrt(2.0 * std::cos(in.beta_b) * std::cos(in.alpha_wt) /
                      (ca * ca * std::sin(in.alpha_wt)));
    f.Z_E = std::sqrt(1.0 / (pi * ((1 - in.nu1 * in.nu1) / in.E1 + (1 - in.nu2 * in.nu2) / in.E2)));
    const double ea = in.eps_alpha, eb = in.eps_beta;
    if (eb < 1.0)
      f.Z_eps = std::sqrt((4.0 - ea) / 3.0 * (1.0 - eb) + eb / ea);
    else
      f.Z_eps = std::sqrt(1.0 / ea);
    f.Z_beta = std::sqrt(1.0 / std::cos(in.beta)); // ISO 6336-2:2006 eq. 23
    const double r1 = std::sqrt(in.da1 * in.da1 / (in.db1 * in.db1) - 1.0);
    const double r2 = std::sqrt(in.da2 * in.da2 / (in.db2 * in.db2) - 1.0);
    f.M1 = std::tan(in.alpha_wt) /
           std::sqrt((r1 - 2 * pi / in.z1) * (r2 - (ea - 1.0) * 2 * pi / in.z2));
    f.M2 = std::tan(in.alpha_wt) /
           std::sqrt((r2 - 2 * pi / in.z2) * (r1 - (ea - 1.0) * 2 * pi / in.z1));
    // Spur: Z_B = M1, Z_D = M2 (not below 1); helical eps_beta >= 1: 1; between: interpolate.
    auto interp = [&](double M) {
      if (eb >= 1.0)
        return 1.0;
      return std::max(1.0, M - eb * (M - 1.0));
    };
    f.Z_B = interp(f.M1);
    f.Z_D = interp(f.M2);
    const double u = double(in.z2) / in.z1;
    f.sigma_H0 = f.Z_H * f.Z_E * f.Z_eps * f.Z_beta * std::sqrt(in.Ft / (in.d1 * in.b) * (u + 1.0) / u);
    const double K = std::sqrt(in.K_A * in.K_v * in.K_Hbeta * in.K_Halpha);
    f.sigma_H1 = f.Z_B * f.sigma_H0 * K;
    f.sigma_H2 = f.Z_D * f.sigma_H0 * K;
    return f;
  }

  CriticalSection critical_section(const PlaneCurve &c, double angle_deg)
  {
    // g(t) = angle between the tangent and the tooth axis minus the target, measured as
    // atan2(|x'|, |y'|).
    const double target = angle_deg * deg;
    auto g = [&](double t) {
      return std::atan2(std::abs(c.x(t, 1)), std::abs(c.y(t, 1))) - target;
    };
    // Bracket on a sample, then bisection + secant (the angle is monotone on a fillet).
    const int n = 200;
    double ta = c.t0, ga = g(ta);
    double lo = 0, hi = 0;
    bool found = false;
    for (int i = 1; i <= n && !found; ++i)
      {
        const double tb = c.t0 + (c.t1 - c.t0) * i / n;
        const double gb = g(tb);
        if (ga == 0.0 || ga * gb < 0.0)
          {
            lo = ta;
            hi = tb;
            found = true;
          }
        ta = tb;
        ga = gb;
      }
    if (!found)
      throw SolverError("ISO 6336-3 critical section: no fillet point has its tangent at " +
                        to_string_g(angle_deg) + " deg to the tooth axis");
    CriticalSection cs;
    cs.t = base::find_root_bisection(g, lo, hi, "ISO 6336-3 critical section (" + to_string_g(angle_deg) +
                                                  " deg tangent)");
    cs.s_Fn = 2.0 * std::abs(c.x(cs.t, 0));
    cs.y = c.y(cs.t, 0);
    const double x1 = c.x(cs.t, 1), y1 = c.y(cs.t, 1), x2 = c.x(cs.t, 2), y2 = c.y(cs.t, 2);
    cs.rho_F = std::pow(x1 * x1 + y1 * y1, 1.5) / std::abs(x1 * y2 - y1 * x2);
    return cs;
  }

  RootFactors root_factors(const CriticalSection &cs, const InvoluteFlank &fl, double r_e,
                           double module, double alpha_n)
  {
    if (!(r_e > fl.rb))
      throw InputError("ISO 6336-3 load radius", to_string_g(r_e) + " m",
                       "> base radius " + to_string_g(fl.rb) + " m");
    const double a_en = std::acos(fl.rb / r_e);
    const double gamma_e = fl.psi_b - (std::tan(a_en) - a_en); // half angle at r_e
    RootFactors f;
    f.alpha_Fen = a_en - gamma_e;
    // Load line from (r sin g, r cos g) meets the axis at y = r cos g - r sin g tan a_Fen.
    const double y_int = r_e * std::cos(gamma_e) - r_e * std::sin(gamma_e) * std::tan(f.alpha_Fen);
    f.s_Fn = cs.s_Fn;
    f.rho_F = cs.rho_F;
    f.h_Fe = y_int - cs.y;
    const double sm = f.s_Fn / module, hm = f.h_Fe / module;
    f.Y_F = 6.0 * hm * std::cos(f.alpha_Fen) / (sm * sm * std::cos(alpha_n));
    f.L = f.s_Fn / f.h_Fe;
    f.q_s = f.s_Fn / (2.0 * f.rho_F);
    f.Y_S = (1.2 + 0.13 * f.L) * std::pow(f.q_s, 1.0 / (1.21 + 2.3 / f.L));
    return f;
  }

  RackFilletClosedForm rack_fillet_closed_form(int zn, double m, double an, double x,
                                               double h_fP, double rho_fP, double s_pr)
  {
    RackFilletClosedForm r;
    // ISO 6336-3 eqs. (E, G, H, theta) with h_fP, rho_fP as multiples of m.
    r.E = pi * m / 4.0 - h_fP * m * std::tan(an) + s_pr / std::cos(an) -
          (1.0 - std::sin(an)) * rho_fP * m / std::cos(an);
    r.G = rho_fP - h_fP + x;
    r.H = 2.0 / zn * (pi / 2.0 - r.E / m) - pi / 3.0;
    // Newton on f(th) = 2G/zn tan th - H - th from pi/6, in (-pi/2, pi/2) where tan is finite.
    const double th = base::find_root_newton(
      [&](double t) {
        return std::make_pair(2.0 * r.G / zn * std::tan(t) - r.H - t,
                              2.0 * r.G / zn / (std::cos(t) * std::cos(t)) - 1.0);
      },
      -0.5 * pi + 1e-6, 0.5 * pi - 1e-6, pi / 6.0, 1e-15, 200, "ISO 6336-3 theta equation");
    r.theta = th;
    r.s_Fn = m * (zn * std::sin(pi / 3.0 - th) + std::sqrt(3.0) * (r.G / std::cos(th) - rho_fP));
    r.rho_F = m * (rho_fP + 2.0 * r.G * r.G / (std::cos(th) * (zn * std::cos(th) * std::cos(th) - 2.0 * r.G)));
    // Height of the chord: ISO's h_Fe subtracts 0.5 m [zn cos(pi/3 - th) + G/cos th - rho_fP].
    r.y = 0.5 * m * (zn * std::cos(pi / 3.0 - th) + r.G / std::cos(th) - rho_fP);
    return r;
  }

  double Y_eps(double eps_alpha)
  {
    require_greater("contact ratio eps_alpha", eps_alpha, 0.0);
    return 0.25 + 0.75 / eps_alpha;
  }

  double Y_beta(double eps_beta, double beta)
  {
    const double eb = std::min(eps_beta, 1.0);
    const double b = std::min(beta, 30.0 * deg);
    return 1.0 - eb * b / (120.0 * deg);
  }
} // namespace gearfem::rating::iso6336
