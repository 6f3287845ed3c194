#pragma once
// Equivalent curvature along the path of contact of a conjugate pair, from the pinion flank
// alone (Koronaios 2021, ch. 3; Euler-Savary). SI units (m, 1/m, rad).
//
// Frame: the pinion (gear 1) body frame of lib/geometry: centre at the origin, tooth 0 axis
// +y, the flank on the x > 0 (coast) side; the pitch point is C = (0, r01) and the gear
// centre O2 = (0, r01 + r02). A flank point G with tangent G' is in contact when the
// pinion is turned by -theta so that its normal passes through C (the involutisation
// condition, Spitas, Costopoulos & Spitas 2002): sin(beta - theta) = G.G'/(r01 |G'|), beta
// the direction of G'; of its two roots the one that turns the outward normal towards gear 2. The rack displacement is
// K = r01 theta and the rack point is Q - (K, r01) (docs/geometry.md).
//
// The gear-2 curvature at the same contact follows from the Euler-Savary equation for the
// two pitch circles: with e the unit common normal (e.y > 0, pointing out of the pinion)
// and signed positions along it from C, a (pinion centre of curvature), a' (gear-2 centre
// of curvature), 1/a' = 1/a + (1/r01 + 1/r02)/e.y. The equivalent (relative) curvature is
// 1/R = kappa1 + kappa2 (each convex > 0), i.e. the thesis' 1/R1 - 1/R2 with signed
// curvatures (eq. 3.11). For an involute pair this is 1/rho1 + 1/rho2 exactly.
// No deal.II: this is the light layer.
#include "geometry/curve.h"

#include <string>
#include <vector>

namespace gearfem::optimise
{
  using geometry::Vec2;

  /// Everything known about the contact of one flank point.
  struct ContactSample
  {
    double t = 0;          ///< flank curve parameter
    double r1 = 0;         ///< pinion radius of the point [m]
    double theta = 0;      ///< pinion turn -theta that brings it into contact [rad]
    double K = 0;          ///< rack displacement r01 theta [m]
    double rack_u = 0;     ///< rack abscissa of the generating rack point [m]
    double rack_v = 0;     ///< rack ordinate (away from the pinion centre) [m]
    Vec2 contact;          ///< contact point in the fixed frame (pinion centre at the origin) [m]
    double r2 = 0;         ///< distance of the contact point from the gear-2 centre [m]
    double kappa1 = 0;     ///< pinion curvature, convex > 0 [1/m]
    double kappa2 = 0;     ///< gear-2 curvature, convex > 0 [1/m]
    double kappa_eq = 0;   ///< 1/R = kappa1 + kappa2 [1/m]
    double normal_sine = 0; ///< e.y: sine of the angle between the normal and the pitch line
  };

  /// The pinion flank of a pair at the reference centre distance.
  class FlankKinematics
  {
  public:
    /// @param flank  pinion flank in the pinion body frame (x > 0 side), any direction
    /// @param r01, r02  pitch radii of pinion and gear [m]
    FlankKinematics(geometry::CurvePtr flank, double r01, double r02);
    /// Contact of flank parameter t. Throws SolverError naming the radius when the normal
    /// of the point cannot pass through C (|G.G'| >= r01 |G'|).
    ContactSample at(double t) const;
    /// Parameter where `value(at(t))` equals target, t between a and b (bracketing
    /// required; SolverError otherwise), by TOMS 748 to 1e-14 relative.
    template <typename F>
    double solve(F &&value, double target, double a, double b, const std::string &what) const;
    const geometry::Curve &flank() const { return *flank_; }
    double r01() const { return r01_; }
    double r02() const { return r02_; }

  private:
    geometry::CurvePtr flank_;
    double r01_, r02_;
    double outward_sign_ = 1; ///< +1: the right normal of the traversal is outward
  };

  /// Statistics of values sampled uniformly in some variable (the thesis' tables are point
  /// statistics over the flank): mean and standard deviation with trapezoidal weights, the
  /// limit of unweighted point statistics for many points (digest section 2); max over the points.
  struct Statistics
  {
    double mean_abs = 0; ///< mean |1/R| [1/m]
    double max_abs = 0;  ///< max |1/R| [1/m]
    double std = 0;      ///< population standard deviation of 1/R [1/m]
    double min = 0;      ///< smallest signed value [1/m]
  };
  Statistics statistics(const std::vector<double> &values);

  /// How the samples are spaced (fixed by two checks against Koronaios 2021).
  enum class Sampling
  {
    pinion_radius, ///< uniform in pinion radius (the involute rows of Table 6.1)
    rack_abscissa  ///< uniform in rack u (the sinusoid rows of Tables 5.2 and 6.1)
  };

  /// n samples (n >= 2, both ends included) between flank parameters ta and tb, uniform in
  /// the chosen quantity between its values at ta and tb, which must be strictly monotone in
  /// between (the caller checks it on a coarse grid first).
  std::vector<ContactSample> sample_flank(const FlankKinematics &k, double ta, double tb, int n,
                                          Sampling sampling);
} // namespace gearfem::optimise

#include "base/roots.h"

namespace gearfem::optimise
{
  template <typename F>
  double FlankKinematics::solve(F &&value, double target, double a, double b,
                                const std::string &what) const
  {
    auto f = [&](double t) { return value(at(t)) - target; };
    return base::find_root(f, a, b, 1e-14, 200, what);
  }
} // namespace gearfem::optimise
