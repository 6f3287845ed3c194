// The analytical models on the generated geometry (involute + real fillet): AGMA Y_J and
// the ISO 30-degree section on the exact fillet curves, the potential-energy mesh
// stiffness of the 62/62 case, the Weber/Cornell model against ISO 6336-1.
#include "rating/agma.h"
#include "base/units.h"
#include "calibration/model.h"
#include "analytical/cycle_table.h"
#include "analytical/from_geometry.h"
#include "rating/iso6336.h"
#include "analytical/mesh_cycle.h"
#include "analytical/ricker_load_sharing.h"
#include "analytical/tooth.h"
#include "geometry/pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace gearfem;
using namespace gearfem::analytical;
using namespace gearfem::calibration;

namespace
{
  using gearfem::units::pi;
  constexpr double deg = pi / 180;

  geometry::GearParameters gear(int z, double m, double x = 0.0, double b = 0.02)
  {
    geometry::GearParameters g;
    g.name = "Gear";
    g.teeth = z;
    g.profile_shift = x;
    g.face_width = b;
    g.rack.module = m;
    g.rack.pressure_angle = 20 * deg;
    g.rack.addendum = 1.0;
    g.rack.dedendum = 1.25;
    g.rack.root_radius = 0.25;
    return g;
  }

  geometry::GearPair pair(int z1, int z2, double m, double x1 = 0, double x2 = 0)
  {
    return geometry::GearPair(geometry::ToothProfile::generate(gear(z1, m, x1)),
                              geometry::ToothProfile::generate(gear(z2, m, x2)), {});
  }
} // namespace

TEST(GeneratedGeometry, ThicknessTableAndInvoluteData)
{
  // psi_b from the generated flank equals the closed form (pi/2 + 2 x tan a)/z + inv a, and
  // the tabulated t(y) reproduces half_width_at_height between the table points.
  const geometry::ToothProfile p = geometry::ToothProfile::generate(gear(23, 4e-3, 0.2));
  const InvoluteTooth t = involute_tooth(p);
  EXPECT_NEAR(t.psi_b, (pi / 2 + 2 * 0.2 * std::tan(20 * deg)) / 23 + std::tan(20 * deg) - 20 * deg, 1e-9);
  for (double s : {0.013, 0.31, 0.52, 0.77, 0.93})
    {
      const double y = s * t.beam.height;
      EXPECT_NEAR(t.beam.thickness(y) / (2 * p.half_width_at_height(p.radii().root + y)), 1.0, 2e-4) << s;
    }
}

TEST(GeneratedGeometry, IsoCriticalSectionOnGeneratedFillet)
{
  // ISO 6336-3: the 30-degree construction on the generated (rack) fillet against the
  // standard's closed form for the same rack.
  for (auto c : {std::pair<int, double>{23, 0.0}, {69, 0.0}, {17, 0.4}})
    {
      const geometry::ToothProfile p = geometry::ToothProfile::generate(gear(c.first, 4e-3, c.second));
      const gearfem::rating::iso6336::CriticalSection cs = gearfem::rating::iso6336::critical_section(fillet_curve(p));
      const auto cf = gearfem::rating::iso6336::rack_fillet_closed_form(c.first, 4e-3, 20 * deg, c.second, 1.25, 0.25);
      EXPECT_NEAR(cs.s_Fn / cf.s_Fn, 1.0, 1e-6) << c.first;
      EXPECT_NEAR(cs.rho_F / cf.rho_F, 1.0, 1e-5) << c.first;
      EXPECT_NEAR((cs.y - cf.y) / 4e-3, 0.0, 1e-6) << c.first;
    }
}

