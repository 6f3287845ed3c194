#include "rating/agma.h"
#include "base/units.h"

#include "base/errors.h"
#include "base/roots.h"

#include <cmath>
#include <limits>

namespace gearfem::rating::agma
{
  namespace
  {
    using units::pi;
    double inv(double a) { return std::tan(a) - a; }
    double inv_inverse(double v)
    {
      // inv a >= a^3/3: the root lies in [0, cbrt(3 v)]; Newton from the upper end.
      const double hi = std::min(std::cbrt(3.0 * v), 0.5 * pi);
      return base::find_root_newton(
        [v](double a) {
          const double t = std::tan(a);
          return std::make_pair(inv(a) - v, t * t);
        },
        0.0, hi, hi, 4e-16, 100, "AGMA 908 inverse involute function inv a = " + to_string_g(v));
    }
  } // namespace

  namespace
  {
    /// Gear ratio, pitch, base and tip radii and centre distance in module units (AGMA
    /// 908 notation), shared by the external and internal lines of action.
    LineOfAction pair_radii(int z1, int z2, double m, double phi_n, double ro1, double ro2, double a)
    {
      LineOfAction l;
      l.mG = double(z2) / z1;
      l.R1 = 0.5 * z1;
      l.R2 = l.R1 * l.mG;
      l.Rb1 = l.R1 * std::cos(phi_n);
      l.Rb2 = l.Rb1 * l.mG;
      l.Ro1 = ro1 / m;
      l.Ro2 = ro2 / m;
      l.Cr = a / m;
      return l;
    }
  } // namespace

  LineOfAction line_of_action(int z1, int z2, double m, double phi_n, double ro1, double ro2,
                              double a)
  {
    require_greater("Gear 1/Number of teeth", z1, 4);
    require_greater("Gear 2/Number of teeth", z2, 4);
    require_greater("module", m, 0.0, "m");
    LineOfAction l = pair_radii(z1, z2, m, phi_n, ro1, ro2, a);
    const double c = (l.Rb1 + l.Rb2) / l.Cr;
    if (!(c < 1.0))
      throw InputError("Pair/Centre distance", to_string_g(a) + " m",
                       "> sum of base radii " + to_string_g((l.Rb1 + l.Rb2) * m) + " m");
    l.phi_r = std::acos(c);
    l.pb = 2.0 * pi * l.Rb1 / z1;
    l.C6 = l.Cr * std::sin(l.phi_r);
    l.C1 = l.C6 - std::sqrt(l.Ro2 * l.Ro2 - l.Rb2 * l.Rb2);
    l.C3 = l.C6 / (l.mG + 1.0);
    l.C4 = l.C1 + l.pb;
    l.C5 = std::sqrt(l.Ro1 * l.Ro1 - l.Rb1 * l.Rb1);
    l.C2 = l.C5 - l.pb;
    l.contact_ratio = (l.C5 - l.C1) / l.pb;
    return l;
  }

  double geometry_factor_I(const LineOfAction &l)
  {
    const double rho1 = l.C2, rho2 = l.C6 - rho1;
    if (!(rho1 > 0.0 && rho2 > 0.0))
      throw InputError("AGMA Z_I: LPSTC outside the involutes (rho1 = " + to_string_g(rho1) +
                       ", rho2 = " + to_string_g(rho2) + " module units)");
    const double d = 2.0 * l.Cr / (l.mG + 1.0);
    return std::cos(l.phi_r) / ((1.0 / rho1 + 1.0 / rho2) * d);
  }

  LineOfAction line_of_action_internal(int z1, int z2, double m, double phi_n, double ro1,
                                       double ro2, double a)
  {
    require_greater("Gear 1/Number of teeth", z1, 4);
    require_greater("Internal gear/Number of teeth", z2, z1);
    require_greater("module", m, 0.0, "m");
    LineOfAction l = pair_radii(z1, z2, m, phi_n, ro1, ro2, a);
    const double c = (l.Rb2 - l.Rb1) / l.Cr;
    if (!(c < 1.0))
      throw InputError("Internal mesh/Centre distance", to_string_g(a) + " m",
                       "> difference of base radii " + to_string_g((l.Rb2 - l.Rb1) * m) + " m");
    if (!(l.Ro2 > l.Rb2))
      throw InputError("Internal gear/Tip diameter", to_string_g(2 * ro2) + " m",
                       "> base diameter " + to_string_g(2 * l.Rb2 * m) + " m");
    l.phi_r = std::acos(c);
    l.pb = 2.0 * pi * l.Rb1 / z1;
    l.C6 = l.Cr * std::sin(l.phi_r);
    l.C1 = std::sqrt(l.Ro2 * l.Ro2 - l.Rb2 * l.Rb2) - l.C6;
    l.C3 = l.C6 / (l.mG - 1.0);
    l.C4 = l.C1 + l.pb;
    l.C5 = std::sqrt(l.Ro1 * l.Ro1 - l.Rb1 * l.Rb1);
    l.C2 = l.C5 - l.pb;
    l.contact_ratio = (l.C5 - l.C1) / l.pb;
    if (!(l.C1 > 0.0))
      throw InputError("Internal gear/Tip diameter", to_string_g(2 * ro2 * 1e3) + " mm",
                       "> " + to_string_g(2e3 * m * std::sqrt(l.Rb2 * l.Rb2 + l.C6 * l.C6)) + " mm",
                       "internal interference: the internal gear's tip starts contact below the "
                       "pinion's base circle (C1 = " + to_string_g(l.C1) + " module units)");
    return l;
  }

