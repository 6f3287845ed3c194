// Ricker-wavelet load sharing (Gkimisis 2019, eqs. 3.35-3.46) against facts that
// follow from its definitions independently of the implementation: the single-contact
// zone of eq. 3.35, the wavelet's extrema and zeros, its integral, superposition of the
// pairs that are on the line of action, periodicity and symmetry.
#include "dynamics/ricker_law.h"
#include "base/units.h"

#include "base/errors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem::dynamics;

namespace
{
  constexpr double deg = gearfem::units::pi / 180;

  /// Gkimisis 2019 Table 1 pair: z1 = 32, AB = [-9.2 deg, 10.2 deg] in w1 (digest "Cases").
  RickerLawParameters table1(SecondPair sp = SecondPair::thesis)
  {
    RickerLawParameters p;
    p.z1 = 32;
    p.omega_A = -9.2 * deg;
    p.omega_B = 10.2 * deg;
    p.nominal_compression = 1e-5;
    p.second_pair = sp;
    return p;
  }

  const double pitch = 2 * gearfem::units::pi / 32;

  /// Minimum of the law's wavelet on [a, b] by dense sampling and golden-section refinement.
  std::pair<double, double> minimum(const RickerLoadSharingLaw &law, double x, double a, double b)
  {
    const int n = 2000;
    double best = a;
    for (int i = 0; i <= n; ++i)
      {
        const double w = a + (b - a) * i / n;
        if (law.wavelet(w, x) < law.wavelet(best, x))
          best = w;
      }
    double lo = best - (b - a) / n, hi = best + (b - a) / n;
    const double r = 0.5 * (std::sqrt(5.0) - 1);
    for (int it = 0; it < 200; ++it)
      {
        const double c = hi - r * (hi - lo), d = lo + r * (hi - lo);
        if (law.wavelet(c, x) < law.wavelet(d, x))
          hi = d;
        else
          lo = c;
      }
    const double w = 0.5 * (lo + hi);
    return {w, law.wavelet(w, x)};
  }
} // namespace

// Eq. 3.42 on the Table 1 pair by hand: L = 2 * 11.25 - 19.4 = 3.1 deg at x = 0, and
// c_x = 2 deg/mm narrows it to 2.1 deg at x = 0.5 mm; f_m = sqrt(3)/(pi L) = 10.19 /rad.
TEST(RickerLaw, Table1Numbers)
{
  const RickerLoadSharingLaw law([](double, double) { return 1e8; }, table1());
  EXPECT_NEAR(law.period(), 11.25 * deg, 1e-15);
  EXPECT_NEAR(law.single_contact_width(0), 3.1 * deg, 1e-13);
  EXPECT_NEAR(law.single_contact_width(0.5e-3), 2.1 * deg, 1e-13);
  EXPECT_NEAR(law.f_m(0), 10.19, 0.005);
  EXPECT_NEAR(law.centre(), 0.5 * deg, 1e-15);
}

// W = 1 at the centre of AB, symmetric about it; its minima sit on the borders of the
// single-contact zone of eq. 3.35 (w_B - 2 pi/z1 and w_A + 2 pi/z1) at x = 0, move inwards
// by c_x x/2 under load, and are -e^-3/2 (the thesis rounds to -0.02); W = 0 at L/sqrt(6).
TEST(RickerLaw, WaveletExtremaAndZeros)
{
  const RickerLawParameters p = table1();
  const RickerLoadSharingLaw law([](double, double) { return 1e8; }, p);
  const double wbar = law.centre();
  EXPECT_DOUBLE_EQ(law.wavelet(wbar, 0), 1.0);
  EXPECT_DOUBLE_EQ(law.second_pair_weight(wbar, 2e-5), 0.0);
  for (double d : {0.1 * deg, 0.9 * deg, 2.0 * deg, 4.0 * deg})
    EXPECT_NEAR(law.wavelet(wbar + d, 1e-5), law.wavelet(wbar - d, 1e-5), 1e-14);

  const double single_lo = p.omega_B - pitch, single_hi = p.omega_A + pitch; // eq. 3.35
  for (double x : {0.0, 2e-5, 0.3e-3})
    {
      const double shrink = 0.5 * p.c_x * x;
      const auto right = minimum(law, x, wbar, wbar + 0.5 * pitch);
      const auto left = minimum(law, x, wbar - 0.5 * pitch, wbar);
      EXPECT_NEAR(right.first, single_hi - shrink, 1e-7) << x;
      EXPECT_NEAR(left.first, single_lo + shrink, 1e-7) << x;
      EXPECT_NEAR(right.second, -0.5 * std::exp(-3.0), 1e-12);
      EXPECT_NEAR(left.second, -0.02, 0.005); // the thesis' stated W_min
      const double z = law.single_contact_width(x) / std::sqrt(6.0);
      EXPECT_NEAR(law.wavelet(wbar + z, x), 0.0, 1e-14);
      EXPECT_NEAR(law.wavelet(wbar - z, x), 0.0, 1e-14);
    }
}

