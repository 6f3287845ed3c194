#pragma once
// Proof of a model choice on the run itself (`Solve/Target`). The first guess of
// choose_model is solved at four sample positions of the line of action at every torque,
// together with a companion model whose sizes differ where the asked quantities need them
// (h_contact for STE and p_max, h_fillet for the root stress): coarser by 2, so that the proof
// costs a fraction of the run. Richardson with order p between the two levels a (the candidate)
// and b (the companion), h_b = rho h_a,
//   e_a = Q_exact - Q_a ~ (Q_b - Q_a) / (1 - rho^p),
// estimates the candidate's error. Where it exceeds the target, the sizes of the failing
// quantities are refined by the factor the estimate asks for, and the refined level is
// estimated against the companion again (the largest rho: the least amplified scatter of
// non-nested meshes), and so on, within a cost cap. The sweep then runs on the accepted
// level, and its estimate is reported beside each quantity. Full gears refine only the teeth
// the swept positions load (geometry::loaded_teeth), their bodies and unloaded teeth are
// sized for the target (choose_model), and the companion coarsens the unloaded teeth up to
// unloaded_tooth_size.
#include "base/table.h"
#include "model_choice/choose.h"
#include "solve/error_estimate.h"
#include "solve/input.h"

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::model_choice
{
  struct TargetOptions
  {
    /// Wall-time cap [s] of the whole run (levels, samples and the predicted sweep); 0: none.
    double cost_cap  = 1800;
    int max_levels   = 5;    ///< candidates tried at most
    double order     = 2;    ///< p of the Richardson estimate
    post::PostOptions post;  ///< evaluation thresholds (as in the sweep)
    std::ostream *out = nullptr;
  };

  /// One model tried.
  struct Level
  {
    std::string role;               ///< "companion", "candidate", "delivered"
    double h_contact = 0, h_fillet = 0; ///< gear 1 [m]
    unsigned int degree = 2, dofs = 0;
    double seconds_setup = 0, seconds_samples = 0;
    /// A gear's all-quad mesh came from gmsh's subdivision fallback (slower set-up, less
    /// regular cells).
    bool subdivided = false;
    int remeshed    = 0; ///< sizes nudged after a failed first quad recombination
    /// Torque-major samples (target_sample_positions x torques).
    std::vector<solve::EstimatedQuantities> samples;
    /// Estimated relative error per quantity (Quantity order) of this level, from it and the
    /// companion (the first level); NaN where no estimate (the companion).
    std::array<double, n_quantities> estimate{};
    /// h of the level it was estimated against / h of this level, contact and fillet groups.
    double rho_contact = 1, rho_fillet = 1;
    /// fillet_resolution of its h_fillet (relative; 0: the companion): the root-stress
    /// estimate is never below it.
    double fillet_resolution = 0;
    /// A swept level the choice refined after its sweep: the torques that sweep covered (fewer
    /// than Solve/Torques where abandon_sweep stopped it); 0 for the other levels.
    std::size_t swept_torques = 0;
    /// The parts of a swept p-p estimate (swept_pp_estimate) at the torque where it is
    /// largest, relative to that torque's swept p-p: the Richardson part of the zone samples
    /// and twice the swept ripple; the torque [N m]. NaN where the level was not swept.
    double pp_richardson = std::nan(""), pp_ripple = std::nan(""), pp_torque = std::nan("");
    /// The resolution of the swept p-p (relative): twice the swept ripple, the largest over
    /// the torques; the p-p estimate is never below it. NaN where the level was not swept.
    double pp_resolution = std::nan("");
  };

  struct TargetOutcome
  {
    AccuracyTarget target;
    ModelChoice choice;             ///< the first guess
    std::vector<Level> levels;      ///< in the order built
    std::size_t delivered = 0;      ///< index into levels
    bool met = false;
    std::string stop_reason;        ///< why the refinement stopped short, or empty
    double order = 2;               ///< p of the estimate
    double seconds = 0;             ///< wall time of the choice (levels and samples) [s]
    std::vector<double> positions;  ///< sample roll angles [rad]
    /// Weights of the zone samples in the cycle mean (zone_weights); empty: none.
    std::vector<double> mean_weights;
    std::vector<double> torques;
    /// The delivered model, built; the input's mesh and FE degree are set to it.
    std::unique_ptr<contact::GearContactModel> model;
    /// The route of the delivered sweep (model_choice/route.h): "full FE" or "condensed cycle", why.
    std::string route = "full FE", route_why;
    /// The condensation's error measured on the run (condensed route; NaN: none), already
    /// included in the delivered level's estimate.
    std::array<double, n_quantities> condensation{};
    TargetOutcome() { condensation.fill(std::numeric_limits<double>::quiet_NaN()); }
    const Level &delivered_level() const { return levels.at(delivered); }
  };

  /// The sample positions: (A+B)/2 (double-pair zone), B (the gear's highest point of single
  /// contact), (B+D)/2 (single-pair zone), D (the pinion's).
  std::vector<double> target_sample_positions(const geometry::GearPair &pair);

  /// The cycle weights of the zone samples (zone_samples): the double-pair zone A-B spans
  /// (B - A) / (D - A) = eps_alpha - 1 of a pitch from A, the single-pair zone B-D the rest.
  /// Empty where B is not between A and D (a contact ratio outside 1-2).
  std::vector<double> zone_weights(const geometry::GearPair &pair);

  /// Estimated relative errors of level `a` from its samples and those of level `b`
  /// (`rho_contact`, `rho_fillet`: h_b / h_a of the two size groups; a group with |rho - 1| <=
  /// 0.2 gives NaN for its quantities), with `n_positions` positions per torque and order `p`:
  /// mean STE: with `mean_weights` (one per STE sample), the error of the cycle mean,
  /// |sum w e| / sum w Q, each zone middle standing for its zone (the largest over the
  /// torques); without, the largest |e|/Q of the STE samples (`ste_samples`, empty: all). The
  /// largest |e|/Q overstates the error of the mean where the zones' errors differ (FZG type C
  /// at 94 N m: 0.23 % at the double-zone middle, 0.0 % at the single-zone middle, a true
  /// error of the mean of 0.055 %; the weighted estimate 0.086 %); p-p STE: the
  /// error of (max Q - min Q) over those samples of a torque, e(max) - e(min), relative to it; root stress: |e|/Q at the sample of each gear's
  /// largest stress; p_max: the largest |e|/Q. `pp` (per torque [m]): the p-p STE that the
  /// p-p error is relative to, instead of the samples' max Q - min Q.
  std::array<double, n_quantities> estimate_relative(const std::vector<solve::EstimatedQuantities> &a,
                                                     const std::vector<solve::EstimatedQuantities> &b,
                                                     std::size_t n_positions, double rho_contact,
                                                     double rho_fillet, double p,
                                                     const std::vector<double> *pp = nullptr,
                                                     const std::vector<std::size_t> &ste_samples = {},
                                                     const std::vector<double> &mean_weights = {});
  /// The samples (indices within a torque) that the STE estimates read: the middles of the
  /// double- and single-pair zones, (A+B)/2 and (B+D)/2. B and D, the transitions, serve the
  /// root stresses: there the STE jumps over a few hundredths of a degree, and its level-to-
  /// level difference is the position of the jump, not a discretisation error (Siasos 2010
  /// 23/69 with all four samples: a p-p estimate of 2.7 % at m/30, where validation/speed_vs_error
  /// measured 0.04 %).
  extern const std::vector<std::size_t> zone_samples;

  /// The Hertz half-width (model_choice::contact_half_width) of `in`'s pair and materials at the
  /// smallest non-zero |torque| of its Solve/Torques [m] (0: none), the first guess's contact
  /// load.
  double lowest_torque_half_width(const solve::GearContactInput &in);

  /// Choose, prove and refine for `in` (its mesh and FE degree are replaced by the delivered
  /// level's). Throws SolverError when a sample solve fails; InputError for an internal pair.
  TargetOutcome run_to_target(solve::GearContactInput &in, const AccuracyTarget &target, const FixedSettings &fixed,
                              const TargetOptions &options);

  /// The mesh ripple of a swept STE curve (`ste` over `roll`, one torque, in order): at each
  /// interior position, |STE - the least-squares quadratic through the two neighbours on each
  /// side|; the median of these (the mean of the two middle ones for an even count). A smooth
  /// curve gives its curvature term only (the converged
  /// references of validation/model_choice: 0.04-0.11 % of the p-p; the 75th percentile,
  /// which the transitions reach, 0.12-0.38 %); the node-to-segment ripple of a contact mesh
  /// (the STE of the Parker pair at m/30 and 100 N m moves by +-0.01 um from position to
  /// position) adds to it, and a p-p taken over the positions picks it up at both ends (the p-p
  /// error 1.1 % there; twice the median 0.72 %).
  double ste_ripple(const std::vector<double> &roll, const std::vector<double> &ste);

  /// Per torque of a sweep: the swept p-p STE [m] and its mesh ripple (ste_ripple) [m].
  struct SweptPp
  {
    std::vector<double> pp, ripple; ///< in the order of the torques; only the torques swept
  };
  /// SweptPp of the torques of `torques` whose positions are in `sweep` (sweep.csv: columns
  /// "torque" [N m], "roll angle" [deg], "STE" [um]), up to the first torque with none.
  SweptPp swept_pp(const Table &sweep, const std::vector<double> &torques);

  /// The parts of a swept p-p estimate, relative to the swept p-p of their torque.
  struct PpParts
  {
    double richardson   = std::nan(""); ///< the zone middles' Richardson part, where largest
    double twice_ripple = std::nan(""); ///< twice the swept ripple, where the estimate is largest
    double torque       = std::nan(""); ///< that torque [N m]
    double resolution   = std::nan(""); ///< twice the swept ripple, the largest over the torques
  };
  /// The p-p estimate of the delivered level against the sweep: per torque swept, the
  /// Richardson part of its zone samples relative to the swept p-p and twice the swept ripple
  /// relative to it, combined as independent parts (root sum of squares); the largest over
  /// the torques. The ripple part is the p-p's resolution: a p-p over the positions picks the
  /// position-to-position scatter up at both ends, and below it the p-p error of a mesh is
  /// not ordered by h (docs/model-choice.md, step 3). `parts` (may be null): filled.
  double swept_pp_estimate(const TargetOutcome &o, const SweptPp &swept, PpParts *parts = nullptr);

  /// With the sweep done: the delivered level's p-p estimate becomes swept_pp_estimate, and
  /// its parts are kept (Level::pp_richardson, pp_ripple, pp_torque, pp_resolution). Updates
  /// `met`.
  void rescale_pp(TargetOutcome &o, const SweptPp &swept);
  /// `met`: every asked quantity's estimate of the delivered level within its tolerance.
  void update_met(TargetOutcome &o);

  /// While the sweep runs, after torque `torques_done - 1` (`contact_seconds` of solves so
  /// far): true when the p-p estimate of the torques swept already is above the target and
  /// refine_after_sweep would refine (it would discard this sweep): the caller stops the
  /// sweep there. With three torques, a sweep that the first torque condemns costs a third
  /// (Siasos 2010 23/69 at m/45: 0.3 s instead of 1.0 s of solves).
  bool abandon_sweep(const TargetOutcome &o, const solve::GearContactInput &in, const FixedSettings &fixed,
                     const TargetOptions &options, const SweptPp &swept, std::size_t torques_done,
                     double contact_seconds);

  /// When the p-p estimate after the sweep is above its tolerance: refine h_contact (the
  /// factor the estimate asks for, to the next rung), prove the new level against the
  /// companion and deliver it (true: sweep again), unless h_contact is set in the input, the levels
  /// are spent or the cost cap would be exceeded (false, with the reason). `sweep_seconds`:
  /// the wall time of the sweep just done; `torques_swept`: the torques it covered when
  /// abandon_sweep stopped it (0: all), its cost scaled to all of them for the cost cap.
  bool refine_after_sweep(TargetOutcome &o, solve::GearContactInput &in, const FixedSettings &fixed,
                          const TargetOptions &options, double sweep_seconds, std::size_t torques_swept = 0);

  /// Markdown for the summary: the target, the choice and why, each level, the achieved
  /// estimate against the target.
  std::string model_choice_summary(const TargetOutcome &o);
  /// JSON object (run.json member `model_choice`, docs/output-format.md).
  std::string model_choice_json(const TargetOutcome &o);
} // namespace gearfem::model_choice