TEST(GeneratedGeometry, AgmaLewisParabolaOnGeneratedFilletMatchesAgma908)
{
  // AGMA 908: Lewis parabola tangent to the fillet. On the exact rack-generated fillet (the
  // n_o -> infinity limit) against AGMA 908's own trochoid with a 10000-tooth shaper.
  const geometry::GearPair gp = pair(23, 69, 4e-3);
  const gearfem::rating::agma::LineOfAction l = gearfem::rating::agma::line_of_action(23, 69, 4e-3, 20 * deg, 50e-3, 142e-3, 184e-3);
  for (int i : {1, 2})
    {
      const int z = i == 1 ? 23 : 69;
      const double tanW = i == 1 ? l.C4 / l.Rb1 : (l.C6 - l.C2) / l.Rb2;
      const gearfem::rating::agma::BendingGeometry ref = gearfem::rating::agma::geometry_factor_J(z, 0, tanW, 20 * deg, l.phi_r);
      const gearfem::rating::agma::LewisSection s = gearfem::rating::agma::lewis_section(fillet_curve(gp.gear(i)), ref.r_nL * 4e-3);
      gearfem::rating::agma::BendingGeometry g = ref;
      g.s_F = s.s_F / 4e-3;
      g.h_F = s.h_F / 4e-3;
      g.rho_F = s.rho_F / 4e-3;
      gearfem::rating::agma::form_and_stress_factors(g, 20 * deg, l.phi_r);
      EXPECT_NEAR(g.s_F / ref.s_F, 1.0, 2e-4) << z;
      EXPECT_NEAR(g.h_F / ref.h_F, 1.0, 2e-4) << z;
      EXPECT_NEAR(g.rho_F / ref.rho_F, 1.0, 2e-3) << z;
      EXPECT_NEAR(g.Y_J / ref.Y_J, 1.0, 1e-3) << z;
      std::printf("AGMA Y_J z=%d: 908 closed form %.5f, generated fillet %.5f\n", z, ref.Y_J, g.Y_J);
    }
}

TEST(GeneratedGeometry, PotentialEnergyMeshStiffness62x62)
{
  // Reference pair: 62/62, m 2, b 20 mm, bore 35 mm, E 211 GPa: max mesh stiffness of order 4e8 N/m
  // (the exact reference is held back). Plane stress (the FE default) and plane strain.
  const geometry::GearPair gp = pair(62, 62, 2e-3);
  for (auto plane : {PlaneCondition::plane_stress, PlaneCondition::plane_strain})
    {
      PairModelOptions o;
      o.model = StiffnessModel::potential_energy;
      o.plane = plane;
      const double r_int = 0.5 * 35e-3; // bore diameter 35 mm
      PairCompliance pc(involute_tooth(gp.gear(1), r_int), involute_tooth(gp.gear(2), r_int),
                        {211e9, 0.3}, {211e9, 0.3}, 20e-3, pair_line(gp), o);
      const auto cycle = mesh_cycle(pc.mesh_model(), 1000.0, 400);
      double kmax = 0, kmin = 1e300;
      for (const auto &s : cycle)
        kmax = std::max(kmax, s.stiffness), kmin = std::min(kmin, s.stiffness);
      std::printf("PE 62/62 m2 b20 (%s): k_max = %.4g N/m, k_min = %.4g N/m\n",
                  plane == PlaneCondition::plane_stress ? "plane stress" : "plane strain", kmax, kmin);
      EXPECT_GT(kmax, 2e8);
      EXPECT_LT(kmax, 8e8);
      EXPECT_LT(kmin, 0.75 * kmax); // single-pair zone
    }
}

TEST(GeneratedGeometry, TableInterpolationAndPeriodicity)
{
  const geometry::GearPair gp = pair(23, 69, 4e-3);
  PairCompliance pc(involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {205e9, 0.3},
                    {205e9, 0.3}, 70e-3, pair_line(gp));
  const PairLine &l = pc.line();
  for (double s : {0.01, 0.2, 0.5, 0.77, 0.99})
    {
      const double g = l.g_A + s * (l.g_E - l.g_A);
      EXPECT_NEAR(pc(g, 5000) / pc.parts_exact(g, 5000).total(), 1.0, 1e-5) << s;
    }
  const MeshModel mm = pc.mesh_model();
  const auto c = mesh_cycle(mm, 10870.0, 200, 2);
  for (int i = 0; i < 100; ++i)
    {
      EXPECT_NEAR(c[i].stiffness / c[i + 100].stiffness, 1.0, 1e-12);
      double F = 0;
      for (double f : c[i].pair_load)
        F += f;
      EXPECT_NEAR(F / 10870.0, 1.0, 1e-12);
    }
}

