#pragma once
// Gkimisis 2019 semi-analytical pair stiffness (eqs. 3.18-3.34) and its
// Ricker-wavelet load sharing (eqs. 3.36-3.46), built on the same teeth as the full
// Weber/Cornell model so that its error can be reported (the thesis claims <= 15 % at
// the ends of AB). SI units.
#include "analytical/tooth.h"
#include "base/units.h"

namespace gearfem::analytical
{
  class RickerSemiAnalytical
  {
  public:
    /// @param k_mean mean mesh stiffness [N/m] that linearises the Hertz term,
    /// F = k_mean x (eq. 3.30); @param c_x widening of the double-contact zone with the
    /// compression [rad/m] (thesis: about 2 deg/mm).
    RickerSemiAnalytical(InvoluteTooth pinion, InvoluteTooth gear, const Material &m1,
                          const Material &m2, double face_width, const PairLine &line,
                          double k_mean, const PairModelOptions &options = {},
                          double c_x = 2.0 * units::pi / 180.0 / 1e-3);

    /// Exponential thickness fit t = K1 exp(-K2 psi) of tooth i (0 pinion, 1 gear):
    /// K1 = t(0) (common root thickness), K2 by least squares on ln t (eq. 2.58).
    double K1(int i) const { return K1_[i]; }
    double K2(int i) const { return K2_[i]; }

    /// Pair stiffness K_tot,s at contact position g [m] and compression x [m] (eq. 3.33
    /// with the monomial integrals 3.22-3.23 in eq. 3.24, the exact O'Donnell term and the
    /// Hertz term 3.31 frozen at the pitch point with F = k_mean x) [N/m].
    double pair_stiffness(double g, double x) const;

    /// Ricker weight W(phi1, x) (eq. 3.37, f_m eq. 3.42, f_c = 2 f_m) and the total
    /// normal force F = [K(phi1) + (1 - W) K(phi1 - sgn(phi1) 2 pi/z1)] x (eq. 3.36) for
    /// pinion roll angle phi1 (0 at the pitch point) [N].
    double ricker_weight(double phi1, double x) const;
    double load(double phi1, double x) const;

  private:
    double tooth_compliance(int i, double g) const;
    InvoluteTooth t_[2];
    PlaneElastic e_[2];
    double b_, k_mean_, c_x_;
    PairLine line_;
    PairModelOptions opt_;
    double K1_[2], K2_[2];
    double h_C_[2]; ///< Weber depths at the pitch point
  };
} // namespace gearfem::analytical
