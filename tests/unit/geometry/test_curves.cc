// Curves, conjugate generation and its inverse: exactness checks against closed forms.
#include "base/errors.h"
#include "base/units.h"
#include "geometry/conjugate.h"
#include "geometry/curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace gearfem::geometry;

namespace
{
  double fd_error(const Curve &c, int order, double t)
  {
    // Central difference of the next-lower derivative (independent of the analytic one).
    const double h = 1e-6;
    Vec2         fd, ex;
    if (order == 1)
      fd = (c.point(t + h) - c.point(t - h)) / (2 * h), ex = c.d1(t);
    else
      fd = (c.d1(t + h) - c.d1(t - h)) / (2 * h), ex = c.d2(t);
    return (fd - ex).norm() / std::max(1.0, ex.norm());
  }
} // namespace

// Closed form: a degree-4 clamped B-spline with 5 control points is the Bezier curve, so
// p(0) = P0, p'(0) = 4 (P1 - P0), p''(0) = 12 (P2 - 2 P1 + P0), p(1/2) = sum of Bernstein terms.
TEST(Curves, BSplineIsBezierForFivePoints)
{
  std::vector<Vec2> P = {{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 0}};
  BSplineCurve      c(P, 4);
  EXPECT_LT((c.point(0) - P[0]).norm(), 1e-14);
  EXPECT_LT((c.point(1) - P[4]).norm(), 1e-14);
  EXPECT_LT((c.d1(0) - 4 * (P[1] - P[0])).norm(), 1e-12);
  EXPECT_LT((c.d2(0) - 12 * (P[2] - 2 * P[1] + P[0])).norm(), 1e-12);
  EXPECT_LT((c.d3(0) - 24 * (P[3] - 3 * P[2] + 3 * P[1] - P[0])).norm(), 1e-11);
  const Vec2 half = (P[0] + 4 * P[1] + 6 * P[2] + 4 * P[3] + P[4]) / 16.0;
  EXPECT_LT((c.point(0.5) - half).norm(), 1e-14);
}

// More control points than degree + 1: derivatives agree with finite differences.
TEST(Curves, BSplineDerivativesMatchFiniteDifferences)
{
  BSplineCurve c({{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 0}, {7, 2}, {8, 1}}, 4);
  for (double t : {0.1, 0.33, 0.5, 0.77, 0.9})
    {
      EXPECT_LT(fd_error(c, 1, t), 1e-7);
      EXPECT_LT(fd_error(c, 2, t), 1e-6);
    }
}

// closest_parameter recovers the foot of a perpendicular on a circle to ~1e-12.
TEST(Curves, ClosestParameterOnArc)
{
  CircularArc arc(Vec2(0.01, 0.02), 0.05, 0.2, 2.5);
  for (double t : {0.3, 1.0, 2.2})
    {
      const Vec2 q = arc.point(t) + 0.003 * (arc.point(t) - arc.centre()).normalized();
      EXPECT_NEAR(arc.closest_parameter(q), t, 1e-11);
    }
  // Curvature of a CCW circle is +1/r.
  EXPECT_NEAR(arc.curvature(1.0), 1 / 0.05, 1e-9);
}

// The conjugate of a straight rack flank has exact derivatives (finite-difference check),
// and InverseConjugateCurve ("involutisation") recovers the straight rack from it.
TEST(Conjugate, InverseRecoversStraightRack)
{
  const double a = 20 * gearfem::units::deg, r0 = 0.05, m = 0.005;
  auto rack = std::make_shared<LineSegment>(Vec2(m * gearfem::units::pi / 4 - m * std::tan(a), m),
                                            Vec2(m * gearfem::units::pi / 4 + m * std::tan(a), -m));
  auto gear = std::make_shared<ConjugateCurve>(rack, r0);
  for (double t : {0.1, 0.4, 0.7})
    {
      EXPECT_LT(fd_error(*gear, 1, t), 1e-7);
      EXPECT_LT(fd_error(*gear, 2, t), 1e-5);
    }
  InverseConjugateCurve back(gear, r0);
  for (double t : {0.05, 0.3, 0.6, 0.9})
    EXPECT_LT((back.point(t) - rack->point(t)).norm(), 1e-12) << "t = " << t;
  // Its derivatives: tangent parallel to the rack line.
  for (double t : {0.2, 0.5})
    {
      const Vec2 d = back.d1(t), r = rack->d1(t);
      EXPECT_LT(std::abs(d.x() * r.y() - d.y() * r.x()) / (d.norm() * r.norm()), 1e-9);
      EXPECT_LT(fd_error(back, 1, t), 1e-6);
    }
}

