// ISO 6336 and AGMA ratings against the tables of Siasos 2010, the standards' own closed
// forms and ISO 6336-1's rules of thumb.
#include "rating/agma.h"
#include "base/units.h"
#include "rating/iso6336.h"
#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace gearfem::analytical;
using namespace gearfem::rating;

namespace
{
  using gearfem::units::pi;
  constexpr double deg = pi / 180;

  // Siasos 2010 (tables 6.2-1..3): 23/69, m 4, alpha 20 deg, b = 70 mm (the
  // narrower face), E 205 GPa, nu 0.3, K_o = K_s = 1, K_v = 1.05, Z_R = 1, precision enclosed.
  struct Seed001
  {
    int z1 = 23, z2 = 69;
    double m = 4e-3, b = 70e-3, E = 205e9, nu = 0.3, Kv = 1.05;
    double T[4] = {500, 400, 300, 200};
    double sH[4] = {827.0, 739.7, 640.6, 523.1};
    double sF1[4] = {127.0, 101.6, 76.2, 50.8};
    double sF2[4] = {110.9, 88.7, 66.5, 44.4};
  };

  struct AgmaResult
  {
    double ZI, YJ1, YJ2, KH, ZE, d; // d: operating pitch diameter of the pinion [m]
  };
  AgmaResult agma_seed001(const Seed001 &s)
  {
    const double a = 0.5 * s.m * (s.z1 + s.z2);
    const gearfem::rating::agma::LineOfAction l = gearfem::rating::agma::line_of_action(s.z1, s.z2, s.m, 20 * deg, 0.5 * s.m * s.z1 + s.m,
                                                      0.5 * s.m * s.z2 + s.m, a);
    AgmaResult r;
    r.d = 2 * a / (l.mG + 1);
    r.ZI = gearfem::rating::agma::geometry_factor_I(l);
    r.YJ1 = gearfem::rating::agma::geometry_factor_J(s.z1, 0, l.C4 / l.Rb1, 20 * deg, l.phi_r).Y_J;
    r.YJ2 = gearfem::rating::agma::geometry_factor_J(s.z2, 0, (l.C6 - l.C2) / l.Rb2, 20 * deg, l.phi_r).Y_J;
    r.KH = 1 + gearfem::rating::agma::K_Hma(s.b, gearfem::rating::agma::Enclosure::precision) + gearfem::rating::agma::K_Hpf(s.b, r.d);
    r.ZE = gearfem::rating::agma::Z_E(s.E, s.nu, s.E, s.nu);
    return r;
  }
} // namespace

TEST(Agma, Seed001LineOfAction)
{
  // Siasos 2010 (AGMA 908, unit module): C2 = 3.33, C3 = 3.93, C4 = 4.22, eps ~ 1.70.
  const gearfem::rating::agma::LineOfAction l = gearfem::rating::agma::line_of_action(23, 69, 4e-3, 20 * deg, 50e-3, 142e-3, 184e-3);
  EXPECT_NEAR(l.C2, 3.33, 0.005);
  EXPECT_NEAR(l.C3, 3.93, 0.005);
  EXPECT_NEAR(l.C4, 4.22, 0.005);
  EXPECT_NEAR(l.contact_ratio, 1.70, 0.005);
}

TEST(Agma, Seed001TablesWithAgma2101LoadDistribution)
{
  // With K_H from AGMA 2101-D04 (K_Hma precision enclosed + K_Hpf for 25 < b <= 432 mm)
  // the contact stress is within 1 % of the thesis table; the root stresses come out 1.8 %
  // high (see the next test for the cause).
  const Seed001 s;
  const AgmaResult r = agma_seed001(s);
  for (int i = 0; i < 4; ++i)
    {
      const double Ft = 2 * s.T[i] / r.d;
      const double sH = r.ZE * std::sqrt(Ft * s.Kv * r.KH / (r.d * s.b) / r.ZI) / 1e6;
      const double sF1 = Ft * s.Kv * r.KH / (s.b * s.m * r.YJ1) / 1e6;
      const double sF2 = Ft * s.Kv * r.KH / (s.b * s.m * r.YJ2) / 1e6;
      EXPECT_NEAR(sH / s.sH[i], 1.0, 0.01) << "T = " << s.T[i];
      EXPECT_NEAR(sF1 / s.sF1[i], 1.0185, 0.005) << "T = " << s.T[i];
      EXPECT_NEAR(sF2 / s.sF2[i], 1.0185, 0.005) << "T = " << s.T[i];
    }
}

