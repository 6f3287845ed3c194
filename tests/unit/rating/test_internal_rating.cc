// ISO 6336 and AGMA rating of internal pairs (lib/rating/internal.h). Every figure is checked
// against something independent of the code under test; each test says against what.
#include "base/errors.h"
#include "base/units.h"
#include "gearbox/stages.h"
#include "rating/internal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace gearfem;
using namespace gearfem::rating;

namespace
{
  using gearfem::units::pi;
  constexpr double deg = pi / 180, mm = 1e-3;

  double row(const RatingReport &r, const std::string &standard, const std::string &symbol, std::size_t i = 0)
  {
    return r.row(standard, symbol).values.at(i);
  }

  geometry::ToothProfile pinion(int z, double m, double x, double rho, double k, double b)
  {
    geometry::GearParameters p;
    p.name = "Pinion";
    p.teeth = z;
    p.profile_shift = x;
    p.tip_shortening = k;
    p.face_width = b;
    p.rack.module = m;
    p.rack.pressure_angle = 20 * deg;
    p.rack.root_radius = rho;
    return geometry::ToothProfile::generate(p);
  }

  /// A ring cut by a z0-tooth shaper (x0 = 0, tip radius rho0 m). root > 0: the cutter
  /// addendum is set so that the ring's root radius is `root` [m].
  geometry::InternalToothProfile ring(int z, double m, double x, int z0, double rho0, double root = 0.0)
  {
    geometry::InternalGearParameters g;
    g.teeth = z;
    g.module = m;
    g.pressure_angle = 20 * deg;
    g.profile_shift = x;
    g.cutter.teeth = z0;
    g.cutter.tip_radius = rho0;
    geometry::InternalToothProfile t = geometry::InternalToothProfile::generate(g);
    if (root > 0)
      {
        // r_f2 = a0 + r0 + (h_a0 + x0) m, and a0 does not depend on h_a0.
        g.cutter.addendum = (root - t.generating_center_distance() - 0.5 * m * z0) / m;
        t = geometry::InternalToothProfile::generate(g);
      }
    return t;
  }

  geometry::InternalMesh mesh(const geometry::ToothProfile &p, const geometry::InternalToothProfile &r, double a)
  {
    geometry::InternalMeshInput in;
    r.fill_mesh_input(in);
    in.z1 = p.teeth();
    in.x1 = p.parameters().profile_shift;
    in.tip_radius1 = p.radii().tip;
    in.root_radius1 = p.radii().root;
    in.form_radius1 = p.radii().form;
    in.center_distance = a;
    return geometry::internal_mesh(in);
  }
} // namespace

// ---------------------------------------------------------------- rim thickness factors

TEST(InternalRating, RimFactorsAgainstClosedForms)
{
  // Reference: the standards' relations written out here. ISO 6336-3:2006 clause 8, external
  // gears: Y_B = 1.6 ln(2.242 h_t/s_R) for 0.5 < s_R/h_t < 1.2, 1 above; internal gears (in
  // module): Y_B = 1.15 ln(8.324 m_n/s_R) for 1.75 < s_R/m_n < 3.5, 1 above. AGMA 2101-D04:
  // K_B = 1.6 ln(2.242/m_B) for 0.5 <= m_B < 1.2, 1 above.
  const double h_t = 2.25 * mm, m = 1 * mm;
  for (double r : {0.55, 0.7, 0.9, 1.1, 1.19})
    EXPECT_NEAR(iso6336::Y_B_external(r * h_t, h_t), 1.6 * std::log(2.242 / r), 1e-12) << r;
  for (double r : {1.2, 1.5, 3.0})
    EXPECT_EQ(iso6336::Y_B_external(r * h_t, h_t), 1.0);
  for (double r : {1.8, 2.0, 2.5, 3.0, 3.49})
    EXPECT_NEAR(iso6336::Y_B_internal(r * m, m), 1.15 * std::log(8.324 / r), 1e-12) << r;
  for (double r : {3.5, 4.0, 10.0})
    EXPECT_EQ(iso6336::Y_B_internal(r * m, m), 1.0);
  for (double r : {0.5, 0.6, 0.8, 1.0, 1.19})
    EXPECT_NEAR(agma::K_B(r), 1.6 * std::log(2.242 / r), 1e-12) << r;
  EXPECT_EQ(agma::K_B(1.2), 1.0);
  // Continuity at the upper limits: the external relation (ISO and AGMA alike) meets 1 at
  // s_R/h_t = 1.2 to 1e-4; the internal one at s_R/m_n = 3.5 to 0.4 % (1.15 ln(8.324/3.5) =
  // 0.9964: the standard's constants are rounded).
  EXPECT_NEAR(iso6336::Y_B_external(1.2 * h_t * (1 - 1e-9), h_t), 1.0, 1e-4);
  EXPECT_NEAR(agma::K_B(1.2 * (1 - 1e-9)), 1.0, 1e-4);
  EXPECT_NEAR(iso6336::Y_B_internal(3.5 * m * (1 - 1e-9), m), 1.0, 0.004);
  // The lower limits: 1.6 ln(2.242/0.5) = 2.4008, 1.15 ln(8.324/1.75) = 1.7935.
  EXPECT_NEAR(iso6336::Y_B_external(0.5 * h_t * (1 + 1e-9), h_t), 2.4008, 1e-4);
  EXPECT_NEAR(iso6336::Y_B_internal(1.75 * m * (1 + 1e-9), m), 1.7935, 1e-4);
  // Outside the standards' ranges: InputError naming the ratio, its value and the range.
  EXPECT_THROW(iso6336::Y_B_external(0.4 * h_t, h_t), InputError);
  EXPECT_THROW(iso6336::Y_B_internal(1.5 * m, m), InputError);
  try
    {
      iso6336::Y_B_internal(1.5 * m, m);
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("s_R/m_n"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("1.75"), std::string::npos) << e.what();
    }
}

