// Manufacturing deviations (geometry/deviations.h): the ISO 1328-1:2013 tolerance formulas
// against the same formulas evaluated independently (Python, below), the standard's rounding
// rule, the grade step, seeded draws within the tolerances, and the flank offsets.
#include "geometry/deviations.h"

#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace gearfem::geometry;

namespace
{
  constexpr double um = 1e-6, mm = 1e-3;
}

// Reference values [um], unrounded, evaluated independently of gearfem with /usr/bin/python3
// from ISO 1328-1:2013 clause 5.3 (s = sqrt(2)^(A - 5)):
//   f_pT = (0.001 d + 0.4 m + 5) s, F_pT = (0.002 d + 0.55 sqrt(d) + 0.7 m + 12) s,
//   f_HaT = (0.4 m + 0.001 d + 4) s, f_faT = (0.55 m + 5) s, F_aT = hypot(f_HaT, f_faT),
//   f_HbT = (0.05 sqrt(d) + 0.35 sqrt(b) + 4) s, f_fbT = (0.07 sqrt(d) + 0.45 sqrt(b) + 4) s,
//   F_rT = 0.9 F_pT.
TEST(Iso1328, FormulasAgainstAnIndependentEvaluation)
{
  struct Case
  {
    int A;
    double m, d, b;
    double fpt, Fp, fHa, ffa, Fa, fHb, ffb, Fr;
  };
  const Case cases[] = {
    // The demo pair (Parker 50/50 m 3, d 150, b 20) at grade 6.
    {6, 3, 150, 20, 8.980256, 29.890955, 7.566043, 9.40452, 12.070211, 8.736474, 9.71534, 26.901859},
    // FZG type C pinion (m 4.5, d 72, b 14) at grade 5: s = 1.
    {5, 4.5, 72, 14, 6.872, 19.960905, 5.872, 7.475, 9.505578, 5.733844, 6.277716, 17.964814},
    // Siasos 2010 gear (m 4, d 276, b 70) at grade 8.
    {8, 4, 276, 70, 19.448265, 69.266161, 16.619838, 20.364675, 26.285719, 21.945688, 25.251907, 62.339545},
    // The corners of the range of application.
    {1, 0.5, 5, 4, 1.30125, 3.397459, 1.05125, 1.31875, 1.686484, 1.202951, 1.264131, 3.057713},
    {11, 70, 15000, 1200, 384.0, 1266.887743, 376.0, 348.0, 512.32802, 177.98464, 225.293371, 1140.198969},
  };
  for (const auto &c : cases)
    {
      const auto t = iso1328_tolerances(c.A, c.m * mm, c.d * mm, c.b * mm, false);
      const double tol = 1e-6 * um;
      EXPECT_NEAR(t.f_pT, c.fpt * um, tol) << c.A;
      EXPECT_NEAR(t.F_pT, c.Fp * um, tol) << c.A;
      EXPECT_NEAR(t.f_HaT, c.fHa * um, tol) << c.A;
      EXPECT_NEAR(t.f_faT, c.ffa * um, tol) << c.A;
      EXPECT_NEAR(t.F_aT, c.Fa * um, tol) << c.A;
      EXPECT_NEAR(t.f_HbT, c.fHb * um, tol) << c.A;
      EXPECT_NEAR(t.f_fbT, c.ffb * um, tol) << c.A;
      EXPECT_NEAR(t.F_rT, c.Fr * um, tol) << c.A;
      // Rounded by the standard's rule: never more than half a step away.
      const auto r = iso1328_tolerances(c.A, c.m * mm, c.d * mm, c.b * mm, true);
      EXPECT_LE(std::abs(r.F_pT - t.F_pT), 0.5 * um + 1e-12);
      EXPECT_LE(std::abs(r.f_pT - t.f_pT), 0.5 * um + 1e-12);
    }
}

// ISO 1328-1:2013, 5.2: above 10 um to the integer, 5..10 um to 0.5 um, below 5 um to 0.1 um.
TEST(Iso1328, RoundingRule)
{
  EXPECT_NEAR(iso1328_round(29.890955 * um), 30 * um, 1e-15);
  EXPECT_NEAR(iso1328_round(10.4 * um), 10 * um, 1e-15);
  EXPECT_NEAR(iso1328_round(8.980256 * um), 9 * um, 1e-15);
  EXPECT_NEAR(iso1328_round(7.566043 * um), 7.5 * um, 1e-15);
  EXPECT_NEAR(iso1328_round(5.2 * um), 5 * um, 1e-15);
  EXPECT_NEAR(iso1328_round(4.44 * um), 4.4 * um, 1e-15);
  EXPECT_NEAR(iso1328_round(1.30125 * um), 1.3 * um, 1e-15);
}