TEST(GeneratedGeometry, WeberCornellAgainstIso6336)
{
  // ISO 6336-1 (plane strain, mean over the mesh): c_gamma_alpha ~ 20 N/(mm um). Our
  // Weber/Cornell model on the generated 23/69 pair in plane strain: report the ratio and
  // require the same order (+-35 %). Plane stress must be softer. Positive pinion shift
  // stiffens both (ISO q' shift dependence).
  auto mean_k = [](const geometry::GearPair &gp, PlaneCondition plane) {
    PairModelOptions o;
    o.plane = plane;
    PairCompliance pc(involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {206e9, 0.3},
                      {206e9, 0.3}, 20e-3, pair_line(gp), o);
    const auto c = mesh_cycle(pc.mesh_model(), 20e-3 * 300e3, 200); // 300 N/mm
    double k = 0;
    for (const auto &s : c)
      k += s.stiffness;
    return k / c.size() / 20e-3 / 1e9; // N/(mm um)
  };
  const geometry::GearPair gp = pair(23, 69, 4e-3);
  const double k_strain = mean_k(gp, PlaneCondition::plane_strain);
  const double k_stress = mean_k(gp, PlaneCondition::plane_stress);
  gearfem::rating::iso6336::StiffnessInput in;
  in.z1 = 23;
  in.z2 = 69;
  in.alpha_n = 20 * deg;
  in.module = 4e-3;
  in.eps_alpha = gp.contact_ratio();
  const double c_ga = gearfem::rating::iso6336::mesh_stiffness(in).c_gamma_alpha;
  std::printf("23/69 m4: Weber/Cornell mean k = %.2f (plane strain), %.2f (plane stress); ISO c_ga = %.2f N/(mm um)\n",
              k_strain, k_stress, c_ga);
  EXPECT_NEAR(k_strain / c_ga, 1.0, 0.35);
  EXPECT_LT(k_stress, k_strain);
}

TEST(GeneratedGeometry, ShiftDependenceOfSingleStiffnessFollowsIso)
{
  // ISO 6336-1 q' describes the single-pair stiffness c'_th. Our Weber/Cornell single-pair
  // stiffness at the pitch point (plane strain) on generated 23/69 pairs: it rises with the
  // pinion shift x1 and with the wheel shift x2 as 1/q' does, and stays a near-constant
  // fraction of c'_th (0.86 +- 0.06 measured: 0.82..0.88 over the shifts below).
  auto kC = [](double x1, double x2) {
    const geometry::GearPair gp = pair(23, 69, 4e-3, x1, x2);
    PairModelOptions o;
    o.plane = PlaneCondition::plane_strain;
    PairCompliance pc(involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {206e9, 0.3},
                      {206e9, 0.3}, 20e-3, pair_line(gp), o);
    return 1.0 / pc(pc.line().g_C, 6000.0) / 20e-3 / 1e9; // N/(mm um)
  };
  double prev = 0;
  for (double x1 : {-0.3, 0.0, 0.3})
    {
      const double k = kC(x1, 0.0), c_th = 1 / gearfem::rating::iso6336::q_prime(23, 69, x1, 0.0);
      std::printf("23/69 x1 = %+.1f: single-pair k(C) = %.2f, ISO c'_th = %.2f N/(mm um), ratio %.3f\n",
                  x1, k, c_th, k / c_th);
      EXPECT_GT(k, prev);
      EXPECT_NEAR(k / c_th, 0.86, 0.06);
      prev = k;
    }
  EXPECT_GT(kC(0.0, 0.3), kC(0.0, 0.0));
  EXPECT_LT(gearfem::rating::iso6336::q_prime(23, 69, 0.0, 0.3), gearfem::rating::iso6336::q_prime(23, 69, 0.0, 0.0));
}