TEST(Agma, Seed001GeometryFactorsAreConsistentWithAllThreeTables)
{
  // Our Z_I and Y_J do not depend on K_H. Each table row then implies a value of
  // K_o K_v K_s K_H; if Z_I, Y_J1 and Y_J2 match the thesis, the 12 implied values agree.
  // They do to 0.1 %, at K_H = 1.1546 (against 1.1751 from AGMA 2101-D04): the thesis'
  // K_Hpf is 0.0525 rather than 0.0730, close to the b <= 25 mm branch (eq. 4.1.6-5)
  // b/(10 d) - 0.025 = 0.0511 applied to b = 70 mm.
  const Seed001 s;
  const AgmaResult r = agma_seed001(s);
  double lo = 1e9, hi = 0;
  for (int i = 0; i < 4; ++i)
    {
      const double Ft = 2 * s.T[i] / r.d;
      const double q = s.sH[i] * 1e6 / r.ZE;
      const double k[3] = {q * q * r.d * s.b * r.ZI / Ft, s.sF1[i] * 1e6 * s.b * s.m * r.YJ1 / Ft,
                           s.sF2[i] * 1e6 * s.b * s.m * r.YJ2 / Ft};
      for (double v : k)
        {
          lo = std::min(lo, v / s.Kv);
          hi = std::max(hi, v / s.Kv);
        }
    }
  EXPECT_LT(hi / lo - 1, 0.002);
  EXPECT_NEAR(0.5 * (hi + lo), 1.1546, 0.002);
  // With the b <= 25 mm branch all twelve values are within 0.2 %.
  const double KH_thesis = 1 + gearfem::rating::agma::K_Hma(s.b, gearfem::rating::agma::Enclosure::precision) + s.b / (10 * r.d) - 0.025;
  for (int i = 0; i < 4; ++i)
    {
      const double Ft = 2 * s.T[i] / r.d;
      EXPECT_NEAR(r.ZE * std::sqrt(Ft * s.Kv * KH_thesis / (r.d * s.b) / r.ZI) / 1e6 / s.sH[i], 1, 0.002);
      EXPECT_NEAR(Ft * s.Kv * KH_thesis / (s.b * s.m * r.YJ1) / 1e6 / s.sF1[i], 1, 0.002);
      EXPECT_NEAR(Ft * s.Kv * KH_thesis / (s.b * s.m * r.YJ2) / 1e6 / s.sF2[i], 1, 0.002);
    }
}

TEST(Agma, LewisNewtonConvergesAndBehaves)
{
  // The Newton iteration from alpha_n = pi/4 converges in a few steps for 12..200 teeth,
  // and Y_J grows with the number of teeth (AGMA 908-B89 charts).
  double prev = 0;
  for (int z : {12, 17, 25, 35, 50, 85, 200})
    {
      const double rb = 0.5 * z * std::cos(20 * deg);
      const double tanW = std::sqrt(std::pow(0.5 * z + 1, 2) - rb * rb) / rb; // tip load
      const gearfem::rating::agma::BendingGeometry g = gearfem::rating::agma::geometry_factor_J(z, 0, tanW, 20 * deg, 20 * deg);
      EXPECT_LT(g.iterations, 12);
      EXPECT_GT(g.Y_J, prev);
      prev = g.Y_J;
    }
}

