#pragma once
// Parametric plane curves with exact derivatives. Everything in SI (m, rad).
// No deal.II types: this is the light layer.
#include <Eigen/Core>

#include <cmath>
#include <memory>
#include <vector>

namespace gearfem::geometry
{
  using Vec2 = Eigen::Vector2d;

  /// v turned by +90 degrees.
  inline Vec2 perp(const Vec2 &v) { return Vec2(-v.y(), v.x()); }
  /// v turned by `angle` [rad] about the origin, counter-clockwise.
  inline Vec2 rotate(const Vec2 &v, double angle)
  {
    const double c = std::cos(angle), s = std::sin(angle);
    return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
  }

  /// A smooth plane curve p(t), t in [t_begin(), t_end()], with exact first and second
  /// derivatives (third where the generator needs it).
  class Curve
  {
  public:
    virtual ~Curve() = default;
    virtual double t_begin() const = 0;
    virtual double t_end() const = 0;
    virtual Vec2 point(double t) const = 0;
    virtual Vec2 d1(double t) const = 0;
    virtual Vec2 d2(double t) const = 0;
    /// Third derivative; default by central difference of d2 (exact in overrides).
    virtual Vec2 d3(double t) const;
    /// point, d1 and d2 at t in one call: the same values as the three calls (overrides
    /// share the work the three have in common; the closest-point Newton needs all three).
    virtual void evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const;

    /// Signed curvature (x'y'' - y'x'')/|p'|^3; positive when the curve turns left
    /// (counter-clockwise) as t grows. Units 1/m.
    double curvature(double t) const;
    /// Unit normal pointing to the right of the direction of travel (d1 rotated by -90 deg).
    /// For an outline traversed counter-clockwise this is the outward normal.
    Vec2 right_normal(double t) const;
    /// Parameter of the point of the curve closest to q, by safeguarded Newton from a
    /// sampled start; clamped to [t_begin, t_end].
    double closest_parameter(const Vec2 &q) const;
    /// The same, restricted to the parameter interval between a and b (either order).
    double closest_parameter_in(const Vec2 &q, double a, double b) const;
    /// Arc length between t0 and t1 (adaptive Gauss-Legendre).
    double arc_length(double t0, double t1) const;
  };

  using CurvePtr = std::shared_ptr<const Curve>;

  /// Curve parameter t between a and b (either order) where |c(t)| = r: the radius r [m]
  /// must lie between |c(a)| and |c(b)| (an end that lies on the circle is returned as it
  /// is). Bisection on |c(t)| - r (base::find_root_bisection), by default down to the last
  /// bit; with t_tol > 0 it stops once a halving leaves the bracket no wider than
  /// t_tol max(1, |t|). Bisection makes the result reproducible to the bit, which matters
  /// because it places the ends of tooth segments and the mesh vertices at split radii (a
  /// last-bit change of the outline changes the gmsh mesh). Throws SolverError naming r,
  /// the interval and |c| - r at its ends when r is not between the end radii.
  double parameter_at_radius(const Curve &c, double a, double b, double r, double t_tol = 0.0);

  /// Straight segment from a to b, t in [0, 1].
  class LineSegment : public Curve
  {
  public:
    LineSegment(const Vec2 &a, const Vec2 &b);
    double t_begin() const override { return 0.0; }
    double t_end() const override { return 1.0; }
    Vec2 point(double t) const override;
    Vec2 d1(double t) const override;
    Vec2 d2(double t) const override;
    Vec2 d3(double t) const override;

  private:
    Vec2 a_, b_;
  };

  /// Circular arc: centre + r (cos t, sin t), t in [t0, t1] (t1 < t0 traverses clockwise).
  class CircularArc : public Curve
  {
  public:
    CircularArc(const Vec2 &centre, double radius, double t0, double t1);
    double t_begin() const override { return t0_; }
    double t_end() const override { return t1_; }
    Vec2 point(double t) const override;
    Vec2 d1(double t) const override;
    Vec2 d2(double t) const override;
    Vec2 d3(double t) const override;
    const Vec2 &centre() const { return c_; }
    double radius() const { return r_; }

  private:
    Vec2 c_;
    double r_, t0_, t1_;
  };

  /// Clamped B-spline of degree p (default 4) on a uniform open knot vector, t in [0, 1],
  /// with exact derivatives (Koronaios 2021: degree 4, 5 control points).
  class BSplineCurve : public Curve
  {
  public:
    BSplineCurve(std::vector<Vec2> control_points, unsigned int degree = 4);
    double t_begin() const override { return 0.0; }
    double t_end() const override { return 1.0; }
    Vec2 point(double t) const override;
    Vec2 d1(double t) const override;
    Vec2 d2(double t) const override;
    Vec2 d3(double t) const override;
    const std::vector<Vec2> &control_points() const { return cp_; }
    unsigned int degree() const { return p_; }

  private:
    Vec2 derivative(double t, unsigned int order) const;
    std::vector<Vec2> cp_;
    unsigned int p_;
    std::vector<double> knots_;
  };

  /// An affine image of another curve: p(t) = M c(sigma t) + b with sigma = +1 or -1
  /// (sigma = -1 reverses the direction; t then runs over [-c.t_end, -c.t_begin]).
  /// Used for the mirrored (drive) side of a tooth, for reversing a curve's direction, and
  /// for the complementary rack of the mating gear. Exact derivatives of the base curve.
  class AffineCurve : public Curve
  {
  public:
    AffineCurve(CurvePtr base, const Eigen::Matrix2d &M, const Vec2 &b, bool reverse);
    double t_begin() const override;
    double t_end() const override;
    Vec2 point(double t) const override;
    Vec2 d1(double t) const override;
    Vec2 d2(double t) const override;
    Vec2 d3(double t) const override;
    void evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const override;
    /// The base-curve parameter of curve parameter t.
    double base_parameter(double t) const { return sigma_ * t; }
    const CurvePtr &base() const { return base_; }

  private:
    CurvePtr base_;
    Eigen::Matrix2d M_;
    Vec2 b_;
    double sigma_;
  };

  /// The piece of another curve between parameters a < b (same parameter, exact
  /// derivatives): a B-spline rack split into the pieces that generate flank, fillet and
  /// root (rack.cc, closed racks).
  class TrimmedCurve : public Curve
  {
  public:
    TrimmedCurve(CurvePtr base, double a, double b);
    double t_begin() const override { return a_; }
    double t_end() const override { return b_; }
    Vec2 point(double t) const override { return base_->point(t); }
    Vec2 d1(double t) const override { return base_->d1(t); }
    Vec2 d2(double t) const override { return base_->d2(t); }
    Vec2 d3(double t) const override { return base_->d3(t); }
    void evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const override { base_->evaluate(t, p, p1, p2); }

  private:
    CurvePtr base_;
    double a_, b_;
  };

  /// Mirror image x -> -x (same parameter and direction).
  CurvePtr mirrored(CurvePtr c);
  /// The same curve traversed in the opposite direction (parameter t -> -t).
  CurvePtr reversed(CurvePtr c);
} // namespace gearfem::geometry
