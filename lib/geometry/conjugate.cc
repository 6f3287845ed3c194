// Conjugate generation (Costopoulos) and its inverse (Spitas, Costopoulos & Spitas 2002).
// See conjugate.h and docs/geometry.md for the derivation of every term below.
#include "geometry/conjugate.h"
#include "base/units.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::geometry
{
  namespace
  {
    Eigen::Matrix2d rot(double a)
    {
      Eigen::Matrix2d R;
      R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
      return R;
    }
    /// J v: v turned by +90 degrees.
    double cross(const Vec2 &a, const Vec2 &b) { return a.x() * b.y() - a.y() * b.x(); }

    /// Rack displacement s and its first two derivatives for a rack curve P(t):
    /// the rack normal at P passes through the pitch point, s u' = -(P.P').
    struct Displacement
    {
      double s, s1, s2;
    };
    Displacement displacement(const Vec2 &P, const Vec2 &P1, const Vec2 &P2, const Vec2 &P3)
    {
      const double u1 = P1.x(), u2 = P2.x(), u3 = P3.x();
      const double f  = P.dot(P1);
      const double f1 = P1.squaredNorm() + P.dot(P2);
      const double f2 = 3.0 * P1.dot(P2) + P.dot(P3);
      const double N  = f1 * u1 - f * u2; // s' = -N / u1^2
      const double N1 = f2 * u1 - f * u3;
      const double D = u1 * u1, D1 = 2.0 * u1 * u2;
      return {-f / u1, -N / D, -(N1 * D - N * D1) / (D * D)};
    }
    Displacement displacement(const Curve &rack, double t)
    {
      return displacement(rack.point(t), rack.d1(t), rack.d2(t), rack.d3(t));
    }
  } // namespace

  ConjugateCurve::ConjugateCurve(CurvePtr rack_curve, double r0)
    : rack_(std::move(rack_curve))
    , r0_(r0)
  {}
  double ConjugateCurve::t_begin() const { return rack_->t_begin(); }
  double ConjugateCurve::t_end() const { return rack_->t_end(); }

  double ConjugateCurve::rack_displacement(double t) const
  {
    const Vec2 P = rack_->point(t), P1 = rack_->d1(t);
    return -P.dot(P1) / P1.x();
  }

  Vec2 ConjugateCurve::contact_point(double t) const
  {
    const Vec2 P = rack_->point(t);
    return Vec2(P.x() + rack_displacement(t), r0_ + P.y());
  }

  Vec2 ConjugateCurve::point(double t) const
  {
    const double s = rack_displacement(t);
    return rot(s / r0_) * contact_point(t);
  }

  Vec2 ConjugateCurve::d1(double t) const
  {
    const auto   D  = displacement(*rack_, t);
    const Vec2   P1 = rack_->d1(t);
    const Vec2   Q  = contact_point(t);
    const Vec2   Q1(P1.x() + D.s1, P1.y());
    const double th1 = D.s1 / r0_;
    return rot(D.s / r0_) * (Q1 + th1 * perp(Q));
  }

  Vec2 ConjugateCurve::d2(double t) const
  {
    const auto   D  = displacement(*rack_, t);
    const Vec2   P1 = rack_->d1(t), P2 = rack_->d2(t);
    const Vec2   Q  = contact_point(t);
    const Vec2   Q1(P1.x() + D.s1, P1.y()), Q2(P2.x() + D.s2, P2.y());
    const double th1 = D.s1 / r0_, th2 = D.s2 / r0_;
    return rot(D.s / r0_) * (Q2 + 2.0 * th1 * perp(Q1) + th2 * perp(Q) - th1 * th1 * Q);
  }

  void ConjugateCurve::evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const
  {
    // point, d1 and d2 above from one evaluation of the rack (the same expressions).
    Vec2 P, P1, P2;
    rack_->evaluate(t, P, P1, P2);
    const auto         D = displacement(P, P1, P2, rack_->d3(t));
    const Vec2         Q(P.x() + D.s, r0_ + P.y());
    const Vec2         Q1(P1.x() + D.s1, P1.y()), Q2(P2.x() + D.s2, P2.y());
    const double       th1 = D.s1 / r0_, th2 = D.s2 / r0_;
    const Eigen::Matrix2d R = rot(D.s / r0_);
    p  = R * Q;
    p1 = R * (Q1 + th1 * perp(Q));
    p2 = R * (Q2 + 2.0 * th1 * perp(Q1) + th2 * perp(Q) - th1 * th1 * Q);
  }

  // ------------------------------------------------------------------ inverse
  // The gear point G (gear frame) is in contact when the gear is turned by -theta so that
  // its normal passes through the pitch point C = (0, r0): with beta the direction of G',
  // sin(beta - theta) = G.G' / (r0 |G'|). Then s = r0 theta and the rack point is
  // Rot(-theta) G - (s, r0).
  namespace
  {
    struct InverseAngle
    {
      double th, th1, th2;
    };
    InverseAngle inverse_angle(const Curve &g, double r0, double t, double outward_sign)
    {
      const Vec2   G = g.point(t), G1 = g.d1(t), G2 = g.d2(t), G3 = g.d3(t);
      const double L2 = G1.squaredNorm(), L = std::sqrt(L2);
      const double L1  = G1.dot(G2) / L;
      const double L2d = (G2.squaredNorm() + G1.dot(G3) - L1 * L1) / L;
      const double N = G.dot(G1), N1 = L2 + G.dot(G2), N2 = 3.0 * G1.dot(G2) + G.dot(G3);
      const double w  = N / (r0 * L);
      const double w1 = (N1 * L - N * L1) / (r0 * L2);
      const double w2 = (N2 * L - N * L2d) / (r0 * L2) - 2.0 * L1 * (N1 * L - N * L1) / (r0 * L2 * L);
      if (!(std::abs(w) < 1.0))
        throw InputError("Rack/Control points", "flank point at radius " +
                                                  to_string_g(G.norm() * 1e3) + " mm",
                         "a flank whose normal can pass through the pitch point",
                         "the given flank cannot be generated by any rack (|G.G'| >= r0 |G'|)");
      const double q     = std::sqrt(1.0 - w * w);
      const double a     = std::asin(w);
      const double a1    = w1 / q;
      const double a2    = w2 / q + w * w1 * w1 / (q * q * q);
      const double beta  = std::atan2(G1.y(), G1.x());
      const double c     = cross(G1, G2);
      const double beta1 = c / L2;
      const double beta2 = cross(G1, G3) / L2 - 2.0 * c * G1.dot(G2) / (L2 * L2);
      // Two solutions: theta = beta - asin(w) and theta = beta - pi + asin(w). The contact is
      // the one that turns the outward normal towards the rack (n.y > 0); the other touches
      // the back of the flank. Nearest to zero only decides a degenerate case (near the base
      // circle, at large turns, the back-side root can be nearer to zero).
      const double t_a = std::remainder(beta - a, 2.0 * units::pi);
      const double t_b = std::remainder(beta - units::pi + a, 2.0 * units::pi);
      const Vec2   n   = outward_sign * Vec2(G1.y(), -G1.x()) / L;
      const bool   ua  = (rot(-t_a) * n).y() > 0, ub = (rot(-t_b) * n).y() > 0;
      if (ua != ub ? ua : std::abs(t_a) <= std::abs(t_b))
        return {t_a, beta1 - a1, beta2 - a2};
      return {t_b, beta1 + a1, beta2 + a2};
    }
  } // namespace

  InverseConjugateCurve::InverseConjugateCurve(CurvePtr gear_curve, double r0)
    : gear_(std::move(gear_curve))
    , r0_(r0)
  {
    // Outward normal of an x > 0 flank: of the two normals at mid-flank, the one towards +x.
    const double tm = 0.5 * (gear_->t_begin() + gear_->t_end());
    outward_      = gear_->d1(tm).y() > 0 ? 1.0 : -1.0;
  }
  double InverseConjugateCurve::t_begin() const { return gear_->t_begin(); }
  double InverseConjugateCurve::t_end() const { return gear_->t_end(); }

  Vec2 InverseConjugateCurve::point(double t) const
  {
    const auto A = inverse_angle(*gear_, r0_, t, outward_);
    return rot(-A.th) * gear_->point(t) - Vec2(r0_ * A.th, r0_);
  }

  Vec2 InverseConjugateCurve::d1(double t) const
  {
    const auto A = inverse_angle(*gear_, r0_, t, outward_);
    const Vec2 G = gear_->point(t), G1 = gear_->d1(t);
    return rot(-A.th) * (G1 - A.th1 * perp(G)) - Vec2(r0_ * A.th1, 0.0);
  }

  Vec2 InverseConjugateCurve::d2(double t) const
  {
    const auto A = inverse_angle(*gear_, r0_, t, outward_);
    const Vec2 G = gear_->point(t), G1 = gear_->d1(t), G2 = gear_->d2(t);
    return rot(-A.th) * (G2 - 2.0 * A.th1 * perp(G1) - A.th2 * perp(G) - A.th1 * A.th1 * G) -
           Vec2(r0_ * A.th2, 0.0);
  }
} // namespace gearfem::geometry