TEST(Iso6336_1, StiffnessOfStandardSteelPairs)
{
  // ISO 6336-1 clause 9 rule of thumb (VALIDATION.md): c' ~ 12-15 and c_gamma_alpha ~ 18-22
  // N/(mm um) for standard steel spur pairs (eps_alpha from the AGMA line of action).
  for (auto zz : {std::pair<int, int>{20, 40}, {23, 69}, {32, 60}, {25, 25}})
    {
      const double m = 3e-3;
      const double a = 0.5 * m * (zz.first + zz.second);
      const auto l = gearfem::rating::agma::line_of_action(zz.first, zz.second, m, 20 * deg, 0.5 * m * zz.first + m,
                                          0.5 * m * zz.second + m, a);
      gearfem::rating::iso6336::StiffnessInput in;
      in.z1 = zz.first;
      in.z2 = zz.second;
      in.alpha_n = 20 * deg;
      in.module = m;
      in.eps_alpha = l.contact_ratio;
      const gearfem::rating::iso6336::Stiffness s = gearfem::rating::iso6336::mesh_stiffness(in);
      EXPECT_GT(s.c_prime, 12.0);
      EXPECT_LT(s.c_prime, 15.0);
      // "About 18-22": c' (0.75 eps + 0.25) is 17.8 for 25/25 (eps 1.61) to 21.4 for 32/60.
      EXPECT_GT(s.c_gamma_alpha, 17.5);
      EXPECT_LT(s.c_gamma_alpha, 22.0);
      std::printf("ISO 6336-1 %d/%d: eps %.3f c' %.2f c_ga %.2f N/(mm um)\n", zz.first, zz.second,
                  l.contact_ratio, s.c_prime, s.c_gamma_alpha);
      EXPECT_NEAR(s.C_B, 0.975, 1e-12); // [1 + 0.5(1.2 - 1.25)] [1 - 0]
      EXPECT_NEAR(s.c_gamma_beta / s.c_gamma_alpha, 0.85, 1e-12);
    }
}

TEST(Iso6336_1, HelicalStiffnessOfIsoTr6336_30Example1)
{
  // ISO/TR 6336-30:2017 calculation example 1 (m_n 8, alpha_n 20 deg, beta 15.8 deg, z 17/103,
  // x 0.145/0, basic rack profile D: h_fP 1.4 m_n, F_t/b above 100 N/mm): the published c'_th
  // 17.8558, c' 12.3705 and c_gamma_alpha 17.4648 N/(mm um) (values as quoted in
  // validation/helical/iso_reference.py). eps_alpha 1.54934 from ISO 21771 for a = 500 mm; the
  // published c_gamma_alpha implies 1.54909, hence 2e-4 there.
  gearfem::rating::iso6336::StiffnessInput in;
  in.z1 = 17, in.z2 = 103, in.x1 = 0.145, in.x2 = 0;
  in.beta = 15.8 * deg, in.alpha_n = 20 * deg, in.module = 8e-3;
  in.h_fP1 = in.h_fP2 = 1.4;
  in.eps_alpha = 1.54934;
  const auto s = gearfem::rating::iso6336::mesh_stiffness(in);
  EXPECT_NEAR(s.c_th, 17.85584, 2e-4);
  EXPECT_NEAR(s.c_prime, 12.37047, 2e-4);
  EXPECT_NEAR(s.c_gamma_alpha / 17.46485, 1.0, 2e-4);
}

TEST(Iso6336_1, FaceLoadFactorMethodC)
{
  // ISO 6336-1:2006 clause 7 (method C): K = 1 + F_by c_gb / (2 F_m/b) up to 2, above it
  // sqrt(2 F_by c_gb / (F_m/b)); the two branches meet at 2 (r = 2). Hand values.
  using gearfem::analytical::iso6336::face_load_factor_method_c;
  EXPECT_NEAR(face_load_factor_method_c(10, 14, 200), 1.35, 1e-14);
  EXPECT_NEAR(face_load_factor_method_c(100, 20, 200), std::sqrt(20.0), 1e-14);
  EXPECT_NEAR(face_load_factor_method_c(20, 20, 200), 2.0, 1e-14);
  EXPECT_NEAR(face_load_factor_method_c(20 * (1 + 1e-12), 20, 200), 2.0, 1e-10);
  EXPECT_EQ(face_load_factor_method_c(0, 20, 200), 1.0);
  EXPECT_THROW(face_load_factor_method_c(10, 20, 0), gearfem::InputError);
  EXPECT_THROW(face_load_factor_method_c(-1, 20, 200), gearfem::InputError);
}