// ---------------------------------------------------------------- the ring's critical section

TEST(InternalRating, RingSectionTendsToTheRackTooth)
{
  // Reference: the substitute rack tooth written out here. A rack tooth of the ring's basic
  // rack (half thickness pi m/4 on the reference line, flanks at alpha, dedendum h_fP, root
  // arc rho_fP tangent to flank and root line) has, where its root arc's tangent makes 60 deg
  // with the tooth axis, the chord s/m = 2[pi/4 + (h_fP - rho) tan a + rho/cos a - rho cos 60]
  // at the height rho (1 - sin 60) above the root line. As z2 grows the closed form of
  // internal_gear_section must approach it (error about 4/z2).
  const double m = 1 * mm, a = 20 * deg, hfP = 1.25, rho = 0.3, x = -0.2;
  const double s_rack = 2 * m * (pi / 4 + (hfP - rho) * std::tan(a) + rho / std::cos(a) - rho * 0.5);
  double previous = 1e9;
  for (int z : {60, 600, 6000, 60000})
    {
      const iso6336::InternalSection s = iso6336::internal_gear_section(z, m, a, x, hfP, rho);
      const double r_root = 0.5 * m * z + (hfP - x) * m;
      const double height = r_root - s.y; // the chord's distance from the root circle
      const double err = std::abs(s.s_Fn / s_rack - 1);
      std::printf("z2 = %5d: s_Fn/m %.5f (rack %.5f), chord %.5f m above the root (rack %.5f), rho_F/m %.3f\n", z,
                  s.s_Fn / m, s_rack / m, height / m, rho * (1 - std::sin(pi / 3)), s.rho_F / m);
      EXPECT_LT(err, previous);
      EXPECT_LT(err, 5.0 / z);
      EXPECT_NEAR(height / m, rho * (1 - std::sin(pi / 3)), 40.0 / z);
      EXPECT_DOUBLE_EQ(s.rho_F, rho * m);
      previous = err;
    }
}

// ---------------------------------------------------------------- a published worked example

