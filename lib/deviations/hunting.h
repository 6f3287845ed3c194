#pragma once
// The hunting cycle of a pair with manufacturing deviations (geometry/deviations.h), solved on
// the one-pitch condensed cycle (condensed/cycle.h): over lcm(z1, z2) pitches (or a chosen
// number) every stored position is re-solved with the deviations of the teeth that occupy its
// tooth slots at that pitch, as gap modifications. The teeth of the stored cycle are relabelled
// by the pitch: after j pinion pitches the pinion (turning counter-clockwise) has brought tooth
// s - j where the cycle stored tooth s, and gear 2 (clockwise) tooth s + j. Runout adds the
// projection of each gear's rotating eccentricity on the contact normal. Outputs: the solve
// tables over the whole cycle and the order spectrum of the STE (docs/deviations.md).
#include "condensed/cycle.h"
#include "geometry/deviations.h"
#include "post/position.h"
#include "solve/input.h"
#include "solve/run.h"

#include <Eigen/Dense>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::deviations
{
  /// The deviations of both gears with the evaluation ranges of `pair` (the active profile of
  /// each gear between A and E) and its reference pressure angles; checked (InputError).
  geometry::PairDeviations pair_deviations(const geometry::GearPair &pair, const geometry::GearDeviations &g1,
                                           const geometry::GearDeviations &g2);

  /// Tooth index in [0, z) of the tooth whose axis is nearest to body-frame point x (tooth 0
  /// axis +y, teeth counter-clockwise).
  int tooth_at(const Eigen::Vector2d &x, int teeth);

  /// The deviations `d` at the candidates of stored configuration `p` at hunting pitch `pitch`:
  /// - offset [m] (material removed > 0, as contact::CondensedPosition::modification): the
  ///   profile slope and form on the candidate's sample points, and the runout of each gear
  ///   projected on the candidate's normal;
  /// - advance [rad]: the rigid turn of the candidate's teeth (pitch deviation and flank
  ///   offset). An involute moved along its normal by d is the same involute turned by d / r_b,
  ///   and for the conjugate action of the pair a plus material d_b on either member is the
  ///   pinion advanced by d_b / r_b1 (contact::solve_condensed with an advance).
  struct Modification
  {
    Eigen::VectorXd offset, advance;
  };
  Modification deviation_modification(const contact::CondensedPosition &p, const geometry::PairDeviations &d,
                                      long pitch);

  /// One spectrum line: order per pinion revolution, per gear revolution, amplitude [m].
  struct OrderLine
  {
    double order_pinion = 0, order_gear = 0, amplitude = 0;
  };
  /// The single-sided amplitude spectrum of samples equally spaced by `samples_per_pitch`
  /// per pinion pitch of a z1/z2 pair (mean removed): orders of the pinion rotation.
  std::vector<OrderLine> order_spectrum(const std::vector<double> &samples, int samples_per_pitch, int z1, int z2);

  /// Mesh harmonics and the largest non-mesh line of a spectrum: amplitude of order h z1 for
  /// h = 1..3, and the largest line that is not within half a bin of a mesh harmonic.
  struct SpectrumSummary
  {
    double mesh[3] = {0, 0, 0};
    double largest_other = 0, largest_other_order = 0;
  };
  SpectrumSummary summarise(const std::vector<OrderLine> &lines, int z1);

  struct HuntingOptions
  {
    long pitches = 0; ///< 0: the hunting period lcm(z1, z2)
    post::PostOptions post;
    std::ostream *out = nullptr; ///< progress (i/N and ETA); null: quiet
    std::filesystem::path output_dir; ///< empty: nothing written
    std::string input_name;
    /// false: keep only the STE, the spectra and the peaks (no sweep, pairs and pressure
    /// tables; a Monte Carlo sample needs no more).
    bool tables = true;
  };

  struct HuntingRun
  {
    solve::SolveRunResult run;   ///< tables over every torque x pitch x position
    long pitches = 0;
    /// Per torque: the STE over the cycle [m] and its spectrum.
    std::vector<std::vector<double>> ste;
    std::vector<std::vector<OrderLine>> spectrum;
    std::vector<SpectrumSummary> summary;
    /// Per torque: peak root stress of each gear and peak pressure of the flank-to-flank
    /// (Hertzian) pairs over the cycle [Pa] (an edge contact's pressure is mesh-dependent).
    std::vector<double> max_root_stress[2], max_pressure;
  };

  /// Solve the hunting cycle of `variant` (its Solve/Torques; its positions must be the
  /// stored cycle: Positions = cycle over one pitch) with deviations `d` on `cycle`. The
  /// variant's tip reliefs (gap route) come on top. Writes sweep.csv, pairs.csv, pressure.csv,
  /// results.h5 and spectrum.csv to options.output_dir (also after a failure, with the
  /// finished positions; HuntingRun::run.failure then says why).
  HuntingRun run_hunting(const condensed::CondensedCycle &cycle, const solve::GearContactInput &variant,
                         const geometry::PairDeviations &d, const HuntingOptions &options);

  /// Checks that the positions of `in` form one pitch of equally spaced positions (InputError
  /// naming Solve/Positions otherwise): a hunting cycle concatenates them pitch after pitch.
  void check_one_pitch_cycle(const solve::GearContactInput &in);
} // namespace gearfem::deviations
