#pragma once
// One root-finding utility for the whole code. Pure C++ and header-only Boost.Math
// (no deal.II), so the light layer (geometry, analytical, dynamics) uses it too.
//
// Three bracketed solvers, one contract:
//   find_root            TOMS 748 (Alefeld, Potra, Shi 1995) via boost::math::tools::toms748_solve,
//                        for smooth scalar equations where a few evaluations matter;
//   find_root_newton     Newton with the derivative, safeguarded by the bracket (a step that
//                        leaves the bracket or does not halve it becomes a bisection step);
//   find_root_bisection  plain bisection down to adjacent doubles. Slow but bit-reproducible and
//                        insensitive to the shape of f; used where the root places mesh vertices
//                        or segment ends (a change in the last bit moves the gmsh mesh).
// The bracket [lo, hi] must make f change sign (a zero at an end point is accepted and returned).
// Every solver returns a converged root or throws SolverError naming the equation (`what`), the
// bracket and the iteration count: it never returns an unconverged value.
#include "base/errors.h"

#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

namespace gearfem::base
{
  namespace detail
  {
    /// SolverError for an interval on which f does not change sign.
    [[noreturn]] void throw_not_bracketed(const std::string &what, double lo, double hi, double f_lo,
                                          double f_hi);
    /// SolverError for a solver that used up max_iter (or met a non-finite value of f).
    [[noreturn]] void throw_not_converged(const std::string &what, const char *method, double lo,
                                          double hi, long iterations, const std::string &reason);

    /// (lo, hi, f(lo), f(hi)) checked: finite and of opposite signs (or a zero at an end).
    inline void check_bracket(const std::string &what, double lo, double hi, double f_lo, double f_hi)
    {
      if (!std::isfinite(lo) || !std::isfinite(hi) || !std::isfinite(f_lo) || !std::isfinite(f_hi) ||
          (f_lo != 0.0 && f_hi != 0.0 && (f_lo < 0) == (f_hi < 0)))
        throw_not_bracketed(what, lo, hi, f_lo, f_hi);
    }
  } // namespace detail

  /// Root of f in the bracket [lo, hi] (either order) by TOMS 748. Converged when the bracket
  /// is no wider than tol * max(|lo|, |hi|) or has shrunk to adjacent doubles, or f is exactly
  /// zero. Throws SolverError if f does not change sign on [lo, hi], is not finite, or the
  /// bracket is still wider after max_iter evaluations.
  /// @param what        the equation in words, e.g. "AGMA 908 inv^-1" (for the error message)
  /// @param iterations  if given, receives the number of TOMS 748 iterations used
  template <typename F>
  double find_root(F &&f, double lo, double hi, double tol, int max_iter, const std::string &what,
                   int *iterations = nullptr)
  {
    if (iterations)
      *iterations = 0;
    if (lo > hi)
      std::swap(lo, hi);
    const double f_lo = f(lo), f_hi = f(hi);
    detail::check_bracket(what, lo, hi, f_lo, f_hi);
    if (f_lo == 0.0)
      return lo;
    if (f_hi == 0.0)
      return hi;
    auto converged = [tol](double a, double b) {
      return std::abs(b - a) <= tol * std::max(std::abs(a), std::abs(b)) ||
             std::nextafter(a, b) == b;
    };
    bool finite = true;
    auto g      = [&](double x) {
      const double v = f(x);
      if (!std::isfinite(v))
        finite = false;
      return finite ? v : 0.0; // a non-finite value stops the solver; reported below
    };
    std::uintmax_t n = static_cast<std::uintmax_t>(std::max(1, max_iter));
    std::pair<double, double> r;
    try
      {
        r = boost::math::tools::toms748_solve(g, lo, hi, f_lo, f_hi, converged, n);
      }
    catch (const std::exception &e)
      {
        detail::throw_not_converged(what, "TOMS 748", lo, hi, static_cast<long>(n), e.what());
      }
    if (iterations)
      *iterations = static_cast<int>(n);
    if (!finite)
      detail::throw_not_converged(what, "TOMS 748", r.first, r.second, static_cast<long>(n),
                                  "the function is not finite inside the bracket");
    if (r.first == r.second) // f is exactly zero there
      return r.first;
    if (!converged(r.first, r.second))
      detail::throw_not_converged(what, "TOMS 748", r.first, r.second, static_cast<long>(n),
                                  "iteration limit " + std::to_string(max_iter) + " reached");
    // The end with the smaller residual.
    return std::abs(f(r.first)) <= std::abs(f(r.second)) ? r.first : r.second;
  }