TEST(InternalRating, KisssoftPlanetRingExample)
{
  // Reference: a KISSsoft 03/2017 report, ISO 6336:2006 method B, of the NREL 5 MW
  // planetary stage, public in github.com/gfsReboucas/Drivetrain (@NREL_5MW/stage_01.rtf):
  // planet z = 17, x = 0.8021, tip diameter 905.470 mm (k m = 10.861 mm), basic rack
  // 1.25/0.38/1.0; ring z = -56, x = -0.5013, root diameter 2677.618 mm, basic rack
  // 1.25/0.30/1.0, cut by a z0 = 36, x0 = 0 shaper; m = 45 mm, b = 491 mm, a = 863 mm,
  // F_t = 779454.877 N at the reference circle; K_A K_gamma = 1.25 x 1.10, K_v = 1.05,
  // K_Hbeta = 1.15, K_Halpha = 1. Its printed figures are rounded to 3-4 digits.
  const double m = 45 * mm;
  const geometry::ToothProfile p = pinion(17, m, 0.8021, 0.38, 10.861 / 45, 491 * mm);
  const geometry::InternalToothProfile r = ring(56, m, -0.5013, 36, 0.30, 0.5 * 2677.618 * mm);
  const geometry::InternalMesh k = mesh(p, r, 863 * mm);
  InternalRatingInput in;
  const double Ft = 779454.877;
  in.rating.torques = {Ft * 0.5 * 17 * m};
  in.rating.K_A = 1.25 * 1.10, in.rating.K_v_iso = 1.05, in.rating.K_Hbeta = 1.15;
  const RatingReport rep = rate_internal(p, r, k, in);
  const std::string I = "ISO 6336";
  EXPECT_NEAR(p.radii().tip * 2 / mm, 905.470, 0.01);
  EXPECT_NEAR(row(rep, I, "alpha_wt"), 17.161, 0.001);
  EXPECT_NEAR(row(rep, I, "eps_alpha"), 1.278, 0.0006);
  EXPECT_NEAR(row(rep, I, "F_t"), Ft, 1e-6 * Ft);
  EXPECT_NEAR(row(rep, I, "Z_H"), 2.71, 0.005);
  EXPECT_NEAR(row(rep, I, "Z_E"), 189.81, 0.01);
  EXPECT_NEAR(row(rep, I, "Z_eps"), 0.952, 0.0006);
  EXPECT_NEAR(row(rep, I, "sigma_H0"), 588.62, 0.1);
  EXPECT_NEAR(row(rep, I, "Z_B"), 1.00, 0.005);
  EXPECT_EQ(row(rep, I, "Z_D"), 1.0);
  EXPECT_NEAR(row(rep, I, "sigma_H1"), 758.46, 0.5);
  EXPECT_NEAR(row(rep, I, "sigma_H2"), 758.46, 0.3);
  // Planet root (ISO 6336-3 method B at its outer single contact point of the ring mesh):
  // KISSsoft Y_F 1.14, Y_S 2.38, h_F 49.53 mm, alpha_Fen 29.87 deg, s_Fn 104.13 mm,
  // rho_F 17.19 mm, sigma_F0 95.70 N/mm^2.
  EXPECT_NEAR(row(rep, I, "s_Fn1"), 104.13, 0.15);
  EXPECT_NEAR(row(rep, I, "rho_F1"), 17.19, 0.05);
  EXPECT_NEAR(row(rep, I, "h_Fe1"), 49.53, 0.1);
  EXPECT_NEAR(row(rep, I, "alpha_Fen1"), 29.87, 0.02);
  EXPECT_NEAR(row(rep, I, "Y_F1"), 1.14, 0.006);
  EXPECT_NEAR(row(rep, I, "Y_S1"), 2.38, 0.006);
  EXPECT_NEAR(row(rep, I, "sigma_F01"), 95.70, 0.3);
  // Ring: the load point and its angle are the same construction (KISSsoft: single-contact
  // diameter 2497.634 mm, alpha_Fen 19.59 deg); the closed-form section within 1 % of
  // KISSsoft's s_Fn 129.40 mm at d_sFn 2673.522 mm, h_F 78.40 mm and Y_F 1.27 within 1.5 %.
  EXPECT_NEAR(row(rep, I, "d_en2"), 2497.634, 0.05);
  EXPECT_NEAR(row(rep, I, "alpha_Fen2"), 19.59, 0.01);
  EXPECT_NEAR(row(rep, I, "s_Fn2") / 129.40, 1.0, 0.01);
  EXPECT_NEAR(row(rep, I, "d_sFn2") / 2673.522, 1.0, 0.001);
  EXPECT_NEAR(row(rep, I, "h_Fe2") / 78.40, 1.0, 0.015);
  EXPECT_NEAR(row(rep, I, "Y_F2") / 1.27, 1.0, 0.025);
  // KISSsoft's ring root radius (22.24 mm, from its own pinion-cutter computation) is not
  // the cutter's 13.5 mm tip radius that the generated fillet has (checked to 1 %), so
  // Y_S2 differs; the same eq. 43 with KISSsoft's s_Fn, h_F and rho_F gives its Y_S 2.13.
  EXPECT_NEAR(row(rep, I, "rho_F2"), 13.5, 1e-9);
  EXPECT_NEAR(row(rep, I, "rho_F2,gen") / 13.5, 1.0, 0.01);
  // The closed form against the exact generated ring (60 deg tangent on the shaper-cut
  // fillet, same load line): the chord 2.7 % narrower, the arm within 1.5 %.
  EXPECT_NEAR(row(rep, I, "s_Fn2,gen") / row(rep, I, "s_Fn2"), 1.0, 0.035);
  EXPECT_NEAR(row(rep, I, "h_Fe2,gen") / row(rep, I, "h_Fe2"), 1.0, 0.015);
  const double L = 129.40 / 78.40, q = 129.40 / (2 * 22.24);
  EXPECT_NEAR((1.2 + 0.13 * L) * std::pow(q, 1 / (1.21 + 2.3 / L)), 2.13, 0.005);
  std::printf("KISSsoft planet-ring: Z_H %.4f (2.71) Z_eps %.4f (0.952) sigma_H0 %.2f (588.62) sigma_H %.2f "
              "(758.46)\n  planet Y_F %.3f (1.14) Y_S %.3f (2.38) h_F %.2f (49.53) s_Fn %.2f (104.13) rho_F %.2f "
              "(17.19)\n  ring s_Fn %.2f (129.40) d_sFn %.2f (2673.52) h_F %.2f (78.40) alpha_Fen %.3f (19.59) Y_F "
              "%.3f (1.27) Y_S %.3f (2.13) rho_F %.2f (22.24)\n  generated ring: s_Fn %.2f rho_F %.2f h_F %.2f Y_F "
              "%.3f Y_S %.3f\n",
              row(rep, I, "Z_H"), row(rep, I, "Z_eps"), row(rep, I, "sigma_H0"), row(rep, I, "sigma_H1"),
              row(rep, I, "Y_F1"), row(rep, I, "Y_S1"), row(rep, I, "h_Fe1"), row(rep, I, "s_Fn1"),
              row(rep, I, "rho_F1"), row(rep, I, "s_Fn2"), row(rep, I, "d_sFn2"), row(rep, I, "h_Fe2"),
              row(rep, I, "alpha_Fen2"), row(rep, I, "Y_F2"), row(rep, I, "Y_S2"), row(rep, I, "rho_F2"),
              row(rep, I, "s_Fn2,gen"), row(rep, I, "rho_F2,gen"), row(rep, I, "h_Fe2,gen"), row(rep, I, "Y_F2,gen"),
              row(rep, I, "Y_S2,gen"));
}