// Two grades apart the unrounded tolerances differ by exactly sqrt(2)^2 = 2.
TEST(Iso1328, GradeStepIsSqrt2)
{
  for (int A = 1; A <= 9; ++A)
    {
      const auto a = iso1328_tolerances(A, 3 * mm, 150 * mm, 20 * mm, false);
      const auto b = iso1328_tolerances(A + 2, 3 * mm, 150 * mm, 20 * mm, false);
      EXPECT_NEAR(b.F_pT / a.F_pT, 2.0, 1e-12);
      EXPECT_NEAR(b.f_faT / a.f_faT, 2.0, 1e-12);
    }
}

TEST(Iso1328, RangeOfApplicationIsChecked)
{
  EXPECT_THROW(iso1328_tolerances(0, 3 * mm, 150 * mm, 20 * mm), gearfem::InputError);
  EXPECT_THROW(iso1328_tolerances(12, 3 * mm, 150 * mm, 20 * mm), gearfem::InputError);
  EXPECT_THROW(iso1328_tolerances(6, 0.3 * mm, 150 * mm, 20 * mm), gearfem::InputError);
  EXPECT_THROW(iso1328_tolerances(6, 3 * mm, 4 * mm, 20 * mm), gearfem::InputError);
  EXPECT_THROW(iso1328_tolerances(6, 3 * mm, 150 * mm, 2 * mm), gearfem::InputError);
}

// Draws stay within the tolerances, close the circle, are reproducible, and their statistics
// are those of the named distribution (uniform: std f / sqrt(3); truncated normal at 3 sigma:
// std 0.9866 f / 3).
TEST(Deviations, SeededDrawsWithinTolerances)
{
  const auto t = iso1328_tolerances(6, 3 * mm, 150 * mm, 20 * mm);
  for (const auto dist : {Distribution::uniform, Distribution::truncated_normal})
    {
      double s2 = 0;
      int n = 0;
      for (int seed = 1; seed <= 200; ++seed)
        {
          const auto d = draw_deviations(t, 50, dist, seed, 1);
          EXPECT_NO_THROW(check_deviations(d, 50, "Deviations/Gear 1"));
          const double sum = std::accumulate(d.f_pt.begin(), d.f_pt.end(), 0.0);
          EXPECT_NEAR(sum, 0.0, 1e-18);
          const auto F = d.cumulative_pitch();
          const auto [lo, hi] = std::minmax_element(F.begin(), F.end());
          EXPECT_LE(*hi - *lo, t.F_pT * (1 + 1e-12));
          for (const double f : d.f_pt)
            EXPECT_LE(std::abs(f), t.f_pT * (1 + 1e-12));
          for (const double f : d.f_Ha)
            {
              EXPECT_LE(std::abs(f), t.f_HaT);
              s2 += f * f, ++n;
            }
          for (const auto &f : d.form)
            EXPECT_LE(std::abs(f.amplitude), t.f_faT);
          EXPECT_LE(2 * d.eccentricity, t.F_rT);
          EXPECT_GE(d.eccentricity, 0.0);
        }
      const double std_expected = dist == Distribution::uniform ? t.f_HaT / std::sqrt(3.0) : 0.98658 * t.f_HaT / 3;
      // 10 000 samples: the standard error of the standard deviation is about 0.7 %.
      EXPECT_NEAR(std::sqrt(s2 / n), std_expected, 0.03 * std_expected) << to_string(dist);
    }
  const auto a = draw_deviations(t, 50, Distribution::uniform, 7, 2), b = draw_deviations(t, 50, Distribution::uniform, 7, 2);
  EXPECT_EQ(a.f_pt, b.f_pt);
  EXPECT_EQ(a.eccentricity, b.eccentricity);
  const auto c = draw_deviations(t, 50, Distribution::uniform, 7, 3);
  EXPECT_NE(a.f_pt, c.f_pt);
}

