// base/roots.h: the one root-finding utility. Converged roots of closed-form
// equations; intervals that do not bracket and iteration limits end in SolverError naming
// the equation, the bracket and the iteration count, never in an unconverged value.
#include "base/errors.h"
#include "base/units.h"
#include "base/roots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

using namespace gearfem;

namespace
{
  /// The message of the SolverError thrown by f, or "" if none.
  template <typename F>
  std::string solver_error_of(F f)
  {
    try
      {
        f();
      }
    catch (const SolverError &e)
      {
        return e.what();
      }
    return "";
  }

  /// inv(a) = tan a - a, the involute function; inv(20 deg) = 0.014904383867336.
  double inv(double a) { return std::tan(a) - a; }
  constexpr double deg = gearfem::units::pi / 180.0;
} // namespace

TEST(Roots, Toms748FindsClosedFormRoots)
{
  // cos x = x (the Dottie number) and x^3 = 2, in either bracket order.
  const double dottie = 0.73908513321516064166;
  EXPECT_NEAR(base::find_root([](double x) { return std::cos(x) - x; }, 0.0, 1.0, 1e-15, 100, "cos x = x"),
              dottie, 2e-16);
  EXPECT_NEAR(base::find_root([](double x) { return x * x * x - 2; }, 2.0, 0.0, 1e-15, 100, "x^3 = 2"),
              std::cbrt(2.0), 4e-16);
  // The inverse involute function at 20 deg, as the geometry needs it.
  const double v = inv(20 * deg);
  EXPECT_NEAR(base::find_root([v](double a) { return inv(a) - v; }, 1e-3, 1.2, 1e-15, 100, "inv a = v"),
              20 * deg, 1e-15);
  // A zero at an end of the bracket is returned as it is.
  EXPECT_EQ(base::find_root([](double x) { return x - 1.0; }, 1.0, 3.0, 1e-15, 100, "x = 1"), 1.0);
}

TEST(Roots, NewtonFindsClosedFormRoots)
{
  // sqrt(2) from a poor guess; the step that leaves the bracket is replaced by bisection.
  auto fdf = [](double x) { return std::make_pair(x * x - 2.0, 2.0 * x); };
  EXPECT_NEAR(base::find_root_newton(fdf, 0.0, 4.0, 1e-6, 1e-15, 100, "x^2 = 2"), std::sqrt(2.0), 4e-16);
  // ISO 6336-3 theta equation 2G/zn tan th - H - th = 0 for G = -0.15, zn = 25, H = -0.9.
  const double G = -0.15, zn = 25, H = -0.9;
  auto theta = [&](double th) {
    return std::make_pair(2 * G / zn * std::tan(th) - H - th,
                          2 * G / zn / (std::cos(th) * std::cos(th)) - 1.0);
  };
  const double th = base::find_root_newton(theta, 0.0, 1.5, gearfem::units::pi / 6, 1e-15, 100, "theta");
  EXPECT_NEAR(2 * G / zn * std::tan(th) - H - th, 0.0, 1e-15);
}

TEST(Roots, BisectionCollapsesTheBracketToTheLastBit)
{
  // The root of x^2 - 2 to the last bit: the result and its neighbour bracket sqrt 2.
  auto f = [](double x) { return x * x - 2.0; };
  const double r = base::find_root_bisection(f, 1.0, 2.0, "x^2 = 2");
  EXPECT_NEAR(r, std::sqrt(2.0), 2.3e-16);
  EXPECT_TRUE((f(r) < 0) != (f(std::nextafter(r, 2.0)) < 0) || (f(r) < 0) != (f(std::nextafter(r, 1.0)) < 0));
  // Same answer with the bracket given in decreasing order (f > 0 at the first end).
  EXPECT_EQ(base::find_root_bisection(f, 2.0, 1.0, "x^2 = 2"), r);
  // With an x tolerance, the midpoint of the first bracket no wider than it.
  EXPECT_NEAR(base::find_root_bisection(f, 1.0, 2.0, "x^2 = 2", 1e-6), std::sqrt(2.0), 1e-6);
}

TEST(Roots, IntervalThatDoesNotBracketIsAnError)
{
  auto f = [](double x) { return x * x + 1.0; }; // no real root
  for (const auto &msg : {solver_error_of([&] { base::find_root(f, -1.0, 2.0, 1e-15, 100, "x^2 + 1 = 0"); }),
                          solver_error_of([&] { base::find_root_bisection(f, -1.0, 2.0, "x^2 + 1 = 0"); }),
                          solver_error_of([&] {
                            base::find_root_newton([&](double x) { return std::make_pair(f(x), 2 * x); },
                                                   -1.0, 2.0, 0.5, 1e-15, 100, "x^2 + 1 = 0");
                          })})
    {
      EXPECT_NE(msg.find("x^2 + 1 = 0"), std::string::npos) << msg; // names the equation
      EXPECT_NE(msg.find("does not bracket"), std::string::npos) << msg;
      EXPECT_NE(msg.find("[-1, 2]"), std::string::npos) << msg; // and the interval
    }
  // A NaN at an end is not a bracket either.
  EXPECT_NE(solver_error_of([] {
              base::find_root([](double x) { return x > 1 ? std::nan("") : x; }, -1.0, 2.0, 1e-15, 100, "nan end");
            }).find("does not bracket"),
            std::string::npos);
}

TEST(Roots, NonConvergenceIsAnErrorNotAValue)
{
  // A step function: the sign changes at 1/3 but no solver can make f small; with a few
  // iterations and a tight tolerance each solver must give up with an error that says so.
  auto step = [](double x) { return x < 1.0 / 3.0 ? -1.0 : 1.0; };
  const std::string t = solver_error_of([&] { base::find_root(step, 0.0, 1.0, 1e-15, 5, "step equation"); });
  EXPECT_NE(t.find("step equation"), std::string::npos) << t;
  EXPECT_NE(t.find("did not converge after"), std::string::npos) << t;
  EXPECT_NE(t.find("bracket ["), std::string::npos) << t;
  const std::string b =
    solver_error_of([&] { base::find_root_bisection(step, 0.0, 1.0, "step equation", 0.0, 10); });
  EXPECT_NE(b.find("did not converge after 10 iterations"), std::string::npos) << b;
  const std::string n = solver_error_of([&] {
    base::find_root_newton([&](double x) { return std::make_pair(step(x), 0.0); }, 0.0, 1.0, 0.5, 1e-15, 8,
                           "step equation");
  });
  EXPECT_NE(n.find("did not converge after 8 iterations"), std::string::npos) << n;
  // Given enough iterations the bisection does find the jump to the last bit.
  const double r = base::find_root_bisection(step, 0.0, 1.0, "step equation");
  EXPECT_LT(r, 1.0 / 3.0 + 1e-16);
  EXPECT_GT(r, 1.0 / 3.0 - 1e-16);
}