// ---------------------------------------------------------------- the gearbox's planet-ring mesh

TEST(InternalRating, Seed001StageOnePlanetRingAgainstGearbox)
{
  // Reference: lib/gearbox/stages.cc (mesh_geometry + mesh_stress) for inputs/seed001_gearbox.prm
  // stage 1, planet 28 (x 0.6, bore 120 mm) - ring 74 (x -0.9, outside diameter 572 mm),
  // m 6 mm, b 110 mm, a = r_w2 - r_w1 = 139.8 mm (Siasos 2010). Same radii, centre distance
  // and factors: ISO sigma_H1/sigma_H2, the AGMA sigma_H and the planet's AGMA sigma_F agree
  // to rounding; the planet's ISO root stress (stages: the rack closed form, here the
  // generated fillet) within 1 %. Z_H, Z_eps and sigma_H0 also against their closed forms
  // written out here.
  gearbox::StageInput s;
  s.z_sun = 16, s.z_planet = 28, s.z_ring = 74, s.x_sun = 0.7, s.x_planet = 0.6, s.x_ring = -0.9;
  s.module = 6 * mm, s.face_width = 110 * mm, s.pressure_angle = 20 * deg;
  gearbox::AgmaFactors f;
  const gearbox::MeshGeometry g =
    gearbox::mesh_geometry("planet-ring", "planet", "ring", true, 28, 74, 0.6, -0.9, s, 120 * mm, 572 * mm, f);
  const geometry::ToothProfile p = pinion(28, 6 * mm, 0.6, 0.25, 0.0, 110 * mm);
  const geometry::InternalToothProfile r = ring(74, 6 * mm, -0.9, 25, 0.25);
  const geometry::InternalMesh k = mesh(p, r, g.a);
  InternalRatingInput in;
  in.rating.torques = {20000, 10000, 5000};
  in.pinion_rim_thickness = p.radii().root - 60 * mm;
  in.ring_rim_thickness = 286 * mm - r.radii().root;
  const RatingReport rep = rate_internal(p, r, k, in);
  EXPECT_NEAR(g.r_a2, r.radii().tip, 1e-12);
  EXPECT_NEAR(g.r_a1, p.radii().tip, 1e-9);
  const std::string I = "ISO 6336", A = "AGMA";
  const double aw = k.alpha_w, eps = k.contact_ratio, u = 74.0 / 28;
  EXPECT_NEAR(aw, g.loa.phi_r, 1e-12);
  EXPECT_NEAR(row(rep, I, "Z_H"), std::sqrt(2 * std::cos(aw) / (std::pow(std::cos(20 * deg), 2) * std::sin(aw))), 1e-12);
  EXPECT_NEAR(row(rep, I, "Z_eps"), std::sqrt((4 - eps) / 3), 1e-12);
  EXPECT_NEAR(row(rep, I, "Z_B"), g.iso.Z_B, 1e-9);
  for (std::size_t i = 0; i < in.rating.torques.size(); ++i)
    {
      const double T = in.rating.torques[i], d1 = 28 * 6 * mm;
      const double s0 = 189.812 * std::sqrt(2 * T / d1 / (d1 * 110 * mm) * (u - 1) / u) * row(rep, I, "Z_H") *
                        row(rep, I, "Z_eps") / 1e3; // Z_E of steel 206 GPa, 0.3 [sqrt(MPa)]
      EXPECT_NEAR(row(rep, I, "sigma_H0", i) / s0, 1.0, 2e-5);
      // stages: F_t at Siasos' working radius r_w1, F_t,ISO = F_t r_w1/r_1 = T/r_1.
      const gearbox::MeshStress ms = gearbox::mesh_stress(g, T / g.r_w1, f);
      EXPECT_NEAR(row(rep, I, "sigma_H1", i) / (ms.sigma_H1_iso / 1e6), 1.0, 1e-9);
      EXPECT_NEAR(row(rep, I, "sigma_H2", i) / (ms.sigma_H2_iso / 1e6), 1.0, 1e-9);
      EXPECT_NEAR(row(rep, I, "sigma_F1", i) / (ms.sigma_F1_iso / 1e6), 1.0, 0.01);
      // AGMA: F_t at d_w1 = 2a/(u - 1).
      const gearbox::MeshStress ma = gearbox::mesh_stress(g, 2 * T / g.d_w1, f);
      EXPECT_NEAR(row(rep, A, "sigma_H", i) / (ma.sigma_H / 1e6), 1.0, 1e-9);
      EXPECT_NEAR(row(rep, A, "sigma_F1", i) / (ma.sigma_F1 / 1e6), 1.0, 1e-9);
      std::printf("T = %5.0f N m: ISO sigma_H1 %.2f (gearbox %.2f), sigma_F1 %.2f (%.2f), sigma_F2 %.2f; AGMA "
                  "sigma_H %.2f (%.2f), sigma_F1 %.2f (%.2f), sigma_F2 %.2f MPa\n",
                  T, row(rep, I, "sigma_H1", i), ms.sigma_H1_iso / 1e6, row(rep, I, "sigma_F1", i),
                  ms.sigma_F1_iso / 1e6, row(rep, I, "sigma_F2", i), row(rep, A, "sigma_H", i), ma.sigma_H / 1e6,
                  row(rep, A, "sigma_F1", i), ma.sigma_F1 / 1e6, row(rep, A, "sigma_F2", i));
    }
  EXPECT_NEAR(row(rep, A, "Z_I"), g.Z_I, 1e-12);
  // The ring: the closed form against the exact generated ring (thin teeth, x2 = -0.9): the
  // chord within 5 %, the closed form's Y_F the larger; the generated fillet's radius at the
  // section is never below the cutter's tip radius (an envelope of the tip arc), here 11 %
  // above it, so rho_F2 = rho_a0 is the conservative side too.
  EXPECT_NEAR(row(rep, I, "s_Fn2,gen") / row(rep, I, "s_Fn2"), 1.0, 0.05);
  EXPECT_GT(row(rep, I, "Y_F2"), row(rep, I, "Y_F2,gen"));
  EXPECT_GE(row(rep, I, "rho_F2,gen"), row(rep, I, "rho_F2"));
  EXPECT_NEAR(row(rep, I, "rho_F2,gen") / row(rep, I, "rho_F2"), 1.11, 0.02);
  EXPECT_EQ(row(rep, A, "K_B1"), g.K_B1);
  EXPECT_EQ(row(rep, A, "K_B2"), g.K_B2);
  std::printf("ring: s_Fn2 %.3f (generated %.3f) mm, Y_F2 %.3f (%.3f), Y_S2 %.3f (%.3f); AGMA Y_J2 %.3f, Y_J1 %.3f\n",
              row(rep, I, "s_Fn2"), row(rep, I, "s_Fn2,gen"), row(rep, I, "Y_F2"), row(rep, I, "Y_F2,gen"),
              row(rep, I, "Y_S2"), row(rep, I, "Y_S2,gen"), row(rep, A, "Y_J2"), row(rep, A, "Y_J1"));
}

