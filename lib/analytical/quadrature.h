#pragma once
// Adaptive Gauss-Kronrod (7/15) quadrature for the thickness integrals of the tooth
// compliance models. Pure C++.
#include <functional>
#include <vector>

namespace gearfem::analytical
{
  /// Integral of f over [a, b] by recursive G7-K15 bisection until the Kronrod-Gauss
  /// difference is below max(abs_tol, rel_tol |I|) on every piece (Piessens et al. 1983,
  /// QUADPACK). `breakpoints` (inside (a, b)) split the interval first, e.g. at the
  /// fillet/involute junction where t(y) has a kink. Throws SolverError if the
  /// integrand returns a non-finite value.
  double integrate(const std::function<double(double)> &f, double a, double b,
                   double rel_tol = 1e-10, double abs_tol = 0.0,
                   const std::vector<double> &breakpoints = {});
} // namespace gearfem::analytical
