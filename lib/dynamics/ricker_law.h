#pragma once
// Semi-analytical mesh force with Ricker-wavelet load sharing (Gkimisis 2019,
// NTUA, ch. 3.4, eqs. 3.35-3.46), as a MeshForceLaw for the dynamics:
//
//   F(w1, x)  = [K(w1, x) + g(w1, x) K(f(w1), x)] x                            (3.36)
//   W(w1, x)  = (1 - 2 pi^2 f_m^2 (w1 - wbar)^2) exp(-pi^2 f_c^2 (w1 - wbar)^2),
//               wbar = (w_A + w_B)/2                                           (3.37)
//   f_m(x)    = sqrt(3) / (pi (4 pi/z1 - (w_B - w_A) - c_x x))                 (3.42)
//   f_c       = 2 f_m                                                          (3.43)
//   g         = 1 - W                                                          (3.44)
//   f(w1)     = w1 - sgn(w1) 2 pi/z1                                           (3.45)
//
// w1 = pinion roll angle [rad] (0 at the pitch point C, the project's theta), x = the
// compression along the line of action [m], K = single-pair stiffness [N/m] (the thesis
// uses its closed form 3.33; any model can be plugged in). Facts that follow from the
// definitions (and are tested): W = 1 and g = 0 at wbar; the minima of W lie at
// wbar +- L/2, L = 4 pi/z1 - (w_B - w_A) - c_x x, i.e. at x = 0 exactly on the borders
// w_B - 2 pi/z1 and w_A + 2 pi/z1 of the single-contact zone (3.35); W_min = -e^-3/2 =
// -0.0249 (the thesis rounds this to -0.02); W = 0 at |w1 - wbar| = L/sqrt(6); and the
// integral of W over the line is sqrt(3 pi) L/8.
// [note] With eq. 3.45 as printed, sgn(w1) switches at the pitch point w1 = 0, not at wbar,
// where g is not 0 unless w_A = -w_B: F then jumps at w1 = 0 by g(0) [K(w1 + p) -
// K(w1 - p)] x. The law reports w1 = 0 as a break so that the integrator locates it;
// SecondPair::centred switches at wbar instead (g = 0 there), which makes F continuous.
#include "dynamics/mesh_force.h"
#include "base/units.h"

#include <functional>

namespace gearfem::dynamics
{
  /// Single-pair mesh stiffness K(w1, x) [N/m] of the tooth pair at pinion roll angle w1
  /// [rad] under compression x [m]. It is also called at angles outside the line of action
  /// AB (the neighbour pair of eq. 3.36), as in the thesis.
  using PairStiffness = std::function<double(double w1, double x)>;

  /// Which neighbour pair eq. 3.36 adds.
  enum class SecondPair
  {
    thesis,  ///< f(w1) = w1 - sgn(w1) 2 pi/z1 (eq. 3.45 as printed; sgn(0) = +1)
    centred  ///< f(w1) = w1 - sgn(w1 - wbar) 2 pi/z1 (continuous at wbar)
  };

  struct RickerLawParameters
  {
    int z1 = 0;         ///< pinion teeth [-]
    double omega_A = 0; ///< start of the line of action AB in pinion roll angle [rad] (< 0)
    double omega_B = 0; ///< end of AB [rad] (> 0); contact ratio (w_B - w_A) z1/(2 pi) in (1, 2)
    /// Widening of the double-contact zone with compression [rad/m] (eq. 3.42; the thesis
    /// takes c_x = 2 deg/mm from its Fig. 16).
    double c_x = 2.0 * units::pi / 180.0 / 1e-3;
    /// Compression at which mean_stiffness() is evaluated [m] (the static deflection).
    double nominal_compression = 1e-5;
    /// K is evaluated at max(|x|, this) [m], so that a load-dependent K (the Hertz ln x
    /// term of eq. 3.33) stays finite at and below zero compression.
    double min_stiffness_compression = 1e-9;
    SecondPair second_pair = SecondPair::thesis;
  };

  /// Ricker-wavelet load-sharing mesh force of Gkimisis 2019 (eqs. 3.36-3.46; see the file header).
  class RickerLoadSharingLaw : public MeshForceLaw
  {
  public:
    /// Throws InputError for z1 < 5, w_A >= 0 or w_B <= 0, a contact ratio outside (1, 2),
    /// c_x < 0, a negative nominal compression or an empty K.
    RickerLoadSharingLaw(PairStiffness K, const RickerLawParameters &p);
    std::string name() const override { return "Ricker load sharing"; }
    double period() const override { return period_; }
    /// {0} (the pitch point, where eq. 3.45 switches pairs) for SecondPair::thesis, {} else.
    std::vector<double> breaks() const override;
    /// F = [K(w1, x) + g K(f(w1), x)] x [N] (eq. 3.36); theta = w1 [rad], delta = x [m].
    double force(double theta, double delta, int zone) const override;
    /// Mean over one period of F/x at the nominal compression [N/m].
    double mean_stiffness() const override { return kbar_; }
    std::unique_ptr<MeshForceLaw> clone() const override
    {
      return std::make_unique<RickerLoadSharingLaw>(*this);
    }

    /// Mesh stiffness F/x = K(w1, x) + g K(f(w1), x) [N/m].
    double stiffness(double theta, double x) const;
    /// Ricker wavelet W(w1, x) [-] (eq. 3.37 with 3.42-3.43); periodic in w1. W = 0 once
    /// the single-contact width L(x) has closed (L <= 0). x < 0 is taken as 0.
    double wavelet(double theta, double x) const;
    /// Weight of the second pair g = 1 - W [-] (eq. 3.44).
    double second_pair_weight(double theta, double x) const { return 1.0 - wavelet(theta, x); }
    /// Roll angle of the second pair f(w1) [rad] (eq. 3.45), for w1 reduced to one period
    /// centred on wbar.
    double second_pair_angle(double theta) const;
    /// Fraction of the mesh force carried by the pair at theta, K/(K + g K_f) [-]; the
    /// second pair carries the rest.
    double load_share(double theta, double x) const;
    /// Width between the minima of W, L(x) = 4 pi/z1 - (w_B - w_A) - c_x x [rad]: the
    /// single-contact zone (eq. 3.35) narrowed by the compression. x < 0 is taken as 0.
    double single_contact_width(double x) const;
    /// f_m(x) [1/rad] (eq. 3.42); infinite once L(x) <= 0.
    double f_m(double x) const;
    /// Centre of AB, wbar = (w_A + w_B)/2 [rad].
    double centre() const { return wbar_; }

  private:
    /// theta reduced to [wbar - p/2, wbar + p/2).
    double reduce(double theta) const;
    PairStiffness K_;
    RickerLawParameters p_;
    double period_, wbar_, kbar_ = 0;
  };
} // namespace gearfem::dynamics