// ---------------------------------------------------------------- bad input, writers

TEST(InternalRating, BadInputNamesTheEntry)
{
  // Reference: the project's error convention (lib/base/errors.h): InputError naming the
  // parameter, its value and the allowed range.
  const geometry::ToothProfile p = pinion(28, 6 * mm, 0.6, 0.25, 0.0, 110 * mm);
  const geometry::InternalToothProfile r = ring(74, 6 * mm, -0.9, 25, 0.25);
  const geometry::InternalMesh k = mesh(p, r, 139.8 * mm);
  auto message = [&](const InternalRatingInput &in) {
    try
      {
        rate_internal(p, r, k, in);
      }
    catch (const InputError &e)
      {
        return std::string(e.what());
      }
    return std::string("no InputError");
  };
  InternalRatingInput in;
  in.ring_rim_thickness = 1.5 * 6 * mm; // s_R/m_n = 1.5 <= 1.75
  std::string e = message(in);
  EXPECT_NE(e.find("Rating/Ring rim thickness"), std::string::npos) << e;
  EXPECT_NE(e.find("9 mm"), std::string::npos) << e;
  EXPECT_NE(e.find("> 10.5 mm"), std::string::npos) << e;
  in = {};
  in.pinion_rim_thickness = 5 * mm; // h_t = 13.5 mm: s_R/h_t = 0.37
  e = message(in);
  EXPECT_NE(e.find("Rating/Pinion rim thickness"), std::string::npos) << e;
  in = {};
  in.rating.K_B = 1.2;
  EXPECT_NE(message(in).find("Rating/AGMA rim thickness factor"), std::string::npos);
  in = {};
  in.rating.accuracy_grade = 6;
  EXPECT_NE(message(in).find("Rating/ISO accuracy grade"), std::string::npos);
  in = {};
  in.rating.torques = {100, -5};
  EXPECT_NE(message(in).find("Rating/Pinion torques"), std::string::npos);
  // A mesh of another pinion.
  const geometry::InternalMesh other = mesh(pinion(27, 6 * mm, 0.6, 0.25, 0.0, 110 * mm), r, 139.8 * mm);
  EXPECT_THROW(rate_internal(p, r, other, InternalRatingInput{}), InputError);
  // Thin rims within range give the closed forms (s_R2/m_n = 2.5, m_B1 = 0.8).
  in = {};
  in.ring_rim_thickness = 2.5 * 6 * mm;
  in.pinion_rim_thickness = 0.8 * (p.radii().tip - p.radii().root);
  const RatingReport rep = rate_internal(p, r, k, in);
  EXPECT_NEAR(row(rep, "ISO 6336", "Y_B2"), 1.15 * std::log(8.324 / 2.5), 1e-12);
  EXPECT_NEAR(row(rep, "ISO 6336", "Y_B1"), 1.6 * std::log(2.242 / 0.8), 1e-12);
  EXPECT_NEAR(row(rep, "AGMA", "K_B1"), 1.6 * std::log(2.242 / 0.8), 1e-12);
  EXPECT_NEAR(row(rep, "AGMA", "m_B2"), 15 * mm / (r.radii().root - r.radii().tip), 1e-12);
  // The report goes through RatingReport's writers.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "gearfem_internal_rating";
  std::filesystem::create_directories(dir);
  rep.write_markdown(dir / "rating.md", "Internal pair");
  rep.write_csv(dir / "rating.csv");
  EXPECT_GT(std::filesystem::file_size(dir / "rating.md"), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir / "rating.csv"), 1000u);
  std::filesystem::remove_all(dir);
}