TEST(GeneratedGeometry, Seed000SemiAnalyticalAgainstFullModel)
{
  // Gkimisis 2019 Table 1 pair (z 32/60, m 3, b 30, C_f 0.49, E 200 GPa; plane strain, the
  // thesis' 50/(2 pi)). The closed form (exponential thickness fit, monomial integrals,
  // Hertz frozen at the pitch point) against the full Weber/Cornell model on the same
  // generated teeth: the thesis reports <= 15 % along AB; we measure 12.8 % at most.
  auto g = [](int z) {
    geometry::GearParameters p = gear(z, 3e-3, 0.0, 30e-3);
    p.thickness_allowance = 0.01 * pi * 3e-3; // C_f = 0.49
    return geometry::ToothProfile::generate(p);
  };
  const geometry::GearPair gp(g(32), g(60), {});
  PairModelOptions o;
  o.plane = PlaneCondition::plane_strain;
  o.odonnell = ODonnellConstant::seed000_50_over_2pi;
  const InvoluteTooth t1 = involute_tooth(gp.gear(1)), t2 = involute_tooth(gp.gear(2));
  const PairLine L = pair_line(gp);
  const PairCompliance full(t1, t2, {200e9, 0.3}, {200e9, 0.3}, 30e-3, L, o);
  const MeshModel mm = full.mesh_model();
  const double F = 40.0 / L.rb1; // 40 N m
  double km = 0;
  const auto c = mesh_cycle(mm, F, 200);
  for (const auto &s : c)
    km += s.stiffness / c.size();
  const double x = F / km;
  const RickerSemiAnalytical sa(t1, t2, {200e9, 0.3}, {200e9, 0.3}, 30e-3, L, km, o);
  EXPECT_NEAR(sa.K1(0), t1.beam.thickness(0), 1e-15);
  double emax = 0;
  for (int i = 0; i <= 100; ++i)
    {
      const double gg = L.g_A + (L.g_E - L.g_A) * i / 100.0;
      emax = std::max(emax, std::abs(sa.pair_stiffness(gg, x) * full(gg, km * x * 0.5) - 1));
    }
  std::printf("Gkimisis 2019 semi-analytical pair stiffness: max error %.1f %% along AB\n", 100 * emax);
  EXPECT_LT(emax, 0.15);
  // Ricker weight (eq. 3.37, f_c = 2 f_m): 1 at the middle of AB and its minima
  // -exp(-3)/2 = -0.025 at the edges of the single-contact zone (c_x x -> 0).
  const double wA = (L.g_A - L.g_C) / L.rb1, wB = (L.g_E - L.g_C) / L.rb1, p = L.base_pitch / L.rb1;
  const double w = 2 * p - (wB - wA);
  EXPECT_NEAR(sa.ricker_weight(0.5 * (wA + wB), 1e-15), 1.0, 1e-12);
  EXPECT_NEAR(sa.ricker_weight(0.5 * (wA + wB) + 0.5 * w, 1e-15), -0.5 * std::exp(-3.0), 1e-9);
  // The Ricker load sharing against the line-of-action load sharing of the full model
  // (which has no corner contact): close in the double-contact zones (< 10 %), far off
  // inside the single-contact zone, where the wavelet phases the second pair in gradually.
  double dmax = 0, smax = 0;
  for (int i = 0; i < 400; ++i)
    {
      const double phi = 0.5 * (wA + wB) - 0.5 * p + p * (i + 0.5) / 400;
      const double e = std::abs(sa.load(phi, x) / load_at_compression(mm, phi, x) - 1);
      (phi > wB - p && phi < wA + p ? smax : dmax) = std::max(phi > wB - p && phi < wA + p ? smax : dmax, e);
    }
  std::printf("Gkimisis 2019 Ricker load sharing: max error %.1f %% (double-contact zones), %.1f %% (single)\n",
              100 * dmax, 100 * smax);
  EXPECT_LT(dmax, 0.10);
}