TEST(Iso6336_1, ShiftDependenceOfSingleStiffness)
{
  // q' (ISO 6336-1 eq. 71): positive shift on the pinion stiffens the pair (dq'/dx1 =
  // -0.00635 - 0.11654/z1 + 0.01058 x1 < 0 for x1 < 0.6), the quadratic terms give a
  // minimum of q' at x1 = (0.00635 + 0.11654/z1)/0.01058; the wheel shift acts likewise.
  const double z1 = 20, z2 = 40;
  const double q0 = gearfem::rating::iso6336::q_prime(z1, z2, 0, 0);
  EXPECT_NEAR(1 / q0, 1 / (0.04723 + 0.15551 / 20 + 0.25791 / 40), 1e-12);
  EXPECT_LT(gearfem::rating::iso6336::q_prime(z1, z2, 0.5, 0), q0);
  EXPECT_LT(gearfem::rating::iso6336::q_prime(z1, z2, 0, 0.5), q0);
  EXPECT_GT(gearfem::rating::iso6336::q_prime(z1, z2, -0.5, 0), q0);
  const double x_min = (0.00635 + 0.11654 / z1) / 0.01058;
  const double h = 1e-4;
  EXPECT_LT(gearfem::rating::iso6336::q_prime(z1, z2, x_min, 0), gearfem::rating::iso6336::q_prime(z1, z2, x_min + 100 * h, 0));
  EXPECT_LT(gearfem::rating::iso6336::q_prime(z1, z2, x_min, 0), gearfem::rating::iso6336::q_prime(z1, z2, x_min - 100 * h, 0));
  // Load correction below 100 N/mm: (w/100)^0.25.
  gearfem::rating::iso6336::StiffnessInput in;
  in.z1 = 20;
  in.z2 = 40;
  in.alpha_n = 20 * deg;
  in.module = 3e-3;
  in.eps_alpha = 1.6;
  const double c_full = gearfem::rating::iso6336::mesh_stiffness(in).c_prime;
  in.load_per_width = 50e3; // 50 N/mm
  EXPECT_NEAR(gearfem::rating::iso6336::mesh_stiffness(in).c_prime / c_full, std::pow(0.5, 0.25), 1e-12);
  // Rim factor C_R = 1 + ln(b_s/b)/(5 e^(s_R/(5 m))).
  in.load_per_width = 0;
  in.rim_ratio = 0.5;
  in.rim_thickness = 2 * 3e-3;
  EXPECT_NEAR(gearfem::rating::iso6336::mesh_stiffness(in).C_R, 1 + std::log(0.5) / (5 * std::exp(2.0 / 5)), 1e-12);
  in.z1 = 3;
  EXPECT_THROW(gearfem::rating::iso6336::mesh_stiffness(in), gearfem::InputError);
}

namespace
{
  // An exact rack-generated fillet, built here independently of lib/geometry: the tip
  // circle (radius rho) of the cutter tooth centred at u = pi m/2 rolls on the pitch
  // circle r0 = m z/2 (shift x); the fillet is the offset of the trochoid of its centre.
  struct RackFillet
  {
    double m, r0, rho, uc, vc;
    RackFillet(int z, double m_, double alpha, double x, double hfp, double rhofp)
      : m(m_), r0(0.5 * m_ * z), rho(rhofp * m_)
    {
      const double yref = r0 + x * m; // rack reference line in the gear frame at theta = 0
      vc = yref - hfp * m + rho;
      uc = pi * m / 4 + (yref - vc) * std::tan(alpha) + rho / std::cos(alpha);
    }
    // Centre trochoid C(t) = R(t) (uc + r0 t, vc).
    void centre(double t, double &x, double &y) const
    {
      const double u = uc + r0 * t;
      x = u * std::cos(t) - vc * std::sin(t);
      y = u * std::sin(t) + vc * std::cos(t);
    }
    void point(double t, double &x, double &y) const
    {
      const double h = 1e-6;
      double xa, ya, xb, yb;
      centre(t - h, xa, ya);
      centre(t + h, xb, yb);
      double cx, cy;
      centre(t, cx, cy);
      const double dx = xb - xa, dy = yb - ya, n = std::hypot(dx, dy);
      // Offset by rho away from the centre trochoid, towards the gear material.
      x = cx + rho * dy / n;
      y = cy - rho * dx / n;
    }
  };
} // namespace