// The normal offsets of each deviation on a loaded flank point, by hand.
TEST(Deviations, FlankOffsets)
{
  PairDeviations p;
  p.teeth[0] = p.teeth[1] = 10;
  for (auto &r : p.range)
    r.base_radius = 10 * mm, r.xi_start = 2 * mm, r.xi_end = 6 * mm, r.cos_alpha = std::cos(20 * gearfem::units::pi / 180);
  auto &g = p.gear[0];
  g.f_pt.assign(10, 0.0);
  g.f_pt[3] = 5 * um, g.f_pt[4] = -5 * um; // tooth 3 alone advanced by 5 um
  p.finalise();
  const double r_mid = std::hypot(10 * mm, 4 * mm); // xi = 4 mm, u = 0
  // The datum is the teeth's mean position: 5 um on one tooth of ten puts the others at -0.5 um.
  const double ca = p.range[0].cos_alpha;
  EXPECT_NEAR(p.plus_material(1, 3, r_mid), 4.5 * um * ca, 1e-15);
  EXPECT_NEAR(p.plus_material(1, 13, r_mid), 4.5 * um * ca, 1e-15); // modulo z
  EXPECT_NEAR(p.plus_material(1, -7, r_mid), 4.5 * um * ca, 1e-15);
  EXPECT_NEAR(p.plus_material(1, 4, r_mid), -0.5 * um * ca, 1e-15);
  EXPECT_NEAR(p.plus_material(2, 3, r_mid), 0.0, 1e-15);
  // Slope: linear in the roll length, +-f/2 at the ends of the range, 0 mid-range.
  g.f_pt.clear();
  g.f_Ha = {4 * um};
  p.finalise();
  EXPECT_NEAR(p.plus_material(1, 0, std::hypot(10 * mm, 6 * mm)), 2 * um, 1e-15);
  EXPECT_NEAR(p.plus_material(1, 0, std::hypot(10 * mm, 2 * mm)), -2 * um, 1e-15);
  EXPECT_NEAR(p.plus_material(1, 0, r_mid), 0.0, 1e-15);
  // Parabolic form: the range over the profile is the amplitude, the mean is zero.
  g.f_Ha.clear();
  g.form = {ProfileForm{ProfileForm::Kind::parabolic, 3 * um, {}}};
  double lo = 1, hi = -1, mean = 0;
  const int n = 4001;
  for (int i = 0; i < n; ++i)
    {
      const double xi = 2 * mm + 4 * mm * i / (n - 1);
      const double v  = p.plus_material(1, 0, std::hypot(10 * mm, xi));
      lo = std::min(lo, v), hi = std::max(hi, v), mean += v / n;
    }
  EXPECT_NEAR(hi - lo, 3 * um, 1e-15);
  EXPECT_NEAR(mean, 0.0, 1e-3 * um);
  // Table trace: linear interpolation in the roll length from the start of the range.
  g.form = {ProfileForm{ProfileForm::Kind::table, 0, {{0, 0}, {2 * mm, 2 * um}, {4 * mm, -1 * um}}}};
  EXPECT_NEAR(p.plus_material(1, 0, std::hypot(10 * mm, 3 * mm)), 1 * um, 1e-15);
  EXPECT_NEAR(p.plus_material(1, 0, std::hypot(10 * mm, 5 * mm)), 0.5 * um, 1e-15);
  // Runout: the eccentricity turns with the body.
  g.eccentricity = 7 * um, g.eccentricity_phase = 0.3;
  const auto v = p.runout(1, 0.5);
  EXPECT_NEAR(v.norm(), 7 * um, 1e-18);
  EXPECT_NEAR(std::atan2(v.y(), v.x()), 0.8, 1e-12);
}

TEST(Deviations, InputChecks)
{
  GearDeviations d;
  d.f_pt = {1 * um, 2 * um, -1 * um};
  EXPECT_THROW(check_deviations(d, 3, "Deviations/Gear 1"), gearfem::InputError); // no closure
  d.f_pt = {1 * um, -1 * um};
  EXPECT_THROW(check_deviations(d, 3, "Deviations/Gear 1"), gearfem::InputError); // size
  d.f_pt = {1 * um, 1 * um, -2 * um};
  EXPECT_NO_THROW(check_deviations(d, 3, "Deviations/Gear 1"));
  d.f_Ha = {1 * um, 2 * um};
  EXPECT_THROW(check_deviations(d, 3, "Deviations/Gear 1"), gearfem::InputError);
}

// Hunting period: every tooth pair recurs after lcm(z1, z2) pitches.
TEST(Deviations, HuntingPeriod)
{
  EXPECT_EQ(hunting_pitches(50, 50), 50);
  EXPECT_EQ(hunting_pitches(16, 24), 48);
  EXPECT_EQ(hunting_pitches(23, 69), 69);
  EXPECT_EQ(hunting_pitches(19, 55), 1045);
  // Brute force: the first j > 0 with j = 0 mod z1 and mod z2.
  for (int z1 = 5; z1 < 40; z1 += 7)
    for (int z2 = z1; z2 < 90; z2 += 11)
      {
        long j = 1;
        while (j % z1 != 0 || j % z2 != 0)
          ++j;
        EXPECT_EQ(hunting_pitches(z1, z2), j);
      }
}
