// Corner contact (OA/BΓ of Gkimisis 2019): the exact rigid gap of lib/analytical/corner.h against a
// brute-force construction of the rigid pair (involutes drawn from their string-unwinding
// definition, radii and rotations found by bisection), its leading-order curvature form,
// continuity and monotony, and the lever arm of the corner force.
#include "analytical/corner.h"
#include "base/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace gearfem::analytical;

namespace
{
  using gearfem::units::pi;
  constexpr double deg = pi / 180;

  // A standard external pair (sharp tips at the tip circles): z1/z2, module m [m].
  CornerGeometry pair_geometry(int z1, int z2, double m)
  {
    CornerGeometry g;
    const double a = 0.5 * m * (z1 + z2), al = 20 * deg;
    g.rb1 = 0.5 * m * z1 * std::cos(al), g.rb2 = 0.5 * m * z2 * std::cos(al);
    g.r_tip1 = 0.5 * m * z1 + m, g.r_tip2 = 0.5 * m * z2 + m;
    g.length = a * std::sin(al);
    g.g_E = std::sqrt(g.r_tip1 * g.r_tip1 - g.rb1 * g.rb1);
    g.g_A = g.length - std::sqrt(g.r_tip2 * g.r_tip2 - g.rb2 * g.rb2);
    return g;
  }

  double bisect(const std::function<double(double)> &f, double lo, double hi)
  {
    double flo = f(lo);
    EXPECT_LE(flo * f(hi), 0.0) << "bracket";
    for (int i = 0; i < 200; ++i)
      {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm <= 0) == (flo <= 0))
          lo = mid, flo = fm;
        else
          hi = mid;
      }
    return 0.5 * (lo + hi);
  }

  struct V
  {
    double x, y;
  };
  V rot(const V &p, const V &c, double b)
  {
    const double dx = p.x - c.x, dy = p.y - c.y;
    return {c.x + std::cos(b) * dx - std::sin(b) * dy, c.y + std::sin(b) * dx + std::cos(b) * dy};
  }

  // Brute force in the pair frame: O1 = 0, T1 = (rb1, 0), the line of action along +y,
  // T2 = (rb1, L), O2 = (rb1 + rb2, L). An involute is the end of a string unwound from
  // its base circle: point(u) = C + rb [e(t0 - u) + u e(t0 - u + pi/2)] (pinion, unwinding
  // clockwise from t0), the gear the same turned by pi about O2. At rigid position g both
  // involutes pass through T1 + g y (pinion roll g, gear roll L - g).
  struct Brute
  {
    CornerGeometry G;
    V O1{0, 0}, O2;
    explicit Brute(const CornerGeometry &g)
      : G(g)
      , O2{g.rb1 + g.rb2, g.length}
    {}
    V pinion_flank(double g, double u) const
    {
      const double t = g / G.rb1 - u;
      return {G.rb1 * (std::cos(t) - u * std::sin(t)), G.rb1 * (std::sin(t) + u * std::cos(t))};
    }
    V gear_flank(double g, double u) const
    {
      const double t = (G.length - g) / G.rb2 - u;
      return {O2.x - G.rb2 * (std::cos(t) - u * std::sin(t)), O2.y - G.rb2 * (std::sin(t) + u * std::cos(t))};
    }
    // The point of a flank at distance r from its centre (bisection on the roll u).
    static V at_radius(const std::function<V(double)> &flank, const V &c, double r)
    {
      const double u = bisect([&](double uu) { const V p = flank(uu); return std::hypot(p.x - c.x, p.y - c.y) - r; },
                              0.0, 2.0);
      return flank(u);
    }
    // Signed angle from the flank point at p's radius to p, about c (positive: p outside).
    static double offset(const std::function<V(double)> &flank, const V &c, const V &p, double sense)
    {
      const V q = at_radius(flank, c, std::hypot(p.x - c.x, p.y - c.y));
      const double a = std::atan2(p.y - c.y, p.x - c.x) - std::atan2(q.y - c.y, q.x - c.x);
      return sense * std::remainder(a, 2 * pi);
    }
    V pinion_corner(double g) const
    {
      return at_radius([&](double u) { return pinion_flank(g, u); }, O1, std::hypot(G.rb1, G.g_E));
    }
    V gear_corner(double g) const
    {
      return at_radius([&](double u) { return gear_flank(g, u); }, O2, std::hypot(G.rb2, G.length - G.g_A));
    }
    // Beyond E, gear turned: the gear rotation (about O2, towards the corner) that brings
    // its flank at the corner's radius onto the pinion corner, times rb2.
    double gap_end_gear_turns(double g) const
    {
      const V P = pinion_corner(g);
      const double b = bisect(
        [&](double beta) {
          return offset([&](double u) { return rot(gear_flank(g, u), O2, beta); }, O2, P, 1.0);
        },
        0.0, 0.2);
      return G.rb2 * b;
    }
    // Beyond E, pinion turned (gear held): the pinion rotation that brings its corner onto
    // the gear flank, times rb1.
    double gap_end_pinion_turns(double g) const
    {
      const double b = bisect(
        [&](double beta) {
          return offset([&](double u) { return gear_flank(g, u); }, O2, rot(pinion_corner(g), O1, beta), 1.0);
        },
        0.0, 0.2);
      return G.rb1 * b;
    }
    // Before A, pinion turned: its flank at the corner's radius onto the gear corner.
    double gap_start(double g) const
    {
      const V Q = gear_corner(g);
      const double b = bisect(
        [&](double beta) {
          return offset([&](double u) { return rot(pinion_flank(g, u), O1, beta); }, O1, Q, -1.0);
        },
        0.0, 0.2);
      return G.rb1 * b;
    }
  };
} // namespace

