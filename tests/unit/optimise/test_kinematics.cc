// Seed 003 statistics and the curvature route (lib/optimise/kinematics.h, design.h).
// Independent references: the involute closed forms (1/rho1 + 1/rho2 on the line of action,
// eps from the line of action), gear 2's own conjugate curve from the complementary rack
// (direct curvature, no Euler-Savary), and the thesis' Tables 5.2 and 6.1 (seed 003).
#include "geometry/conjugate.h"
#include "optimise/design.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem;
using namespace gearfem::optimise;

namespace
{
  const PairData seed003;
  double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }
} // namespace

TEST(Kinematics, InvoluteMatchesClosedForm)
{
  // Closed form (docs/geometry.md): rho1 = sqrt(r^2 - rb1^2), rho2 = a sin(alpha) - rho1.
  const Design d(DesignKind::involute, seed003);
  const FlankKinematics k(d.flank({}), seed003.r01(), seed003.r02());
  const double a = seed003.pressure_angle, rb1 = seed003.r01() * std::cos(a);
  const double T1T2 = (seed003.r01() + seed003.r02()) * std::sin(a);
  for (double t = 0.0; t <= 1.0; t += 0.05)
    {
      const ContactSample s = k.at(t);
      const double rho1 = std::sqrt(s.r1 * s.r1 - rb1 * rb1), rho2 = T1T2 - rho1;
      EXPECT_NEAR(s.kappa1 * rho1, 1.0, 1e-9) << t;
      EXPECT_NEAR(s.kappa2 * rho2, 1.0, 1e-9) << t;
      EXPECT_NEAR(s.kappa_eq, 1 / rho1 + 1 / rho2, 1e-9 * s.kappa_eq);
      // theta by involutisation equals the rack displacement of the generating rack / r01.
      const geometry::ConjugateCurve &cc = static_cast<const geometry::ConjugateCurve &>(k.flank());
      EXPECT_NEAR(s.K, cc.rack_displacement(t), 1e-12);
    }
}

TEST(Kinematics, EulerSavaryMatchesGearTwoConjugate)
{
  // Gear 2 generated directly from the complementary rack (u, v) -> (p/2 - u, -v): its own
  // curvature at the matching parameter (convex > 0), against kappa2 from Euler-Savary.
  for (DesignKind kind : {DesignKind::sinusoid, DesignKind::case1_rack})
    {
      const Design d(kind, seed003);
      const auto x = d.default_start();
      const auto rk = d.rack(x);
      const double p = M_PI * seed003.module;
      Eigen::Matrix2d M;
      M << -1, 0, 0, -1;
      auto comp = std::make_shared<geometry::AffineCurve>(rk, M, Vec2(p / 2, 0.0), true);
      const geometry::ConjugateCurve g2(comp, seed003.r02());
      const FlankKinematics k(d.flank(x), seed003.r01(), seed003.r02());
      int checked = 0;
      for (double f = 0.05; f < 0.96; f += 0.05)
        {
          const double t = rk->t_begin() + f * (rk->t_end() - rk->t_begin());
          const ContactSample s = k.at(t);
          // traversal of g2 runs from its tip to its root: convex = -signed curvature.
          const double k2 = -g2.curvature(-t);
          EXPECT_NEAR(s.kappa2, k2, 1e-7 * (std::abs(k2) + 10)) << to_string(kind) << " t " << t;
          // The same contact point: gear 2's point at distance r2 from its centre.
          EXPECT_NEAR(s.r2, g2.point(-t).norm(), 1e-10);
          ++checked;
        }
      EXPECT_GT(checked, 15);
    }
}

TEST(Statistics, InvoluteRowOfTable61)
{
  // Thesis (second Table 6.1): mean 0.1783, max 0.6708, std 0.0762 1/mm, sampled uniformly
  // in pinion radius from r = 22.3730 mm (digest section 2) to the tip. Tolerance 0.2 %.
  const Design d(DesignKind::involute, seed003);
  EvaluationSettings s;
  s.start_radius = 22.3730e-3;
  const Evaluation ev = d.evaluate({}, s);
  ASSERT_TRUE(ev.computable) << ev.reason;
  EXPECT_LT(rel(ev.stats.mean_abs * 1e-3, 0.1783), 2e-3) << ev.stats.mean_abs * 1e-3;
  EXPECT_LT(rel(ev.stats.max_abs * 1e-3, 0.6708), 2e-3) << ev.stats.max_abs * 1e-3;
  EXPECT_LT(rel(ev.stats.std * 1e-3, 0.0762), 2e-3) << ev.stats.std * 1e-3;
  // Contact ratio from the sampled rack displacements against the closed form eps_alpha
  // from SAP (exact) to the tip: 1.657 (docs/geometry.md's line-of-action construction).
  EvaluationSettings sap;
  const Evaluation e2 = d.evaluate({}, sap);
  const double a = seed003.pressure_angle, rb1 = seed003.r01() * std::cos(a), rb2 = seed003.r02() * std::cos(a);
  const double ra1 = seed003.tip_radius(1), ra2 = seed003.tip_radius(2);
  const double eps = (std::sqrt(ra1 * ra1 - rb1 * rb1) + std::sqrt(ra2 * ra2 - rb2 * rb2) -
                      (seed003.r01() + seed003.r02()) * std::sin(a)) / (M_PI * seed003.module * std::cos(a));
  EXPECT_NEAR(e2.contact_ratio, eps, 1e-9);
  EXPECT_TRUE(e2.feasible) << e2.reason;
}

TEST(Statistics, SinusoidRowOfTable52)
{
  // Thesis Table 5.2: mean 0.1333, max 0.6719, std 0.1542 1/mm, uniform in rack x over one
  // flank. Tolerance 0.2 %.
  const Design d(DesignKind::sinusoid, seed003);
  const Evaluation ev = d.evaluate({}, EvaluationSettings{});
  ASSERT_TRUE(ev.computable) << ev.reason;
  EXPECT_LT(rel(ev.stats.mean_abs * 1e-3, 0.1333), 2e-3) << ev.stats.mean_abs * 1e-3;
  EXPECT_LT(rel(ev.stats.max_abs * 1e-3, 0.6719), 2e-3) << ev.stats.max_abs * 1e-3;
  EXPECT_LT(rel(ev.stats.std * 1e-3, 0.1542), 2e-3) << ev.stats.std * 1e-3;
  std::cout << "sinusoid eps " << ev.contact_ratio << " reason " << ev.reason << " min " << ev.stats.min * 1e-3
            << " c " << ev.constraints[0] << " " << ev.constraints[1] << "\n";
}

TEST(Design, StartPoints)
{
  for (DesignKind kind : {DesignKind::case1_rack, DesignKind::case2_flank})
    {
      const Design d(kind, seed003);
      const Evaluation ev = d.evaluate(d.default_start(), EvaluationSettings{});
      std::cout << to_string(kind) << " f " << ev.objective << " mean " << ev.stats.mean_abs * 1e-3 << " max "
                << ev.stats.max_abs * 1e-3 << " std " << ev.stats.std * 1e-3 << " eps " << ev.contact_ratio
                << " feasible " << ev.feasible << " " << ev.reason << " c " << ev.constraints[0] << " "
                << ev.constraints[1] << " " << ev.constraints[2] << " " << ev.constraints[3] << "\n";
    }
}
