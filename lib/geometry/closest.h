#pragma once
// The one closest-point search on an exact curve, shared by geometry::Curve (the profiles and
// the pair kinematics) and mesh::ParametricCurve (the contact search on the meshed boundary):
// a sampled start, then safeguarded Newton on f(t) = (p(t) - q) . p'(t) = 0 in the bracket of
// the best sample. `eval(t, p, p1, p2)` gives the point and its first two derivatives. No
// deal.II.
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace gearfem::geometry
{
  using ClosestVec2 = Eigen::Vector2d;

  /// Safeguarded Newton on f(t) = (p(t) - q) . p'(t) = 0 from t in the bracket [a, b] of
  /// [lo, hi]. `x` and `x1` return the point and the tangent at the result; `newton` whether
  /// the last step was a Newton step that met the tolerance (false after a bisection: the
  /// bracket was not verified and the iteration may have run into one of its ends).
  template <class Eval>
  double newton_closest(const Eval &eval, const ClosestVec2 &q, double lo, double hi, double t, double a, double b,
                        ClosestVec2 &x, ClosestVec2 &x1, bool &newton)
  {
    ClosestVec2 p2;
    newton = false;
    for (int it = 0; it < 50; ++it)
      {
        eval(t, x, x1, p2);
        const ClosestVec2 r = x - q;
        const double f = r.dot(x1), df = x1.squaredNorm() + r.dot(p2);
        // Keep a bracket [a, b] for safeguarding (f is increasing through the minimum).
        if (f > 0)
          b = t;
        else
          a = t;
        double tn = (df > 0) ? t - f / df : 0.5 * (a + b);
        bool step = df > 0;
        if (!(tn > a && tn < b))
          tn = 0.5 * (a + b), step = false;
        if (std::abs(tn - t) <= 1e-15 * (1.0 + std::abs(t)) + 1e-16 * (hi - lo))
          {
            // The last step is below round-off of t: first order carries x and x1 to it.
            x += (tn - t) * x1, x1 += (tn - t) * p2;
            t      = tn;
            newton = step;
            break;
          }
        t = tn;
      }
    const double tc = std::clamp(t, lo, hi);
    if (tc != t)
      eval(tc, x, x1, p2);
    return tc;
  }

  /// The parameter in [lo, hi] (lo <= hi) of the point closest to q: the best of the samples
  /// (sample(i) is the point at lo + (hi - lo) i / n, i = 0..n), then newton_closest in the
  /// bracket of one sample interval around it.
  template <class Eval, class Sample>
  double closest_parameter(const Eval &eval, const Sample &sample, const ClosestVec2 &q, double lo, double hi, int n)
  {
    double best = lo, best_d = 1e300;
    for (int i = 0; i <= n; ++i)
      {
        const double d = (sample(i) - q).squaredNorm();
        if (d < best_d)
          best_d = d, best = lo + (hi - lo) * i / n;
      }
    const double dt = (hi - lo) / n;
    ClosestVec2 x, x1;
    bool newton = false;
    return newton_closest(eval, q, lo, hi, best, std::max(lo, best - dt), std::min(hi, best + dt), x, x1, newton);
  }
} // namespace gearfem::geometry