  double geometry_factor_I_internal(const LineOfAction &l)
  {
    const double rho1 = l.C2, rho2 = l.C6 + rho1;
    if (!(rho1 > 0.0))
      throw InputError("AGMA Z_I (internal): LPSTC outside the pinion involute (rho1 = " +
                       to_string_g(rho1) + " module units)");
    const double d = 2.0 * l.Cr / (l.mG - 1.0);
    return std::cos(l.phi_r) / ((1.0 / rho1 - 1.0 / rho2) * d);
  }

  BendingGeometry geometry_factor_J(int n, double x_g, double tan_phi_nW, double phi_n,
                                    double phi_nr, const Tool &t)
  {
    BendingGeometry g;
    g.tan_phi_nW = tan_phi_nW;
    const double rn = 0.5 * n, rnb = rn * std::cos(phi_n);
    const double sn = 0.5 * pi + 2.0 * x_g * std::tan(phi_n);
    // Load angle and radius (4.3.2-8..15; phi_nL = tan phi_nW - inv phi_np).
    g.phi_nL = tan_phi_nW - (inv(phi_n) + sn / n);
    g.r_nL = rnb / std::cos(g.phi_nL);
    // Tool (4.3.2-16..25); S is the centre of the tool tip radius, inside the tool tooth
    // by rho_ao along the involute normal: lambda/2 = inv phi_npo - inv phi_ns + (delta - rho)/r_nbo.
    const double rno = 0.5 * t.n_o, rnbo = rno * std::cos(phi_n);
    const double rnos = rno + t.h_ao + t.x_o - t.rho_ao;
    const double phi_ns = std::acos(rnbo / rnos);
    const double inv_npo = inv(phi_n) + t.s_no / t.n_o;
    const double lam2 = inv_npo - inv(phi_ns) + (t.delta_ao - t.rho_ao) / rnbo;
    // Generating pressure angle and pitch radii (4.3.2-26..28).
    const double phi_pp = inv_inverse(inv(phi_n) + 2.0 * (x_g + t.x_o) * std::tan(phi_n) / (n + t.n_o));
    const double rnpp = rn * std::cos(phi_n) / std::cos(phi_pp);
    const double rnopp = rno * std::cos(phi_n) / std::cos(phi_pp);

    struct Point
    {
      double y, xi, eta, hF;
    };
    auto eval = [&](double an) {
      const double mu = std::acos(rnopp * std::cos(an) / rnos) - an;
      const double KS = rnopp * std::sin(an) - rnos * std::sin(an + mu);
      const double KF = KS - t.rho_ao;
      const double tho = mu - lam2 + pi / t.n_o;
      const double th = t.n_o / n * tho;
      const double bn = an - th;
      Point p;
      p.xi = rnpp * std::sin(th) + KF * std::cos(bn);
      p.eta = rnpp * std::cos(th) + KF * std::sin(bn);
      p.hF = g.r_nL - p.eta;
      p.y = 2.0 * p.hF * std::tan(bn) - p.xi; // (4.3.2-37)
      return p;
    };
    // Newton from alpha_n = pi/4 (4.3.2-38) with a central-difference derivative.
    double an = 0.25 * pi;
    bool converged = false;
    for (int it = 1; it <= 100; ++it)
      {
        const double h = 1e-7;
        const double y = eval(an).y;
        const double dy = (eval(an + h).y - eval(an - h).y) / (2 * h);
        const double step = y / dy;
        an -= step;
        g.iterations = it;
        if (!std::isfinite(an))
          break;
        if (std::abs(step) < 1e-13)
          {
            converged = true;
            break;
          }
      }
    if (!converged)
      throw SolverError("AGMA 908 Y_J: the Lewis-parabola Newton iteration did not converge (" +
                        std::to_string(n) + " teeth)");
    g.alpha_n = an;
    const Point p = eval(an);
    g.s_F = 2.0 * p.xi;
    g.h_F = p.hF;
    // Minimum fillet radius at alpha_n = pi/2 (4.3.2-40).
    const double dr = rnopp - rnos;
    g.rho_F = t.rho_ao + dr * dr / (rnpp * rnopp / (rnpp + rnopp) - dr);
    form_and_stress_factors(g, phi_n, phi_nr);
    return g;
  }

