#pragma once
// Per-run discretisation-error estimate of `gearfem solve` (`Solve/Error estimate`):
// a few sample positions on the line of action are solved at every torque on
// the run's model (level h) and on a model whose fine mesh sizes are divided by r = 2
// (level h/r); the error of the level-h values of STE, root stress (pinion, gear) and p_max
// is estimated by Richardson extrapolation with an assumed order p,
//   e_h = Q_exact - Q_h ~ (Q_{h/r} - Q_h) r^p / (r^p - 1)   (Richardson 1911; Roache 1998, grid convergence index),
// p = 2 by default (Q2 elements; the project's convergence data, docs/output-format.md
// section "Error estimate", validation/error_estimate/README.md).
// Callable by a test, the batch driver or an optimiser; `gearfem solve` reports it in its
// summary and in run.json.
#include "solve/input.h"
#include "post/position.h"
#include "base/progress.h"

#include <array>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::solve
{
  /// The quantities whose error is estimated, in SI (STE [m], stresses and pressure [Pa]).
  struct EstimatedQuantities
  {
    double ste = 0;              ///< delta_theta r_b1 [m]
    double root_stress_pinion = 0; ///< max fillet stress of the pinion [Pa]
    double root_stress_gear = 0;   ///< max fillet stress of the gear [Pa]
    double p_max = 0;            ///< peak pressure of the Hertzian pairs [Pa]
    static constexpr int size = 4;
    double operator[](int i) const;
    double &operator[](int i);
    /// Column names (with units of the engineering output) and SI-to-output factors.
    static const std::array<const char *, size> &names();
    static const std::array<double, size> &output_factors(); ///< um, MPa, MPa, MPa
  };

  /// One sample position at one torque: both levels and the estimated error of level h.
  struct ErrorSample
  {
    std::string zone;  ///< "single pair", "double pair" or "transition"
    std::string point; ///< how it was placed: "(B+D)/2", "(A+B)/2", "D"
    double phi1   = 0; ///< pinion roll angle [rad] (0 at C)
    double torque = 0; ///< T1 [N m]
    EstimatedQuantities coarse, fine;
    /// Estimated error of the level-h value, Q_exact - Q_h (signed) [SI].
    EstimatedQuantities error;
    /// |error| / |Q_h| [-] (0 when Q_h = 0).
    EstimatedQuantities relative;
  };

  struct ErrorEstimateOptions
  {
    double refinement = 2; ///< r: the fine mesh sizes of the second level are divided by r (> 1)
    double order      = 2; ///< p: assumed convergence order (> 0)
    post::PostOptions post;      ///< evaluation thresholds (as in the sweep)
    std::ostream *out = nullptr; ///< progress lines (i/N, ETA); null: silent
  };

  struct ErrorEstimate
  {
    double refinement = 2, order = 2;
    std::vector<ErrorSample> samples; ///< position-major within each torque
    /// Per torque and quantity: the largest |error| and |error|/|Q_h| over the samples.
    std::vector<std::pair<double, EstimatedQuantities>> max_error, max_relative;
    unsigned int fine_dofs   = 0;  ///< DoFs of the refined model
    double h_contact_fine    = 0;  ///< h_contact of the refined model, gear 1 [m]
    double seconds_setup     = 0;  ///< wall time to build the refined model [s]
    double seconds_solve     = 0;  ///< wall time of the sample solves on both levels [s]
    double seconds() const { return seconds_setup + seconds_solve; }
  };

  /// The sample positions (name of the zone, how placed, roll angle [rad]) from the points
  /// of the line of action (docs/geometry.md): the middle of the single-pair zone (B+D)/2,
  /// the middle of the approach double-pair zone (A+B)/2, and the transition D (highest
  /// point of single contact of the pinion, where its root stress peaks).
  std::vector<std::array<std::string, 2>> error_sample_names();
  std::vector<double> error_sample_positions(const geometry::GearPair &pair);

  /// The mesh parameters of the refined level: h_contact (its default m_n/30 resolved with
  /// `module` [m]), h_fillet, h_coast and h_corner (when given; their defaults follow
  /// h_fillet and h_contact) divided by r; the body sizes (h_body, h_tooth, growth, bore,
  /// rim) and the fine teeth unchanged.
  mesh::GearMeshParameters refined_mesh(const mesh::GearMeshParameters &p, double module, double refinement);

  /// STE, root stresses and p_max of `model` at `positions` [rad] x `torques` [N m], torque-major
  /// (index t * positions.size() + i); each position warm-started from the same position at the
  /// previous torque. `progress` (may be null) steps from `step` + 1 on. Throws SolverError
  /// when a solve does not converge or a value is not finite.
  std::vector<EstimatedQuantities> solve_samples(contact::GearContactModel &model, const std::vector<double> &positions,
                                                 const std::vector<double> &torques, const post::PostOptions &post,
                                                 Progress *progress = nullptr, std::size_t step = 0,
                                                 const std::string &label = "");

  /// The estimate on a given pair of models (level h = `coarse`, level h/r = `fine`) at
  /// `positions` [rad] x `torques` [N m]. Throws SolverError when a solve does not converge.
  ErrorEstimate estimate_error(contact::GearContactModel &coarse, contact::GearContactModel &fine,
                               const std::vector<double> &positions, const std::vector<double> &torques,
                               const ErrorEstimateOptions &options);

  /// The estimate of a run: builds the refined model of `in` (refined_mesh) and solves the
  /// sample positions (error_sample_positions) at every torque of `in` on both models.
  ErrorEstimate estimate_error(contact::GearContactModel &model, const solve::GearContactInput &in,
                               const ErrorEstimateOptions &options);

  /// Markdown table for the solve summary (engineering units, % of the level-h value).
  std::string error_estimate_table(const ErrorEstimate &e);
  /// JSON object (the `error_estimate` member of run.json; docs/output-format.md), with
  /// `extra` numbers (name, value) appended as members (e.g. the run's sweep time).
  std::string error_estimate_json(const ErrorEstimate &e,
                                  const std::vector<std::pair<std::string, double>> &extra = {});
} // namespace gearfem::solve
