#pragma once
// ParameterHandler binding of the `Deviations` section (gearfem solve): the manufacturing
// deviations of each gear, given or drawn within an ISO 1328-1 accuracy grade, and the length of
// the hunting cycle. Units at the interface: um, mm (roll length) and deg; SI in the struct.
#include "geometry/deviations.h"

#include <cstdint>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::geometry
{
  class GearPair;
}

namespace gearfem::deviations
{
  struct DeviationParameters
  {
    /// How the deviations enter the contact problem (`Deviations/Model`).
    enum class Model
    {
      condensed, ///< the hunting cycle on a condensed cycle: deviations as gap and advance offsets
      geometry   ///< single pitch deviations built into the mesh (teeth turned), the full-FE sweep of `Solve`
    };
    Model model = Model::condensed;
    /// Pitches of the cycle: 0 = the hunting period lcm(z1, z2).
    long pitches = 0;
    /// ISO 1328-1 accuracy grade (1..11) of a random draw; 0: no draw.
    int grade = 0;
    geometry::Distribution distribution = geometry::Distribution::uniform;
    std::uint64_t seed = 1;
    /// The given deviations of each gear (the draw replaces them when grade > 0).
    geometry::GearDeviations gear[2];
    /// Any deviation given or drawn: `gearfem solve` then runs the hunting cycle.
    bool active() const { return grade > 0 || !gear[0].empty() || !gear[1].empty(); }
  };

  /// The `Tolerance` section of `gearfem tolerance`.
  struct ToleranceParameters
  {
    long samples = 100;     ///< Monte Carlo samples
    std::string cycle_file; ///< a stored condensed cycle; empty: build it (condensed.h5 in the output)
  };
  void declare_tolerance_parameters(dealii::ParameterHandler &prm);
  ToleranceParameters parse_tolerance_parameters(dealii::ParameterHandler &prm);

  void declare_deviation_parameters(dealii::ParameterHandler &prm);
  /// InputError naming the entry for values out of range (sizes against the tooth counts are
  /// checked by pair_deviations / resolve_deviations).
  DeviationParameters parse_deviation_parameters(dealii::ParameterHandler &prm);

  /// The deviations of both gears for `pair`: the given ones, or the draw of the grade (sample
  /// `sample` of the seed's sequence), with the evaluation ranges; checked.
  geometry::PairDeviations resolve_deviations(const DeviationParameters &p, const geometry::GearPair &pair,
                                              std::uint64_t sample = 0);
} // namespace gearfem::deviations