// Constant K: one pair at the centre of AB, two pairs deep in double contact; the load
// share of the pair at w1 goes from 1 to 1/2. The mean stiffness equals the closed form
// K (2 - integral(W)/p) with integral(W) = sqrt(3 pi) L/8 (Gaussian integrals).
TEST(RickerLaw, ConstantStiffnessSharing)
{
  const double k0 = 3.7e8, x = 1e-5;
  const RickerLoadSharingLaw law([&](double, double) { return k0; }, table1());
  const double wbar = law.centre();
  EXPECT_DOUBLE_EQ(law.force(wbar, x, 0), k0 * x);
  EXPECT_DOUBLE_EQ(law.load_share(wbar, x), 1.0);
  for (double w : {wbar - 0.5 * pitch, wbar + 0.5 * pitch - 1e-9})
    {
      EXPECT_NEAR(law.force(w, x, 0), 2 * k0 * x, 1e-12 * k0 * x);
      EXPECT_NEAR(law.load_share(w, x), 0.5, 1e-12);
    }
  // Shares of the two pairs: each in [1/(2 + e^-3/2), 1], summing to 1 by construction.
  for (int i = 0; i < 500; ++i)
    {
      const double w = wbar - 0.5 * pitch + pitch * (i + 0.5) / 500;
      const double s1 = law.load_share(w, x);
      const double s2 = law.second_pair_weight(w, x) * k0 / law.stiffness(w, x);
      EXPECT_NEAR(s1 + s2, 1.0, 1e-14);
      EXPECT_GE(s1, 1 / (2 + 0.5 * std::exp(-3.0)) - 1e-14);
      EXPECT_LE(s1, 1.0 + 1e-14);
    }
  const double L = law.single_contact_width(1e-5);
  EXPECT_NEAR(law.mean_stiffness(), k0 * (2 - std::sqrt(3 * gearfem::units::pi) * L / 8 / pitch),
              1e-9 * k0);
}

// Deep in double contact (|W| < 1e-13) the force is the sum of K x over the pairs whose
// roll angle w1 + n 2 pi/z1 lies on AB, found here by counting, not through eq. 3.45.
TEST(RickerLaw, SuperpositionInDoubleContact)
{
  const RickerLawParameters p = table1();
  const auto K = [](double w, double x) { return 4e8 * (1 + 0.3 * w / pitch) * (1 + x / 1e-4); };
  const RickerLoadSharingLaw law(K, p);
  for (double w : {law.centre() - 5.2 * deg, law.centre() + 5.2 * deg})
    for (double x : {2e-6, 1e-5, 3e-5})
      {
        double expected = 0;
        int pairs = 0;
        for (int n = -3; n <= 3; ++n)
          if (w + n * pitch >= p.omega_A && w + n * pitch <= p.omega_B)
            expected += K(w + n * pitch, x) * x, ++pairs;
        EXPECT_EQ(pairs, 2);
        EXPECT_NEAR(law.force(w, x, 0), expected, 1e-12 * expected) << w << " " << x;
        // Shifted by whole periods, the same force.
        for (int k : {-3, -1, 1, 4})
          EXPECT_NEAR(law.force(w + k * pitch, x, 0), expected, 1e-12 * expected);
      }
}

// With a K symmetric about the centre of AB, the centred variant gives a force symmetric
// about it, continuous everywhere and with no breaks.
TEST(RickerLaw, CentredSymmetryAndContinuity)
{
  const RickerLawParameters p = table1(SecondPair::centred);
  const double wbar = 0.5 * (p.omega_A + p.omega_B);
  const auto K = [&](double w, double) {
    const double s = (w - wbar) / pitch;
    return 4e8 * (1 - 0.2 * s * s);
  };
  const RickerLoadSharingLaw law(K, p);
  EXPECT_TRUE(law.breaks().empty());
  const double x = 1e-5;
  for (int i = 1; i < 50; ++i)
    {
      const double d = 0.5 * pitch * i / 50;
      EXPECT_NEAR(law.force(wbar + d, x, 0), law.force(wbar - d, x, 0), 1e-12 * 8e8 * x);
    }
  const double h = 1e-10;
  for (double w : {0.0, wbar, wbar + 0.5 * pitch})
    EXPECT_NEAR(law.force(w + h, x, 0), law.force(w - h, x, 0), 1e-6 * 4e8 * x) << w;
}