TEST(CornerGap, ZeroOnThePathAndAtItsEnds)
{
  for (const auto &G : {pair_geometry(50, 50, 3e-3), pair_geometry(23, 69, 4e-3)})
    for (const GapFrame f : {GapFrame::pinion, GapFrame::mating})
      {
        EXPECT_EQ(corner_gap(G, G.g_A, f), 0.0);
        EXPECT_EQ(corner_gap(G, G.g_E, f), 0.0);
        EXPECT_EQ(corner_gap(G, 0.5 * (G.g_A + G.g_E), f), 0.0);
        EXPECT_EQ(corner_contact(G, G.g_E, f).arm, 1.0);
        // Just outside: tiny, positive.
        EXPECT_GT(corner_gap(G, G.g_E + 1e-6, f), 0.0);
        EXPECT_LT(corner_gap(G, G.g_E + 1e-6, f), 1e-10);
        EXPECT_GT(corner_gap(G, G.g_A - 1e-6, f), 0.0);
        EXPECT_LT(corner_gap(G, G.g_A - 1e-6, f), 1e-10);
      }
}

TEST(CornerGap, MatchesBruteForceRotation)
{
  double worst = 0;
  for (const auto &G : {pair_geometry(50, 50, 3e-3), pair_geometry(23, 69, 4e-3)})
    {
      const Brute B(G);
      const double pb = pi * 3e-3 * std::cos(20 * deg);
      for (const double d : {2e-5, 1e-4, 5e-4, 1e-3, 2e-3, 4e-3, 0.8 * pb})
        {
          const double e1 = corner_gap(G, G.g_E + d, GapFrame::mating) - B.gap_end_gear_turns(G.g_E + d);
          const double e2 = corner_gap(G, G.g_E + d, GapFrame::pinion) - B.gap_end_pinion_turns(G.g_E + d);
          const double e3 = corner_gap(G, G.g_A - d, GapFrame::pinion) - B.gap_start(G.g_A - d);
          const double e4 = corner_gap(G, G.g_A - d, GapFrame::mating) - B.gap_start(G.g_A - d);
          for (const double e : {e1, e2, e3, e4})
            {
              EXPECT_LT(std::abs(e), 1e-9) << "d = " << d;
              worst = std::max(worst, std::abs(e));
            }
        }
    }
  std::printf("corner gap against brute force: max |difference| %.2e m\n", worst);
}

