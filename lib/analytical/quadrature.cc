#include "analytical/quadrature.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>

namespace gearfem::analytical
{
  namespace
  {
    // Kronrod 15-point nodes and weights with the embedded Gauss 7-point weights.
    constexpr double xk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                              0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
    constexpr double wk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                              0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                              0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                              0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
    constexpr double wg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                              0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

    void gk15(const std::function<double(double)> &f, double a, double b, double &k, double &err)
    {
      const double c = 0.5 * (a + b), h = 0.5 * (b - a);
      const double fc = f(c);
      double sk = wk[7] * fc, sg = wg[3] * fc;
      for (int j = 0; j < 7; ++j)
        {
          const double f1 = f(c - h * xk[j]), f2 = f(c + h * xk[j]);
          sk += wk[j] * (f1 + f2);
          if (j % 2 == 1)
            sg += wg[j / 2] * (f1 + f2);
        }
      k = sk * h;
      err = std::abs((sk - sg) * h);
      if (!std::isfinite(k))
        throw SolverError("integrate: non-finite integrand on [" + to_string_g(a) + ", " +
                          to_string_g(b) + "]");
    }

    double adapt(const std::function<double(double)> &f, double a, double b, double tol,
                 int depth)
    {
      double k, err;
      gk15(f, a, b, k, err);
      if (err <= tol || depth > 40 || std::abs(b - a) < 1e-15 * (std::abs(a) + std::abs(b)))
        return k;
      const double c = 0.5 * (a + b);
      return adapt(f, a, c, 0.5 * tol, depth + 1) + adapt(f, c, b, 0.5 * tol, depth + 1);
    }
  } // namespace

  double integrate(const std::function<double(double)> &f, double a, double b, double rel_tol,
                   double abs_tol, const std::vector<double> &breakpoints)
  {
    if (a == b)
      return 0.0;
    const double sign = b > a ? 1.0 : -1.0;
    const double lo = std::min(a, b), hi = std::max(a, b);
    std::vector<double> pts{lo};
    for (double p : breakpoints)
      if (p > lo && p < hi)
        pts.push_back(p);
    pts.push_back(hi);
    std::sort(pts.begin(), pts.end());
    // A first coarse estimate sets the absolute tolerance from the relative one.
    double coarse = 0.0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
      {
        double k, e;
        gk15(f, pts[i], pts[i + 1], k, e);
        coarse += std::abs(k);
      }
    const double tol = std::max(abs_tol, rel_tol * coarse);
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
      sum += adapt(f, pts[i], pts[i + 1], tol * (pts[i + 1] - pts[i]) / (hi - lo), 0);
    return sign * sum;
  }
} // namespace gearfem::analytical
