// Plane curves with exact derivatives (see curve.h).
#include "geometry/curve.h"

#include "geometry/closest.h"

#include "base/errors.h"
#include "base/roots.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gearfem::geometry
{
  double parameter_at_radius(const Curve &c, double a, double b, double r, double t_tol)
  {
    return base::find_root_bisection([&](double t) { return c.point(t).norm() - r; }, a, b,
                                     "curve parameter at radius r = " + to_string_g(r) + " m", t_tol);
  }

  Vec2 Curve::d3(double t) const
  {
    // Central difference of the exact second derivative, kept inside the range.
    const double lo = std::min(t_begin(), t_end()), hi = std::max(t_begin(), t_end());
    const double h  = 1e-5 * std::max(1.0, hi - lo);
    const double a = std::max(lo, t - h), b = std::min(hi, t + h);
    return (d2(b) - d2(a)) / (b - a);
  }

  void Curve::evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const
  {
    p = point(t), p1 = d1(t), p2 = d2(t);
  }

  double Curve::curvature(double t) const
  {
    const Vec2   p1 = d1(t), p2 = d2(t);
    const double n  = p1.norm();
    if (n == 0.0)
      return std::numeric_limits<double>::infinity();
    return (p1.x() * p2.y() - p1.y() * p2.x()) / (n * n * n);
  }

  Vec2 Curve::right_normal(double t) const
  {
    const Vec2 p1 = d1(t);
    return Vec2(p1.y(), -p1.x()).normalized();
  }

  double Curve::closest_parameter(const Vec2 &q) const
  {
    return closest_parameter_in(q, t_begin(), t_end());
  }

  double Curve::closest_parameter_in(const Vec2 &q, double a, double b) const
  {
    const double lo = std::min(a, b), hi = std::max(a, b);
    // The shared search (geometry/closest.h) from 64 samples.
    const int n     = 64;
    const auto eval = [this](double s, Vec2 &p, Vec2 &p1, Vec2 &p2) { evaluate(s, p, p1, p2); };
    const double t  = geometry::closest_parameter(eval, [&](int i) { return point(lo + (hi - lo) * i / n); }, q, lo, hi, n);
    // The end points may be closer than the interior stationary point.
    const double dt = (point(t) - q).squaredNorm();
    if ((point(lo) - q).squaredNorm() < dt)
      return lo;
    if ((point(hi) - q).squaredNorm() < dt)
      return hi;
    return t;
  }

  double Curve::arc_length(double t0, double t1) const
  {
    // Composite 5-point Gauss-Legendre on 32 panels: exact for our smooth pieces to
    // far below the tolerances used downstream.
    static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                0.5384693101056831, 0.9061798459386640};
    static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                0.4786286704993665, 0.2369268850561891};
    const int    panels      = 32;
    const double h           = (t1 - t0) / panels;
    double       s           = 0.0;
    for (int k = 0; k < panels; ++k)
      {
        const double c = t0 + (k + 0.5) * h;
        for (int i = 0; i < 5; ++i)
          s += w[i] * d1(c + 0.5 * h * x[i]).norm();
      }
    return std::abs(0.5 * h * s);
  }

  // ---------------------------------------------------------------- LineSegment
  LineSegment::LineSegment(const Vec2 &a, const Vec2 &b)
    : a_(a)
    , b_(b)
  {}
  Vec2 LineSegment::point(double t) const { return a_ + t * (b_ - a_); }
  Vec2 LineSegment::d1(double) const { return b_ - a_; }
  Vec2 LineSegment::d2(double) const { return Vec2::Zero(); }
  Vec2 LineSegment::d3(double) const { return Vec2::Zero(); }

  // ---------------------------------------------------------------- CircularArc
  CircularArc::CircularArc(const Vec2 &centre, double radius, double t0, double t1)
    : c_(centre)
    , r_(radius)
    , t0_(t0)
    , t1_(t1)
  {}
  Vec2 CircularArc::point(double t) const { return c_ + r_ * Vec2(std::cos(t), std::sin(t)); }
  Vec2 CircularArc::d1(double t) const { return r_ * Vec2(-std::sin(t), std::cos(t)); }
  Vec2 CircularArc::d2(double t) const { return -r_ * Vec2(std::cos(t), std::sin(t)); }
  Vec2 CircularArc::d3(double t) const { return r_ * Vec2(std::sin(t), -std::cos(t)); }

  // ---------------------------------------------------------------- BSplineCurve
  namespace
  {
    /// de Boor evaluation of a B-spline of degree p with the given knots.
    Vec2 de_boor(const std::vector<Vec2> &cp, const std::vector<double> &U, int p, double t)
    {
      const int n = static_cast<int>(cp.size());
      if (p < 0)
        return Vec2::Zero();
      if (p == 0 && n == 0)
        return Vec2::Zero();
      // Knot span k with U[k] <= t < U[k+1], k in [p, n-1].
      int k = p;
      while (k < n - 1 && t >= U[k + 1])
        ++k;
      std::vector<Vec2> d(p + 1);
      for (int j = 0; j <= p; ++j)
        d[j] = cp[j + k - p];
      for (int r = 1; r <= p; ++r)
        for (int j = p; j >= r; --j)
          {
            const double den   = U[j + 1 + k - r] - U[j + k - p];
            const double alpha = den > 0.0 ? (t - U[j + k - p]) / den : 0.0;
            d[j]               = (1.0 - alpha) * d[j - 1] + alpha * d[j];
          }
      return d[p];
    }
  } // namespace

  BSplineCurve::BSplineCurve(std::vector<Vec2> control_points, unsigned int degree)
    : cp_(std::move(control_points))
    , p_(degree)
  {
    const int n = static_cast<int>(cp_.size()), p = static_cast<int>(p_);
    if (p < 1)
      throw InputError("Rack/Spline degree", std::to_string(p), ">= 1");
    if (n < p + 1)
      throw InputError("Rack/Control points", std::to_string(n) + " points",
                       ">= degree + 1 = " + std::to_string(p + 1) + " points");
    // Clamped uniform knot vector on [0, 1].
    knots_.assign(p + 1, 0.0);
    const int inner = n - p - 1;
    for (int i = 1; i <= inner; ++i)
      knots_.push_back(static_cast<double>(i) / (inner + 1));
    knots_.insert(knots_.end(), p + 1, 1.0);
  }

  Vec2 BSplineCurve::derivative(double t, unsigned int order) const
  {
    t = std::min(1.0, std::max(0.0, t));
    std::vector<Vec2>   cp = cp_;
    std::vector<double> U  = knots_;
    int                 p  = static_cast<int>(p_);
    for (unsigned int o = 0; o < order; ++o)
      {
        if (p == 0)
          return Vec2::Zero();
        // Derivative control points Q_i = p (P_{i+1} - P_i) / (U_{i+p+1} - U_{i+1}).
        std::vector<Vec2> q(cp.size() - 1);
        for (std::size_t i = 0; i + 1 < cp.size(); ++i)
          {
            const double den = U[i + p + 1] - U[i + 1];
            q[i]             = den > 0.0 ? Vec2(p * (cp[i + 1] - cp[i]) / den) : Vec2::Zero();
          }
        cp = q;
        U  = std::vector<double>(U.begin() + 1, U.end() - 1);
        --p;
      }
    return de_boor(cp, U, p, t);
  }

  Vec2 BSplineCurve::point(double t) const { return derivative(t, 0); }
  Vec2 BSplineCurve::d1(double t) const { return derivative(t, 1); }
  Vec2 BSplineCurve::d2(double t) const { return derivative(t, 2); }
  Vec2 BSplineCurve::d3(double t) const { return derivative(t, 3); }

  // ---------------------------------------------------------------- AffineCurve
  AffineCurve::AffineCurve(CurvePtr base, const Eigen::Matrix2d &M, const Vec2 &b, bool reverse)
    : base_(std::move(base))
    , M_(M)
    , b_(b)
    , sigma_(reverse ? -1.0 : 1.0)
  {}
  double AffineCurve::t_begin() const
  {
    return sigma_ > 0 ? base_->t_begin() : -base_->t_end();
  }
  double AffineCurve::t_end() const { return sigma_ > 0 ? base_->t_end() : -base_->t_begin(); }
  Vec2   AffineCurve::point(double t) const { return M_ * base_->point(sigma_ * t) + b_; }
  Vec2   AffineCurve::d1(double t) const { return sigma_ * (M_ * base_->d1(sigma_ * t)); }
  Vec2   AffineCurve::d2(double t) const { return M_ * base_->d2(sigma_ * t); }
  Vec2   AffineCurve::d3(double t) const { return sigma_ * (M_ * base_->d3(sigma_ * t)); }
  void   AffineCurve::evaluate(double t, Vec2 &p, Vec2 &p1, Vec2 &p2) const
  {
    Vec2 q, q1, q2;
    base_->evaluate(sigma_ * t, q, q1, q2);
    p = M_ * q + b_, p1 = sigma_ * (M_ * q1), p2 = M_ * q2;
  }

  // ---------------------------------------------------------------- TrimmedCurve
  TrimmedCurve::TrimmedCurve(CurvePtr base, double a, double b)
    : base_(std::move(base))
    , a_(a)
    , b_(b)
  {
    if (!(a_ < b_ && a_ >= base_->t_begin() && b_ <= base_->t_end()))
      throw std::logic_error("TrimmedCurve: [a, b] must be a non-empty part of the base range");
  }

  CurvePtr mirrored(CurvePtr c)
  {
    Eigen::Matrix2d M;
    M << -1, 0, 0, 1;
    return std::make_shared<AffineCurve>(std::move(c), M, Vec2::Zero(), false);
  }

  CurvePtr reversed(CurvePtr c)
  {
    return std::make_shared<AffineCurve>(std::move(c), Eigen::Matrix2d::Identity(), Vec2::Zero(),
                                         true);
  }
} // namespace gearfem::geometry