// Calibration: with STE samples generated by the calibrated model
// itself at known factors, the fit must recover them (a consistency check of the fit that
// is independent of the FE), and the corner contact must reproduce the narrowing of the
// single-pair zone with load.
TEST(Calibration, RecoversKnownFactorsAndExtendedContact)
{
  const geometry::GearPair gp = pair(50, 50, 3e-3);
  PairCompliance pc(involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {207e9, 0.3}, {207e9, 0.3}, 20e-3,
                    pair_line(gp));
  CalibrationFactors truth;
  truth.beam = 1.15, truth.foundation = 1.0, truth.hertz = 0.85, truth.body = 4e-10, truth.corner_radius = 0.15e-3;
  const CalibratedMesh m(pc, truth);
  std::vector<SteSample> samples;
  const double p1 = 2 * gearfem::units::pi / 50, phiA = (pc.line().g_A - pc.line().g_C) / pc.line().rb1;
  for (const double T : {100.0, 200.0, 340.0})
    for (int i = 0; i < 30; ++i)
      {
        const double phi = phiA + p1 * i / 30;
        samples.push_back({T, phi, m.ste(phi, T / pc.line().rb1)});
      }
  FitMask mask;
  mask.foundation = false; // beam and foundation scale near-proportional parts: fix one
  mask.corner_radius = true;
  CalibrationFactors start;
  start.corner_radius = 0.1e-3;
  const FitResult f = fit_factors(pc, samples, start, mask);
  EXPECT_NEAR(f.factors.beam / truth.beam, 1.0, 1e-4);
  EXPECT_NEAR(f.factors.hertz / truth.hertz, 1.0, 1e-4);
  EXPECT_NEAR(f.factors.body / truth.body, 1.0, 1e-3);
  EXPECT_NEAR(f.factors.corner_radius / truth.corner_radius, 1.0, 1e-3);
  EXPECT_LT(f.rms, 1e-8);
  for (const auto &e : ste_errors(pc, f.factors, samples))
    EXPECT_LT(e.max_abs, 1e-7);
  // Extended contact: the number of loaded pairs at the position where the rigid model
  // has one pair grows with the load, and load_at inverts ste.
  std::vector<double> loads;
  const double phi = 0.0; // the pitch point lies in the single-pair zone B..D of this pair
  m.ste(phi, 200.0, &loads);
  const std::size_t light = loads.size();
  m.ste(phi, 2e5, &loads);
  EXPECT_GT(loads.size(), light);
  const double d = m.ste(0.0, 5000.0);
  EXPECT_NEAR(m.load_at(0.0, d) / 5000.0, 1.0, 1e-9);
  EXPECT_EQ(m.load_at(0.0, -1e-6), 0.0);
}

// Torque table of Gkimisis 2019 with corner contact OA/BΓ (corner.h): inside the single-pair zone
// and for small x it equals the table without corner contact; the zone where one pair
// carries the load narrows as x grows (Gkimisis 2019, sec. 3.3); T is continuous at A and E.
TEST(TorqueTable, CornerContact)
{
  const geometry::GearPair gp = pair(50, 50, 3e-3);
  const PairCompliance pc(involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {207e9, 0.3}, {207e9, 0.3},
                          20e-3, pair_line(gp));
  const MeshModel plain = pc.mesh_model(), corner = pc.mesh_model(true);
  const PairLine &L = pc.line();
  ASSERT_TRUE(corner.corner);
  EXPECT_FALSE(plain.corner);
  const double phiB = (L.g_E - L.base_pitch - L.g_C) / L.rb1, phiD = (L.g_A + L.base_pitch - L.g_C) / L.rb1;
  ASSERT_LT(phiB, 0.0);
  ASSERT_GT(phiD, 0.0);
  // Small x at the pitch point: the neighbours' corner gaps (tens of um) are not reached.
  for (const double x : {0.5e-6, 2e-6})
    {
      const auto t0 = torque_table(plain, {0.0}, {x}), t1 = torque_table(corner, {0.0}, {x});
      EXPECT_EQ(t1[0][0], t0[0][0]) << x;
    }
  // Width of the single-pair zone: positions over one pitch where only the on-path pair
  // carries load (the corner table equals the plain one and the plain one has one pair).
  auto single_width = [&](double x) {
    int n = 0;
    const int N = 400;
    for (int i = 0; i < N; ++i)
      {
        const double phi = phiB + (phiD - phiB) * (i + 0.5) / N;
        if (load_at_compression(corner, phi, x) == load_at_compression(plain, phi, x))
          ++n;
      }
    return (phiD - phiB) * n / N;
  };
  const double w1 = single_width(1e-6), w5 = single_width(5e-6), w10 = single_width(10e-6);
  std::printf("single-pair zone width with corner contact: %.3f / %.3f / %.3f deg at x = 1 / 5 / 10 um "
              "(geometric B..D %.3f deg)\n", w1 / deg, w5 / deg, w10 / deg, (phiD - phiB) / deg);
  EXPECT_LT(w5, w1);
  EXPECT_LT(w10, w5);
  EXPECT_LT(w1, phiD - phiB);
  // Continuity at E (a pair leaves the path) and at A (a pair enters), and the corner pair
  // adds load beyond E.
  const double x = 8e-6, eps = 1e-10;
  for (const double phi_end : {(L.g_E - L.g_C) / L.rb1, (L.g_A - L.g_C) / L.rb1})
    {
      const double Tm = torque_table(corner, {phi_end - eps}, {x})[0][0];
      const double Tp = torque_table(corner, {phi_end + eps}, {x})[0][0];
      EXPECT_NEAR(Tp / Tm, 1.0, 1e-6);
    }
  EXPECT_GT(load_at_compression(corner, phiB + 0.05 * deg, x), load_at_compression(plain, phiB + 0.05 * deg, x));
}