  void form_and_stress_factors(BendingGeometry &g, double phi_n, double phi_nr)
  {
    const double H = 0.331 - 0.436 * phi_n, L = 0.324 - 0.492 * phi_n, M = 0.261 + 0.545 * phi_n;
    g.K_f = H + std::pow(g.s_F / g.rho_F, L) * std::pow(g.s_F / g.h_F, M);
    // Form factor (4.3.2-46) with K_psi = C_h = 1 (spur).
    g.Y = 1.0 / ((std::cos(g.phi_nL) / std::cos(phi_nr)) *
                 (6.0 * g.h_F / (g.s_F * g.s_F) - std::tan(g.phi_nL) / g.s_F));
    g.Y_J = g.Y / g.K_f;
    if (!(g.Y_J > 0.0) || !std::isfinite(g.Y_J))
      throw SolverError("AGMA 908 Y_J: non-positive result " + to_string_g(g.Y_J));
  }

  LewisSection lewis_section(const analytical::PlaneCurve &c, double yL)
  {
    auto f = [&](double t) {
      const double x = std::abs(c.x(t, 0)), y = c.y(t, 0);
      const double tb = std::abs(c.x(t, 1)) / std::abs(c.y(t, 1)); // tan(beta) to the axis
      return 2.0 * (yL - y) * tb - x;
    };
    const int n = 400;
    double ta = c.t0, fa = f(ta), lo = 0, hi = 0;
    bool found = false;
    for (int i = 1; i <= n && !found; ++i)
      {
        const double tb = c.t0 + (c.t1 - c.t0) * i / n, fb = f(tb);
        if (std::isfinite(fa) && std::isfinite(fb) && fa * fb <= 0.0)
          {
            lo = ta, hi = tb, found = true;
          }
        ta = tb, fa = fb;
      }
    if (!found)
      throw SolverError("AGMA Lewis parabola: no tangency point on the fillet (load point y_L = " +
                        to_string_g(yL) + ")");
    LewisSection s;
    s.t = base::find_root_bisection(f, lo, hi, "AGMA Lewis parabola tangency on the fillet");
    s.s_F = 2.0 * std::abs(c.x(s.t, 0));
    s.y_F = c.y(s.t, 0);
    s.h_F = yL - s.y_F;
    // Minimum radius of curvature along the fillet.
    s.rho_F = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 2000; ++i)
      {
        const double t = c.t0 + (c.t1 - c.t0) * i / 2000.0;
        const double x1 = c.x(t, 1), y1 = c.y(t, 1), x2 = c.x(t, 2), y2 = c.y(t, 2);
        const double k = std::abs(x1 * y2 - y1 * x2) / std::pow(x1 * x1 + y1 * y1, 1.5);
        if (k > 0.0)
          s.rho_F = std::min(s.rho_F, 1.0 / k);
      }
    return s;
  }

  Enclosure enclosure_from_string(const std::string &s)
  {
    if (s == "open")
      return Enclosure::open;
    if (s == "commercial")
      return Enclosure::commercial;
    if (s == "precision")
      return Enclosure::precision;
    if (s == "extra precision")
      return Enclosure::extra_precision;
    throw InputError("Rating/Gear unit class", s, "open|commercial|precision|extra precision");
  }

  const char *to_string(Enclosure e)
  {
    switch (e)
      {
        case Enclosure::open: return "open";
        case Enclosure::commercial: return "commercial";
        case Enclosure::precision: return "precision";
        case Enclosure::extra_precision: return "extra precision";
      }
    return "?";
  }

  double K_Hma(double b, Enclosure e)
  {
    const double bm = b * 1e3; // mm
    double A = 0, B = 0, C = 0;
    switch (e)
      {
        case Enclosure::open: A = 0.247; B = 0.657e-3; C = -1.186e-7; break;
        case Enclosure::commercial: A = 0.127; B = 0.622e-3; C = -1.690e-7; break;
        case Enclosure::precision: A = 0.0675; B = 0.504e-3; C = -1.440e-7; break;
        case Enclosure::extra_precision: A = 0.0380; B = 0.402e-3; C = -1.270e-7; break;
      }
    return A + B * bm + C * bm * bm;
  }

  double K_Hpf(double b, double d)
  {
    const double bm = b * 1e3;
    require_range("face width for K_Hpf", bm, 0.0, 1020.0, "mm");
    const double r = std::max(0.05, b / (10.0 * d));
    if (bm <= 25.0)
      return r - 0.025;
    if (bm <= 432.0)
      return r - 0.0375 + 0.000492 * bm;
    return r - 0.1109 + 0.000815 * bm - 0.000000353 * bm * bm;
  }

  double K_B(double mB)
  {
    require_greater("backup ratio m_B", mB, 0.0);
    return mB < 1.2 ? 1.6 * std::log(2.242 / mB) : 1.0;
  }

  double Z_E(double E1, double nu1, double E2, double nu2)
  {
    return std::sqrt(1.0 / (pi * ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2)));
  }
} // namespace gearfem::rating::agma
