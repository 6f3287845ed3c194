#pragma once
// Equivalent tooth mass and tooth inertia along the path of contact (the NTUA tooth-mass
// thesis, eqs. 3.1-3.6), and a periodic position-dependent inertia J(theta) for the
// equations of motion. SI units (m, kg, kg m^2, rad).
//
// A tooth loaded at height Y (along its axis, from the root circle) deflects along the line
// of action by delta0 = delta_f + delta_b (foundation + beam). The thesis' shape
// (eqs. 3.2-3.3, listing `equivalent_mass`):
//   delta(y) = delta_f + (y/Y) delta_b  for y < Y,   delta(y) = delta0  for y >= Y,
// i.e. delta(y)/delta0 = s + (1 - s) min(y/Y, 1) with the foundation share s = delta_f/delta0.
// Equivalent mass (eq. 3.1): m_eq = sum_i (delta(y_i)/delta0) dm_i, dm_i = rho b t(y_i) dy
// (eq. 3.4); kinetic-energy equivalence needs (delta/delta0)^2 instead. Tooth inertia
// (eq. 3.6): J_t(theta) = sum over the pairs in contact of m_eq r^2, r the radius of the
// contact point.
#include "analytical/compliance.h"
#include "analytical/elastic.h"

#include <memory>
#include <vector>

namespace gearfem::geometry
{
  class GearPair;
}

namespace gearfem::dynamics
{
  /// Weighting of the tooth mass by the deflection shape.
  enum class ToothMassWeighting
  {
    thesis_linear, ///< (delta/delta0), the NTUA tooth-mass thesis eq. 3.1
    kinetic_energy ///< (delta/delta0)^2, kinetic-energy equivalence
  };

  /// delta(y)/delta0 of the thesis' shape: s + (1 - s) min(y/Y, 1) [-].
  /// @param y height above the root circle [m]; @param y_load load height Y > 0 [m];
  /// @param foundation_share s = delta_f/delta0 in [0, 1].
  double deflection_shape(double y, double y_load, double foundation_share);

  /// Tooth mass rho b int_0^H t(y) dy [kg] (root circle to tip).
  double tooth_mass(const analytical::ToothBeam &tooth, double density, double face_width);

  /// Equivalent mass of one tooth loaded at height y_load [kg]:
  /// rho b int_0^H t(y) w(y) dy with w = shape (thesis) or shape^2 (kinetic energy).
  /// Throws InputError for y_load outside (0, H], a share outside [0, 1], density or face
  /// width <= 0.
  double equivalent_tooth_mass(const analytical::ToothBeam &tooth, double y_load,
                               double foundation_share, double density, double face_width,
                               ToothMassWeighting weighting);

  /// Equivalent masses and tooth inertias of a pair along its path of contact.
  struct ToothInertiaCurves
  {
    double theta_A = 0;     ///< roll angle of the start of contact A [rad] (0 at C)
    double period = 0;      ///< mesh period 2 pi/z1 [rad]
    double tooth_mass1 = 0, tooth_mass2 = 0; ///< whole-tooth masses [kg]
    /// Along the path (g from A to E): distance from T1 [m], contact radii [m], foundation
    /// shares [-], load heights [m] and equivalent masses [kg] of the pinion and gear tooth.
    std::vector<double> g, r1, r2, share1, share2, y1, y2, m1, m2;
    /// J_t(theta) over one mesh period from A: roll angles [rad] and tooth inertias of the
    /// pinion and gear [kg m^2] (sum over the pairs in contact).
    std::vector<double> theta, J1, J2;
    /// Means over one mesh period [kg m^2]: (1/p_b) int_A^E m_eq r^2 dg.
    double mean1 = 0, mean2 = 0;
  };

  /// The curves of a generated pair: the Weber/Cornell tooth parts (beam, O'Donnell
  /// foundation; lib/analytical, plane stress) give the foundation share at each contact,
  /// the generated tooth (fillet included) gives t(y). `path_points` positions from A to E
  /// (also the quadrature of the means, Simpson), `samples` roll angles over one period.
  ToothInertiaCurves tooth_inertia_curves(const geometry::GearPair &pair,
                                          const analytical::Material &material, double density,
                                          ToothMassWeighting weighting, int path_points = 401,
                                          int samples = 512);

  /// A periodic inertia J(theta) [kg m^2] of the mesh position theta [rad] (pinion roll
  /// angle): values at n equally spaced nodes from theta0 over one period, interpolated by a
  /// periodic monotone cubic Hermite (Fritsch & Carlson 1980), so J is C1 and its
  /// derivative is the exact derivative of the interpolant (a jump of the tooth count is
  /// spread over one node interval).
  class PeriodicInertia
  {
  public:
    PeriodicInertia(double theta0, double period, std::vector<double> values);
    double value(double theta) const;
    double derivative(double theta) const; ///< dJ/dtheta [kg m^2/rad]
    double mean() const;                   ///< mean over one period of the interpolant [kg m^2]
    double period() const { return period_; }

  private:
    double locate(double theta, std::size_t &i) const; ///< node index and local u in [0, 1)
    double theta0_, period_, h_;
    std::vector<double> v_, d_; ///< node values and slopes dJ/dtheta
  };
} // namespace gearfem::dynamics