// Round trip on a B-spline flank: flank -> rack (inverse) -> flank (forward) to 1e-12 m.
TEST(Conjugate, BSplineFlankRoundTrip)
{
  const double m = 2.5e-3, r0 = 19 * m / 2;
  std::vector<Vec2> cp = {{1.45 * m, 8.5 * m}, {1.35 * m, 8.9 * m}, {1.2 * m, 9.4 * m},
                          {1.0 * m, 9.9 * m},  {0.8 * m, 10.4 * m}};
  auto flank = std::make_shared<BSplineCurve>(cp, 4);
  auto rack  = std::make_shared<InverseConjugateCurve>(flank, r0);
  ConjugateCurve again(rack, r0);
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0})
    EXPECT_LT((again.point(t) - flank->point(t)).norm(), 1e-12) << "t = " << t;
}

// parameter_at_radius (the one "curve parameter at a radius" of profile, tooth_load and the
// gear mesh): on a line x = 0.03 + 0.04 t, y = 0.01 the radius is sqrt(x^2 + y^2), so the
// parameter at r is (sqrt(r^2 - y^2) - 0.03) / 0.04 in closed form; either parameter order;
// an end on the circle is returned exactly; a radius outside the curve is a SolverError
// naming the radius.
TEST(Curves, ParameterAtRadiusClosedForm)
{
  const LineSegment line(Vec2(0.03, 0.01), Vec2(0.07, 0.01));
  for (double r : {0.035, 0.05, 0.0695})
    {
      const double t = (std::sqrt(r * r - 1e-4) - 0.03) / 0.04;
      EXPECT_NEAR(parameter_at_radius(line, 0.0, 1.0, r), t, 1e-15);
      EXPECT_NEAR(parameter_at_radius(line, 1.0, 0.0, r), t, 1e-15);
      EXPECT_NEAR(line.point(parameter_at_radius(line, 0.0, 1.0, r)).norm(), r, 4e-17); // a few ulps of r
    }
  EXPECT_EQ(parameter_at_radius(line, 0.0, 1.0, line.point(1.0).norm()), 1.0);
  try
    {
      parameter_at_radius(line, 0.0, 1.0, 0.08);
      ADD_FAILURE() << "a radius beyond the curve must throw";
    }
  catch (const gearfem::SolverError &e)
    {
      EXPECT_NE(std::string(e.what()).find("r = 0.08 m"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("does not bracket"), std::string::npos) << e.what();
    }
}

// evaluate() (point and both derivatives in one pass, used by the closest-point Newton)
// gives the values of point(), d1() and d2(): the conjugate of a straight rack flank and of
// a rack tip round (the trochoid), and their mirrored, reversed copies.
TEST(Conjugate, EvaluateEqualsThePointAndDerivativeCalls)
{
  const double r0   = 0.075;
  const auto flank  = std::make_shared<LineSegment>(Vec2(-0.0021, -0.00375), Vec2(0.0011, 0.0030));
  const auto round  = std::make_shared<CircularArc>(Vec2(-0.0025, -0.0030), 0.00075, -2.9, -1.6);
  for (const CurvePtr rack : {CurvePtr(flank), CurvePtr(round)})
    {
      const auto conj = std::make_shared<ConjugateCurve>(rack, r0);
      Eigen::Matrix2d M;
      M << -0.6, 0.8, 0.8, 0.6; // a reflection
      const AffineCurve copy(conj, M, Vec2(0.001, -0.002), true);
      for (const Curve *c : {static_cast<const Curve *>(conj.get()), static_cast<const Curve *>(&copy)})
        for (int i = 0; i <= 10; ++i)
          {
            const double t = c->t_begin() + (c->t_end() - c->t_begin()) * (0.02 + 0.096 * i);
            Vec2 p, p1, p2;
            c->evaluate(t, p, p1, p2);
            const Vec2 e[3] = {c->point(t), c->d1(t), c->d2(t)}, g[3] = {p, p1, p2};
            for (int k = 0; k < 3; ++k)
              EXPECT_LE((g[k] - e[k]).norm(), 4e-16 * e[k].norm()) << "t " << t << ", derivative " << k;
          }
    }
}