TEST(CornerGap, LeadingOrderCurvatureForm)
{
  for (const auto &G : {pair_geometry(50, 50, 3e-3), pair_geometry(23, 69, 4e-3)})
    for (const bool end : {true, false})
      {
        const double R = corner_gap_curvature_radius(G, end);
        double prev = 1;
        for (const double d : {1e-4, 1e-5, 1e-6})
          for (const GapFrame f : {GapFrame::pinion, GapFrame::mating})
            {
              const double gap = corner_gap(G, end ? G.g_E + d : G.g_A - d, f);
              const double rel = std::abs(gap / (d * d / (2 * R)) - 1);
              // The next term is O(d / rho): relative error shrinks linearly with d.
              EXPECT_LT(rel, 30 * d / 1e-3 * 0.1 + 1e-6) << "d = " << d << (end ? " beyond E" : " before A");
              if (f == GapFrame::pinion)
                {
                  EXPECT_LT(rel, prev);
                  prev = rel;
                }
            }
      }
  // The Parker pair (50/50, m 3): R = rb^2 rho_m / (rho_c T1T2) ~ 51.8 mm.
  EXPECT_NEAR(corner_gap_curvature_radius(pair_geometry(50, 50, 3e-3), true), 51.8e-3, 0.1e-3);
}

TEST(CornerGap, ContinuousAndMonotone)
{
  const CornerGeometry G = pair_geometry(23, 69, 4e-3);
  const double pb = pi * 4e-3 * std::cos(20 * deg);
  for (const GapFrame f : {GapFrame::pinion, GapFrame::mating})
    for (const bool end : {true, false})
      {
        // Increasing, and smooth: the second differences (~ the curvature 1/R of the gap)
        // change little from one step to the next (a jump or a kink would be a spike).
        const int n = 4000;
        const double h = 0.8 * pb / n; // up to 0.8 p_b (gaps of ~1 mm there)
        std::vector<double> gap(n + 1, 0.0);
        double cmax = 0, dc = 0, cprev = 0, cfirst = 0;
        for (int i = 1; i <= n; ++i)
          {
            gap[i] = corner_gap(G, end ? G.g_E + h * i : G.g_A - h * i, f);
            ASSERT_TRUE(std::isfinite(gap[i]));
            EXPECT_GT(gap[i], gap[i - 1]);
            if (i >= 2)
              {
                const double c = (gap[i] - 2 * gap[i - 1] + gap[i - 2]) / (h * h);
                cmax = std::max(cmax, std::abs(c));
                if (i == 2)
                  cfirst = c;
                if (i >= 3)
                  dc = std::max(dc, std::abs(c - cprev));
                cprev = c;
              }
          }
        EXPECT_LT(dc, 0.01 * cmax);
        EXPECT_NEAR(cfirst * corner_gap_curvature_radius(G, end), 1.0, 0.01); // 1/R at the path end
      }
}

