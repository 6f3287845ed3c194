#pragma once
// The calibrated analytical mesh model, fitted to FE static transmission error. The model: the tooth-pair compliance of PairCompliance split into its beam,
// foundation and Hertz parts, each with a multiplier; a body compliance in series with the
// whole mesh (rim, web and hub deformation that the tooth models leave out); and the corner
// contact outside the geometric path A..E (Gkimisis 2019 OA/BΓ, analytical/corner.h): a pair beyond A or E
// starts with the exact rigid corner gap (gear held, pinion turned, as in `gearfem solve`)
// and carries load once the mesh deflection exceeds it, along the normal of the touched
// flank (lever arm of corner.h). The FE shows this as the narrowing of the single-pair zone
// under load. The one corner parameter is the effective radius of curvature of the tip
// corner in the Hertz term of a corner contact (a sharp corner has none; the FE resolves it
// with elements of finite size). Load sharing by equal deflection with the Hertz
// nonlinearity iterated on the pair loads. Light layer (Eigen only). SI units.
#include "analytical/tooth.h"

#include <string>
#include <vector>

namespace gearfem::calibration
{
  // The analytical models this one calibrates (lib/analytical).
  using analytical::CornerGeometry;
  using analytical::InvoluteTooth;
  using analytical::PairCompliance;
  using analytical::PairLine;

  /// One FE result: STE [m] at pinion roll angle [rad] under pinion torque [N m].
  struct SteSample
  {
    double torque = 0, roll_angle = 0, ste = 0;
  };

  /// The physically meaningful correction factors.
  struct CalibrationFactors
  {
    double beam = 1;        ///< multiplier on the beam (bending + shear + axial) compliance
    double foundation = 1;  ///< multiplier on the fillet-foundation compliance
    double hertz = 1;       ///< multiplier on the Hertz compliance
    double body = 0;        ///< series body compliance [m/N] (of the normal load)
    bool corner = true;     ///< corner contact OA/BΓ outside A..E (exact rigid gap, corner.h)
    /// Radius of curvature of the tip corner [m] in the Hertz term of a corner contact (against
    /// the mating involute's radius at the touching point). 0: the tip rounding of the
    /// geometry (PairLine) if it has one, else the involute radii at the nearest path end.
    double corner_radius = 0;
  };

  /// The calibrated mesh model.
  class CalibratedMesh
  {
  public:
    CalibratedMesh(const PairCompliance &pairs, const CalibrationFactors &f);
    /// Loaded STE [m] at roll angle phi1 [rad] and normal load F [N] (> 0); also the pair
    /// loads and the number of pairs carrying load when asked.
    double ste(double phi1, double F, std::vector<double> *pair_loads = nullptr) const;
    /// Secant mesh stiffness F / STE [N/m].
    double stiffness(double phi1, double F) const { return F / ste(phi1, F); }
    /// Normal load [N] at mesh compression delta [m] (the inverse of ste(); 0 for delta <= 0).
    double load_at(double phi1, double delta) const;
    /// Pinion torque T(phi1, delta) [N m] of the two-sided mesh-table contract
    /// (docs/mesh-tables.md, version 2) for a total clearance b >= 0 along the line of action:
    /// r_b1 load_at(phi1, delta) for delta > 0; 0 for -b <= delta <= 0 (loss of contact);
    /// -r_b1 load_at(reverse_offset - phi1, -delta - b) for delta < -b (back contact on the
    /// coast flanks, mapped onto the drive flanks of the symmetric teeth: Gkimisis 2019, 4.11).
    double torque(double phi1, double delta, double backlash, double reverse_offset) const;
    const CalibrationFactors &factors() const { return f_; }
    double base_radius() const { return pairs_.line().rb1; }

  private:
    PairCompliance pairs_;
    CalibrationFactors f_;
    CornerGeometry geo_;
  };

  /// The reverse-flank mapping offset psi [rad] of Gkimisis 2019 (4.11), theta_r = psi - theta:
  /// the pinion's angular tooth thickness at the working pitch circle, 2 (psi_b - inv
  /// alpha_w), thinned by the pinion's half of a clearance b [m] (b / (2 r_b1)): the backlash
  /// is taken as shared equally by the two gears, as a thickness coefficient C_f on both does.
  double reverse_offset(const InvoluteTooth &pinion, const PairLine &line, double backlash);

  /// Which factors the fit may change.
  struct FitMask
  {
    bool beam = true, foundation = true, hertz = true, body = true;
    bool corner_radius = false; ///< the corner radius (start value from CalibrationFactors, > 0)
  };

  /// Error statistics of a model against samples [relative].
  struct SteErrors
  {
    double torque = 0;
    double mean_abs = 0, max_abs = 0;
  };

  struct FitResult
  {
    CalibrationFactors factors;
    std::vector<std::string> names;        ///< fitted factors
    std::vector<double> values, std_error; ///< value and 1-sigma standard error of each
    std::vector<std::string> warnings;     ///< ill-conditioning, unidentifiable factors
    double condition = 0;                  ///< condition number of J^T J (scaled parameters)
    int iterations = 0;
    double rms = 0;                        ///< RMS relative STE error at the optimum
  };

  /// Relative STE errors per torque of `f` against `samples`.
  std::vector<SteErrors> ste_errors(const PairCompliance &pairs, const CalibrationFactors &f,
                                    const std::vector<SteSample> &samples);

  /// Levenberg-Marquardt fit of the masked factors minimising the relative STE error over
  /// all samples (multipliers in log space, so they stay positive; body and corner radius >= 0).
  /// Standard errors from sigma^2 (J^T J)^-1; factors whose correlation exceeds 0.98 or
  /// whose relative standard error exceeds 50 % are reported as not identifiable.
  FitResult fit_factors(const PairCompliance &pairs, const std::vector<SteSample> &samples,
                        const CalibrationFactors &start, const FitMask &mask = {});
} // namespace gearfem::calibration
