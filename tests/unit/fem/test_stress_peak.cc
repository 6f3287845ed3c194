// fem::fitted_peak, the root stress of a fillet from its boundary samples. References are
// closed forms:
// - a polynomial peak of degree 4 or less sampled without error is reproduced exactly;
// - a Gaussian peak (width 2 and 3 faces) with the raw finite-element stress's jump at each
//   vertex (a sawtooth of +-1.5 % of the peak, antisymmetric in each face: high at one end,
//   low at the other) is recovered within 0.3 %, where the largest sample is up to 1.3 % high;
// - a peak at the end of the boundary (a monotone stress) falls back to the largest sample.
#include "fem/stress_peak.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using gearfem::fem::fitted_peak;

namespace
{
  constexpr std::size_t per_face = 8;

  /// 12 faces of unit length, `per_face` samples at the middles of equal parts.
  void sample(double (*f)(double, double, double), double x0, double width, double jump, std::vector<double> &arc,
              std::vector<double> &s)
  {
    arc.clear(), s.clear();
    for (int face = 0; face < 12; ++face)
      for (std::size_t k = 0; k < per_face; ++k)
        {
          const double xi = (k + 0.5) / per_face;
          arc.push_back(face + xi);
          s.push_back(f(face + xi, x0, width) + jump * (2 * xi - 1));
        }
  }

  double gaussian(double x, double x0, double width) { return 100 * std::exp(-std::pow((x - x0) / width, 2)); }
  double quartic(double x, double x0, double) { return 100 - 2 * std::pow(x - x0, 2) - 0.05 * std::pow(x - x0, 4); }
  double falling(double x, double, double) { return 100 - 3 * x; }
} // namespace

TEST(FittedPeak, ReproducesAPolynomialPeak)
{
  std::vector<double> arc, s;
  for (const double x0 : {4.9, 5.3, 6.45})
    {
      sample(quartic, x0, 0, 0, arc, s);
      const auto p = fitted_peak(arc, s, per_face);
      EXPECT_TRUE(p.fitted);
      // The grid of the fit's maximum (400 steps over 3 faces) leaves at most 2 (3/400)^2 / 4.
      EXPECT_NEAR(p.value, 100, 3e-5) << x0;
      EXPECT_NEAR(arc[p.index], x0, 1.0 / per_face) << x0;
    }
}

TEST(FittedPeak, AveragesTheJumpsBetweenElements)
{
  std::vector<double> arc, s;
  double worst_raw = 0;
  for (const double width : {2.0, 3.0})
    for (const double x0 : {5.0, 5.3, 5.5, 5.77})
      {
        sample(gaussian, x0, width, 1.5, arc, s);
        const auto p = fitted_peak(arc, s, per_face);
        double raw   = -1e300;
        for (const double v : s)
          raw = std::max(raw, v);
        worst_raw = std::max(worst_raw, raw - 100);
        EXPECT_TRUE(p.fitted);
        EXPECT_NEAR(p.value, 100, 0.3) << "width " << width << ", peak at " << x0;
      }
  EXPECT_GT(worst_raw, 1.2); // what the largest sample alone would report
}

TEST(FittedPeak, FallsBackToTheLargestSampleAtAnEnd)
{
  std::vector<double> arc, s;
  sample(falling, 0, 0, 0, arc, s);
  const auto p = fitted_peak(arc, s, per_face);
  EXPECT_FALSE(p.fitted);
  EXPECT_EQ(p.index, 0u);
  EXPECT_DOUBLE_EQ(p.value, s[0]);
  // No samples: no peak, and no crash.
  EXPECT_FALSE(fitted_peak({}, {}, per_face).fitted);
}