TEST(Iso6336_3, ThirtyDegreeTangentOnGeneratedFilletMatchesClosedForm)
{
  // The 30-degree construction on an exact generated fillet against the standard's own
  // closed form (ISO 6336-3 eqs. for E, G, H, theta): s_Fn, rho_F and the chord height.
  for (auto c : {std::tuple<int, double>{23, 0.0}, {17, 0.3}, {69, 0.0}, {40, -0.2}})
    {
      const int z = std::get<0>(c);
      const double x = std::get<1>(c), m = 4e-3, alpha = 20 * deg;
      const RackFillet f(z, m, alpha, x, 1.25, 0.25);
      // The fillet starts where the centre is lowest, t_b = -uc/r0; it climbs for t < t_b.
      const double tb = -f.uc / f.r0;
      gearfem::analytical::PlaneCurve curve;
      auto px = [&f](double t) { double X, Y; f.point(t, X, Y); return X; };
      auto py = [&f](double t) { double X, Y; f.point(t, X, Y); return Y; };
      auto deriv = [](const std::function<double(double)> &g, double t, int k) {
        const double h = 1e-4;
        if (k == 0) return g(t);
        if (k == 1) return (g(t + h) - g(t - h)) / (2 * h);
        return (g(t + h) - 2 * g(t) + g(t - h)) / (h * h);
      };
      curve.x = [=](double t, int k) { return deriv(px, t, k); };
      curve.y = [=](double t, int k) { return deriv(py, t, k); };
      curve.t0 = tb - 1e-6;
      curve.t1 = tb - 0.6;
      const gearfem::rating::iso6336::CriticalSection cs = gearfem::rating::iso6336::critical_section(curve);
      const gearfem::rating::iso6336::RackFilletClosedForm cf = gearfem::rating::iso6336::rack_fillet_closed_form(z, m, alpha, x, 1.25, 0.25);
      EXPECT_NEAR(cs.s_Fn / cf.s_Fn, 1.0, 1e-6) << "z = " << z;
      EXPECT_NEAR(cs.rho_F / cf.rho_F, 1.0, 1e-4) << "z = " << z;
      EXPECT_NEAR((cs.y - cf.y) / m, 0.0, 1e-6) << "z = " << z;
    }
}

TEST(Iso6336_3, FormFactorsOfSeed001Pinion)
{
  // Y_F, Y_S for the 23-tooth pinion (x = 0, h_fP 1.25, rho_fP 0.25), tip load and outer
  // point of single contact, with h_Fe from the load line. Checked against ISO 6336-3's
  // closed form for h_Fe (eq. 30) evaluated here from its own formula.
  const int z = 23;
  const double m = 4e-3, an = 20 * deg;
  const gearfem::rating::iso6336::RackFilletClosedForm cf = gearfem::rating::iso6336::rack_fillet_closed_form(z, m, an, 0, 1.25, 0.25);
  gearfem::rating::iso6336::CriticalSection cs;
  cs.s_Fn = cf.s_Fn;
  cs.rho_F = cf.rho_F;
  cs.y = cf.y;
  gearfem::rating::iso6336::InvoluteFlank fl{0.5 * m * z * std::cos(an), (pi / 2) / z + std::tan(an) - an};
  const double ra = 0.5 * m * z + m;
  const gearfem::rating::iso6336::RootFactors tip = gearfem::rating::iso6336::root_factors(cs, fl, ra, m, an);
  // ISO 6336-3: h_Fe/m = 0.5[(cos g - sin g tan a_Fen) d_en/m - z cos(pi/3 - th) - G/cos th + rho_fP].
  const double a_en = std::acos(fl.rb / ra);
  const double g = fl.psi_b - (std::tan(a_en) - a_en);
  const double aF = a_en - g;
  const double hFe = 0.5 * m * ((std::cos(g) - std::sin(g) * std::tan(aF)) * 2 * ra / m -
                                z * std::cos(pi / 3 - cf.theta) - cf.G / std::cos(cf.theta) + 0.25);
  EXPECT_NEAR(tip.h_Fe / hFe, 1.0, 1e-12);
  EXPECT_NEAR(tip.alpha_Fen, aF, 1e-14);
  // Published ISO 6336-3 chart values for z = 23, x = 0 are Y_Fa ~ 2.7, Y_Sa ~ 1.6.
  EXPECT_NEAR(tip.Y_F, 2.7, 0.15);
  EXPECT_NEAR(tip.Y_S, 1.6, 0.1);
  EXPECT_NEAR(tip.Y_F * tip.Y_S, 4.3, 0.25);
}