// The calibrated model's corner contact: the STE is continuous where a pair leaves the path
// at E or enters it at A (the corner gap is 0 there, and the Hertz term blends from the
// involute to the corner within a half-width of the corner), and the corner force lever arm
// and gap come from corner.h.
TEST(Calibration, CornerContactIsContinuousAtTheEndsOfThePath)
{
  const geometry::GearPair gp = pair(50, 50, 3e-3);
  PairCompliance pc(involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {207e9, 0.3}, {207e9, 0.3}, 20e-3,
                    pair_line(gp));
  const PairLine &L = pc.line();
  for (const double rho : {0.0, 0.1e-3, 0.5e-3})
    {
      CalibrationFactors f;
      f.corner_radius = rho;
      const CalibratedMesh m(pc, f);
      CalibrationFactors no;
      no.corner = false;
      const CalibratedMesh m0(pc, no);
      for (const double T : {100.0, 340.0})
        for (const double ge : {L.g_E, L.g_A})
          {
            const double phi = (ge - L.g_C) / L.rb1, e = 1e-9, F = T / L.rb1;
            EXPECT_NEAR(m.ste(phi + e, F) / m.ste(phi - e, F), 1.0, 1e-6) << rho << " " << T;
            // With the involute Hertz term everywhere (rho = 0) the corner contact only adds load
            // paths: the STE is never above the path-only model.
            if (rho == 0)
              EXPECT_LE(m.ste(phi + 0.1 * deg, F), m0.ste(phi + 0.1 * deg, F) * (1 + 1e-12));
          }
    }
}

// Two-sided torque (mesh-table format version 2): the reverse-flank offset of a standard
// zero-backlash 50/50 pair is the angular tooth thickness at the pitch circle, pi/z (closed
// form of the rack-cut tooth: half the angular pitch), thinned by b/(2 r_b1); the torque is
// 0 across the clearance and, below -b, minus the drive torque at the mirrored angle.
TEST(Calibration, TwoSidedTorqueMirrorsTheDriveFlank)
{
  const geometry::GearPair gp = pair(50, 50, 3e-3);
  const InvoluteTooth t1 = involute_tooth(gp.gear(1));
  PairCompliance pc(t1, involute_tooth(gp.gear(2)), {207e9, 0.3}, {207e9, 0.3}, 20e-3, pair_line(gp));
  const PairLine &L = pc.line();
  EXPECT_NEAR(reverse_offset(t1, L, 0.0), gearfem::units::pi / 50, 1e-7);
  const double b = 1.5e-4;
  EXPECT_NEAR(reverse_offset(t1, L, b), gearfem::units::pi / 50 - b / (2 * L.rb1), 1e-7);
  const CalibratedMesh m(pc, CalibrationFactors{});
  const double psi = reverse_offset(t1, L, b);
  for (const double phi : {-0.05, 0.0, 0.013, 0.04})
    {
      const double d = 5e-6;
      EXPECT_NEAR(m.torque(phi, d, b, psi), L.rb1 * m.load_at(phi, d), 1e-9 * L.rb1 * m.load_at(phi, d));
      EXPECT_EQ(m.torque(phi, 0.0, b, psi), 0.0);
      EXPECT_EQ(m.torque(phi, -0.5 * b, b, psi), 0.0);
      EXPECT_EQ(m.torque(phi, -b, b, psi), 0.0);
      const double rev = m.torque(phi, -b - d, b, psi), fwd = m.torque(psi - phi, d, b, psi);
      EXPECT_GT(fwd, 0.0);
      EXPECT_NEAR(rev, -fwd, 1e-12 * fwd);
    }
}