TEST(CornerGap, NoContactOffTheMatingInvolute)
{
  CornerGeometry G = pair_geometry(50, 50, 3e-3);
  const Brute B(G);
  // Beyond E the pinion corner meets the gear flank ever higher up (further from O2).
  auto radius = [&](double d) {
    const V P = B.pinion_corner(G.g_E + d);
    return std::hypot(P.x - B.O2.x, P.y - B.O2.y);
  };
  const double r1 = radius(1e-3), r3 = radius(3e-3);
  EXPECT_GT(r3, r1);
  // A (fictitious) gear form circle between them: the contact 1 mm beyond E would lie
  // below it, off the involute.
  G.r_form2 = 0.5 * (r1 + r3);
  EXPECT_TRUE(std::isfinite(corner_gap(G, G.g_E + 3e-3, GapFrame::mating)));
  EXPECT_TRUE(std::isinf(corner_gap(G, G.g_E + 1e-3, GapFrame::mating)));
  EXPECT_TRUE(std::isinf(corner_gap(G, G.g_E + 1e-3, GapFrame::pinion)));
  // And above the mate's tip circle.
  G.r_form2 = 0;
  G.r_tip2 = 0.5 * (r1 + r3);
  EXPECT_TRUE(std::isfinite(corner_gap(G, G.g_E + 1e-3, GapFrame::mating)));
  EXPECT_TRUE(std::isinf(corner_gap(G, G.g_E + 3e-3, GapFrame::mating)));
}

// The lever arm of the corner force about O1 (pinion frame): a pinion rotation dθ with the
// gear held equals a rigid advance rb1 dθ plus the gear turned back by rb1 dθ / rb2, so
// the normal approach is rb1 (1 - dG/dg) dθ with G the gear-frame gap: arm = 1 - G'(g + x).
TEST(CornerGap, LeverArmOfTheCornerForce)
{
  const CornerGeometry G = pair_geometry(23, 69, 4e-3);
  for (const double d : {1e-4, 1e-3, 3e-3})
    {
      const CornerContact c = corner_contact(G, G.g_E + d, GapFrame::pinion);
      const double s = G.g_E + d + c.gap, h = 1e-7;
      const double dG = (corner_gap(G, s + h, GapFrame::mating) - corner_gap(G, s - h, GapFrame::mating)) / (2 * h);
      EXPECT_NEAR(c.arm, 1 - dG, 1e-7) << d;
      EXPECT_LT(c.arm, 1.0);
      // Before A the force acts along the pinion normal: arm 1.
      EXPECT_EQ(corner_contact(G, G.g_A - d, GapFrame::pinion).arm, 1.0);
    }
}

// A tip rounding of radius rho moves the end of the flank inwards (the path shortens) and
// the rounding arc then carries the corner contact: its gap against a dense brute-force
// minimum over the arc points of the gear-frame distance.
TEST(CornerGap, TipRounding)
{
  CornerGeometry G = pair_geometry(50, 50, 3e-3);
  const CornerGeometry sharp = G;
  G.rounding1 = 0.3e-3;
  const double rc = G.r_tip1 - G.rounding1;
  const double gE = std::sqrt(rc * rc - G.rb1 * G.rb1) + G.rounding1; // new end of the flank
  EXPECT_LT(gE, sharp.g_E);
  EXPECT_NEAR(corner_path_end(G, true), gE, 1e-15);
  EXPECT_EQ(corner_path_end(G, false), G.g_A); // the gear is still sharp
  EXPECT_EQ(corner_gap(G, gE - 1e-9, GapFrame::mating), 0.0);
  EXPECT_GT(corner_gap(G, gE + 1e-6, GapFrame::mating), 0.0);
  const Brute B(sharp);
  for (const double d : {1e-4, 5e-4, 2e-3})
    {
      const double g = gE + d;
      // Arc centre: at radius r_tip - rho (tangent to the tip circle) and rho inside the flank
      // along its normal (tangent to the flank): bisection on the roll of the tangent point.
      auto normal = [&](double u) {
        const double t = g / G.rb1 - u;
        return V{-std::sin(t), std::cos(t)}; // outward normal of the pinion flank (the string)
      };
      auto centre = [&](double u) {
        const V f = B.pinion_flank(g, u), n = normal(u);
        return V{f.x - G.rounding1 * n.x, f.y - G.rounding1 * n.y};
      };
      const double ut = bisect([&](double u) { const V c = centre(u); return std::hypot(c.x, c.y) - rc; }, 0.1, 1.0);
      const V c = centre(ut), nrm = normal(ut), rad{c.x / rc, c.y / rc};
      EXPECT_NEAR(ut * G.rb1, gE, 1e-12);
      // The arc runs from the flank normal to the radial direction of its centre.
      auto cross = [](const V &a, const V &b) { return a.x * b.y - a.y * b.x; };
      double best = 1e9;
      for (int k = 0; k <= 20002; ++k)
        {
          const double ang = 2 * pi * k / 20000;
          const V w = k == 20001 ? nrm : k == 20002 ? rad : V{std::cos(ang), std::sin(ang)};
          const double side = cross(nrm, rad);
          if (k <= 20000 && (cross(nrm, w) * side < 0 || cross(w, rad) * side < 0 || nrm.x * w.x + nrm.y * w.y < 0))
            continue;
          const V p{c.x + G.rounding1 * w.x, c.y + G.rounding1 * w.y};
          const double off = Brute::offset([&](double u) { return B.gear_flank(g, u); }, B.O2, p, 1.0);
          best = std::min(best, G.rb2 * off);
        }
      EXPECT_NEAR(corner_gap(G, g, GapFrame::mating), best, 2e-9) << d;
    }
}