  /// Root of f in [lo, hi] by Newton from `guess` (clamped into the bracket), safeguarded as
  /// in rtsafe (Numerical Recipes 9.4): the bracket is updated with the sign of f at every
  /// iterate, and a Newton step that leaves the bracket, or is more than half the step before
  /// it, is replaced by bisection. fdf(x) returns {f(x), f'(x)}. Converged when a Newton step
  /// is no larger than tol * |x| (the stepped-to point is returned), when f is exactly zero,
  /// or when the bracket has shrunk to adjacent doubles. Throws SolverError like find_root.
  template <typename FdF>
  double find_root_newton(FdF &&fdf, double lo, double hi, double guess, double tol, int max_iter,
                          const std::string &what)
  {
    if (lo > hi)
      std::swap(lo, hi);
    const double f_lo = fdf(lo).first, f_hi = fdf(hi).first;
    detail::check_bracket(what, lo, hi, f_lo, f_hi);
    if (f_lo == 0.0)
      return lo;
    if (f_hi == 0.0)
      return hi;
    const bool rising  = f_lo < 0; // f < 0 at the lo end
    double     x       = std::isfinite(guess) ? std::clamp(guess, lo, hi) : 0.5 * (lo + hi);
    double     dx_prev = hi - lo;
    for (int it = 1; it <= max_iter; ++it)
      {
        const auto [fx, dfx] = fdf(x);
        if (!std::isfinite(fx))
          detail::throw_not_converged(what, "Newton", lo, hi, it, "f is not finite at " + to_string_g(x));
        if (fx == 0.0)
          return x;
        ((fx < 0) == rising ? lo : hi) = x;
        if (!(std::nextafter(lo, hi) < hi))
          return x;
        const double dx = fx / dfx, x_new = x - dx;
        const bool   inside = std::isfinite(x_new) && x_new > lo && x_new < hi;
        if (inside && std::abs(dx) <= tol * std::abs(x_new))
          return x_new;
        if (inside && std::abs(dx) <= 0.5 * std::abs(dx_prev))
          dx_prev = dx, x = x_new;
        else
          dx_prev = x - 0.5 * (lo + hi), x = 0.5 * (lo + hi);
      }
    detail::throw_not_converged(what, "Newton", lo, hi, max_iter,
                                "iteration limit " + std::to_string(max_iter) + " reached");
  }

  /// Bisection of [lo, hi] without the bracket check (the loop of find_root_bisection):
  /// `lo_negative` says on which end f < 0. For callers that established the bracket
  /// themselves from samples.
  template <typename F>
  double bisect_bracket(F &&f, double lo, double hi, bool lo_negative, const std::string &what,
                        double x_tol = 0.0, int max_iter = 2200)
  {
    for (int it = 0; it < max_iter; ++it)
      {
        const double m = 0.5 * (lo + hi);
        if (m == lo || m == hi)
          return m;
        const double fm = f(m);
        if (std::isnan(fm))
          detail::throw_not_converged(what, "bisection", lo, hi, it, "f is NaN at " + to_string_g(m));
        ((fm < 0) == lo_negative ? lo : hi) = m;
        if (std::abs(hi - lo) <= x_tol * std::max(1.0, std::abs(m)))
          return 0.5 * (lo + hi);
      }
    detail::throw_not_converged(what, "bisection", lo, hi, max_iter,
                                "iteration limit " + std::to_string(max_iter) + " reached");
  }
  /// Root of f in [lo, hi] by bisection until the bracket is adjacent doubles, or (x_tol > 0)
  /// until a halving leaves it no wider than x_tol max(1, |mid|); returns the midpoint of the
  /// final bracket (for adjacent doubles, one of them). An end where f is exactly zero is
  /// returned as it is. The end replaced by mid is the one where f has the sign of f(mid)
  /// (f(mid) = 0 counts as positive). Deterministic to the last bit; every finite bracket
  /// collapses within 2200 halvings. Throws SolverError if f does not change sign, f(mid) is
  /// NaN, or max_iter halvings do not suffice.
  template <typename F>
  double find_root_bisection(F &&f, double lo, double hi, const std::string &what,
                             double x_tol = 0.0, int max_iter = 2200)
  {
    const double f_lo = f(lo), f_hi = f(hi);
    detail::check_bracket(what, std::min(lo, hi), std::max(lo, hi), f_lo, f_hi);
    if (f_lo == 0.0)
      return lo;
    if (f_hi == 0.0)
      return hi;
    return bisect_bracket(f, lo, hi, f_lo < 0, what, x_tol, max_iter);
  }

} // namespace gearfem::base