// Load-given mesh cycle with corner contact (the inverse of load_at_compression): at each
// position the deflection x carries exactly the load (conservation), the pair loads sum to
// it, positions where no corner pair engages give the path-only answer, and the single-pair
// zone narrows as the load grows (Gkimisis 2019; the FE shows the same, docs/contact.md).
TEST(MeshCycle, CornerContactInTheLoadGivenSolver)
{
  const geometry::GearPair gp = pair(50, 50, 3e-3);
  PairCompliance pc(involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {207e9, 0.3}, {207e9, 0.3}, 20e-3,
                    pair_line(gp));
  const MeshModel plain = pc.mesh_model(false), corner = pc.mesh_model(true);
  std::vector<int> single;
  for (const double T : {20.0, 200.0, 2000.0})
    {
      const double F = T / plain.rb1;
      const auto c0 = mesh_cycle(plain, F, 200), c1 = mesh_cycle(corner, F, 200);
      int n1 = 0;
      for (std::size_t i = 0; i < c1.size(); ++i)
        {
          const MeshState &s = c1[i];
          EXPECT_NEAR(load_at_compression(corner, s.roll_angle, s.deflection) / F, 1.0, 1e-9);
          double sum = 0;
          for (double f : s.pair_load)
            sum += f;
          EXPECT_NEAR(sum / F, 1.0, 1e-12);
          EXPECT_LE(s.deflection, c0[i].deflection * (1 + 1e-9)); // extra load paths only stiffen
          if (s.g.size() == c0[i].g.size())
            EXPECT_NEAR(s.deflection / c0[i].deflection, 1.0, 1e-9);
          n1 += s.g.size() == 1;
        }
      single.push_back(n1);
    }
  std::printf("single-pair positions of 200 at 20/200/2000 N m with corner contact: %d/%d/%d\n", single[0],
              single[1], single[2]);
  EXPECT_GT(single[0], single[1]);
  EXPECT_GT(single[1], single[2]);
}

TEST(GeneratedGeometry, MeshCycleTableBothLaws)
{
  // gearfem rate's mesh_cycle.csv (cycle_table.h) on the Gkimisis 2019 Table 1 pair. The
  // load-sharing rows must equal mesh_cycle() itself; the Ricker rows must invert
  // the law (RickerSemiAnalytical::load at the tabulated STE gives F back: the inverse
  // function), carry F in their pair loads (equilibrium), and stay within the thesis' 15 %
  // of the full model's mean stiffness.
  auto g = [](int z) {
    geometry::GearParameters p = gear(z, 3e-3, 0.0, 30e-3);
    p.thickness_allowance = 0.01 * pi * 3e-3;
    return geometry::ToothProfile::generate(p);
  };
  const geometry::GearPair gp(g(32), g(60), {});
  CycleInput in{involute_tooth(gp.gear(1)), involute_tooth(gp.gear(2)), {200e9, 0.3}, {200e9, 0.3}, 30e-3,
                pair_line(gp), {}, false};
  in.options.plane = PlaneCondition::plane_strain;
  const std::vector<double> torques{40.0, 120.0};
  const CycleTable ls = mesh_cycle_table(in, CycleLaw::load_sharing, torques, 40);
  const CycleTable rk = mesh_cycle_table(in, CycleLaw::ricker, torques, 40);
  ASSERT_EQ(ls.table.n_rows(), 80u);
  ASSERT_EQ(rk.table.n_rows(), 80u);
  const PairCompliance pc(in.pinion, in.gear, in.m1, in.m2, in.face_width, in.line, in.options);
  const auto direct = mesh_cycle(pc.mesh_model(false), 120.0 / in.line.rb1, 40);
  const auto ste_ls = ls.table.column("loaded STE"), ste_rk = rk.table.column("loaded STE");
  const auto roll = rk.table.column("roll angle");
  for (int i = 0; i < 40; ++i)
    EXPECT_NEAR(ste_ls[40 + i], direct[i].deflection * 1e6, 1e-12);
  double km = 0;
  for (const auto &s : direct)
    km += s.stiffness / direct.size();
  const RickerSemiAnalytical sa(in.pinion, in.gear, in.m1, in.m2, in.face_width, in.line, km, in.options);
  const double F = 120.0 / in.line.rb1;
  for (int i = 0; i < 40; ++i)
    {
      EXPECT_NEAR(sa.load(roll[40 + i] * deg, ste_rk[40 + i] * 1e-6) / F, 1.0, 1e-9);
      const auto &row = rk.table.row(40 + i);
      EXPECT_NEAR((row[5] + row[6] + row[7]) / F, 1.0, 1e-9);
    }
  EXPECT_NEAR(rk.k_mean[1] / ls.k_mean[1], 1.0, 0.15);
  EXPECT_GT(rk.seconds, 0.0);
}