// Far beyond E on the FZG type C pair (16/24, m 4.5, x 0.1817/0.1715, a 91.5 mm) the
// pinion-frame gap x = G(g + x) is about 4 mm and G' approaches 1: the fixed-point
// iteration alone stalled there (gearfem rate exited 3). The bracketed root must agree with
// the brute-force rotation over the whole pitch beyond E, and be non-decreasing.
TEST(CornerGap, PinionFrameFarBeyondEFzgTypeC)
{
  const double m = 4.5e-3, al = 20 * deg, x1 = 0.1817, x2 = 0.1715;
  const int    z1 = 16, z2 = 24;
  auto inv = [](double a) { return std::tan(a) - a; };
  const double target = inv(al) + 2 * (x1 + x2) * std::tan(al) / (z1 + z2);
  double aw = al;
  for (int i = 0; i < 50; ++i) // Newton on inv(aw) = target (inv' = tan^2)
    aw -= (inv(aw) - target) / std::pow(std::tan(aw), 2);
  CornerGeometry G;
  G.rb1 = 0.5 * m * z1 * std::cos(al), G.rb2 = 0.5 * m * z2 * std::cos(al);
  const double a = (G.rb1 + G.rb2) / std::cos(aw);
  G.r_tip1 = 0.5 * m * z1 + m * (1 + x1), G.r_tip2 = 0.5 * m * z2 + m * (1 + x2);
  G.length = a * std::sin(aw);
  G.g_E = std::sqrt(G.r_tip1 * G.r_tip1 - G.rb1 * G.rb1);
  G.g_A = G.length - std::sqrt(G.r_tip2 * G.r_tip2 - G.rb2 * G.rb2);
  const Brute B(G);
  const double pb = pi * m * std::cos(al);
  double prev = 0, worst = 0, largest = 0;
  for (int k = 1; k <= 40; ++k)
    {
      const double g = G.g_E + pb * k / 40;
      double x = 0;
      ASSERT_NO_THROW(x = corner_gap(G, g, GapFrame::pinion)) << "g = " << g;
      if (!std::isfinite(x))
        break; // the corner has left the gear flank: no contact from here on
      EXPECT_NEAR(x, B.gap_end_pinion_turns(g), 1e-9) << "g = " << g;
      EXPECT_GE(x, prev - 1e-15);
      worst = std::max(worst, std::abs(x - B.gap_end_pinion_turns(g))), prev = x, largest = std::max(largest, x);
    }
  EXPECT_GT(largest, 1e-3); // the hard region (gaps of millimetres) was reached
  std::printf("FZG C pinion-frame corner gap: up to %.3f mm, max |difference| to brute force %.2e m\n",
              largest * 1e3, worst);
}