// Eq. 3.45 as printed switches pairs at w1 = 0, where g != 0 for this asymmetric AB: the
// force jumps there by g(0) [K(-p) - K(p)] x, and the law reports 0 as a break.
TEST(RickerLaw, ThesisVariantJumpsAtPitchPoint)
{
  const auto K = [](double w, double) { return 4e8 * (1 + 0.3 * w / pitch); };
  const RickerLoadSharingLaw law(K, table1(SecondPair::thesis));
  ASSERT_EQ(law.breaks().size(), 1u);
  EXPECT_EQ(law.breaks()[0], 0.0);
  const double x = 1e-5, h = 1e-12;
  EXPECT_DOUBLE_EQ(law.second_pair_angle(h), h - pitch);
  EXPECT_DOUBLE_EQ(law.second_pair_angle(-h), -h + pitch);
  const double g0 = law.second_pair_weight(0.0, x);
  EXPECT_GT(g0, 0.1);
  EXPECT_NEAR(law.force(h, x, 0) - law.force(-h, x, 0), g0 * (K(-pitch, x) - K(pitch, x)) * x,
              1e-6 * 4e8 * x);
}

// The single-contact zone narrows with the compression (c_x, eq. 3.42): at a fixed angle
// inside it the second-pair weight grows until the zone border (the minimum of W) has
// moved past that angle (here 1 deg from the centre: up to L = 2 deg, x = 0.55 mm). The
// zone closes at x = L(0)/c_x: from there on W = 0 and two pairs share everywhere.
TEST(RickerLaw, SingleContactZoneNarrowsWithLoad)
{
  const RickerLawParameters p = table1();
  const RickerLoadSharingLaw law([](double, double) { return 1e8; }, p);
  const double w = law.centre() + 1.0 * deg;
  double g_prev = -1;
  for (double x : {0.0, 1e-4, 3e-4, 5e-4})
    {
      const double g = law.second_pair_weight(w, x);
      EXPECT_GT(g, g_prev) << x;
      g_prev = g;
    }
  const double x_closed = law.single_contact_width(0) / p.c_x;
  EXPECT_NEAR(x_closed, 1.55e-3, 1e-12);
  EXPECT_EQ(law.wavelet(law.centre(), 1.01 * x_closed), 0.0);
  EXPECT_DOUBLE_EQ(law.stiffness(law.centre(), 1.01 * x_closed), 2e8);
}

// A load-dependent K is evaluated at max(|x|, x_min): finite at x = 0, and the force is
// a smooth odd-like extension below 0 (F(0) = 0, sign follows x).
TEST(RickerLaw, NegativeCompressionExtension)
{
  const auto K = [](double, double x) { return 1e8 * (3 + 0.1 * std::log(x / 1e-5)); };
  const RickerLoadSharingLaw law(K, table1());
  EXPECT_EQ(law.force(0.01, 0.0, 0), 0.0);
  EXPECT_LT(law.force(0.01, -1e-6, 0), 0.0);
  EXPECT_TRUE(std::isfinite(law.stiffness(0.01, 0.0)));
  const auto copy = law.clone();
  EXPECT_EQ(copy->force(0.03, 7e-6, 0), law.force(0.03, 7e-6, 0));
  EXPECT_EQ(copy->mean_stiffness(), law.mean_stiffness());
}

TEST(RickerLaw, RejectsBadParameters)
{
  const PairStiffness K = [](double, double) { return 1e8; };
  RickerLawParameters p = table1();
  p.omega_B = 20 * deg; // contact ratio 2.6
  EXPECT_THROW(RickerLoadSharingLaw(K, p), gearfem::InputError);
  p = table1();
  p.omega_B = 1 * deg; // contact ratio 0.91
  EXPECT_THROW(RickerLoadSharingLaw(K, p), gearfem::InputError);
  p = table1();
  p.omega_A = 0.5 * deg;
  EXPECT_THROW(RickerLoadSharingLaw(K, p), gearfem::InputError);
  p = table1();
  p.z1 = 3;
  EXPECT_THROW(RickerLoadSharingLaw(K, p), gearfem::InputError);
  p = table1();
  p.c_x = -1;
  EXPECT_THROW(RickerLoadSharingLaw(K, p), gearfem::InputError);
  EXPECT_THROW(RickerLoadSharingLaw(PairStiffness{}, table1()), gearfem::InputError);
}
