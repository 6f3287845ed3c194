#pragma once
// The sweep of a helical pair over the mesh cycle (`gearfem helical`): the condensed cycle of
// its transverse section on the grid of the `Solve` section, the slices on it at every
// position and torque, the summary per torque, and the tables (docs/helical.md).
#include "condensed/cycle.h"
#include "helical/slicing.h"

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::helical
{
  /// The grid of `section`'s `Solve` section (a cycle of N positions over one pitch of gear 1)
  /// and the slicing options of `hx` on it; sets section's positions to the grid's list (what
  /// the condensed cycle stores). InputError naming the entry for anything else.
  SlicingOptions slicing_options(solve::GearContactInput &section, const HelixInput &hx,
                                 const post::PostOptions &post);

  /// The figures of one torque over the cycle.
  struct TorqueSummary
  {
    double torque = 0;                  ///< [N m]
    double ste_mean = 0, ste_pp = 0;    ///< [m]
    double k_mean = 0;                  ///< mean secant mesh stiffness [N/m]
    double c_gamma = 0;                 ///< k_mean / b [N/m^2] (ISO 6336-1's c_gamma per unit width)
    double c_gamma_iso() const { return c_gamma / 1e9; } ///< the same in N/(mm um)
    double k_h_beta = 0;                ///< largest face load factor over the cycle
    double root_stress_pinion = 0, root_stress_gear = 0, p_max = 0; ///< largest over the cycle [Pa]
  };

  struct HelicalRun
  {
    Helix helix;
    SlicingOptions options;
    double eps_alpha = 0, eps_gamma = 0;
    std::vector<double> torques;
    std::vector<HelicalResult> results; ///< torque-major, in grid order
    std::vector<TorqueSummary> summary;
    std::string failure;                ///< empty: every position solved
    double setup_seconds = 0;           ///< mesh, assemble and factorise the section (0 with a given cycle)
    double build_seconds = 0;           ///< set-up and condensation over the grid (0 with a given cycle)
    double sweep_seconds = 0;           ///< all positions and torques on the cycle
  };

  struct RunOptions
  {
    std::ostream *out = nullptr; ///< progress i/N with ETA; null: quiet
    /// The condensed cycle's torques (condensed/cycle.h): 0 takes the largest torque, and the
    /// range an eighth of the smallest to 4 times the largest (slices of a misaligned face
    /// carry from nothing to several times the mean); scene_ratio < 0: the slices' rule
    /// (condensed::scene_ratio).
    double build_torque = 0, torque_lo = 0, torque_hi = 0, scene_ratio = -1;
    std::filesystem::path cycle_file; ///< read this condensed cycle instead of building one
    std::filesystem::path write_cycle; ///< write the built cycle here (empty: not written)
    /// How one position is solved on the sliced pair; empty: SlicedPair::solve with the
    /// options' lead. The shaft coupling (system_deflection/run.h) solves each position on the
    /// pair's shafts through it.
    std::function<HelicalResult(const SlicedPair &, double phi1, double torque)> position;
  };

  /// Build (or read) the cycle of `section` (positions set by slicing_options, which gave
  /// `o`) and sweep every torque and position. A position that fails ends the sweep with
  /// `failure` set; what was solved is kept.
  HelicalRun run_helical(const solve::GearContactInput &section, const SlicingOptions &o, const RunOptions &options);
  /// The condensed cycle of `section` for `torques` as run_helical builds it (or reads it from
  /// options.cycle_file, InputError for a torque outside its range; written to
  /// options.write_cycle when set); the set-up and build times go into `run`.
  condensed::CondensedCycle section_cycle(const solve::GearContactInput &section, const std::vector<double> &torques,
                                          const RunOptions &options, HelicalRun &run);
  std::vector<TorqueSummary> summarise(const std::vector<HelicalResult> &results);

  /// helical.csv (a row per position and torque), slices.csv (a row per slice),
  /// lines.csv (the loaded contact-line points) and helical.json (the helix and the summary),
  /// each written atomically into `dir`.
  void write_helical(const HelicalRun &run, const std::filesystem::path &dir, const std::string &input_name);
} // namespace gearfem::helical

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::helical
{
  /// A `gearfem helical` job as its input file states it: the transverse section (given in the
  /// normal section by default, ISO 21771), the slicing with its helix, and the cycle options.
  /// The one parser of the CLI command and the Python module's gearfem.helical.
  struct Request
  {
    solve::GearContactInput section;
    HelixInput helix;
    SlicingOptions slicing;
    RunOptions run; ///< out, cycle_file and write_cycle are the caller's
  };
  /// The sections a helical job reads: the solve input, post-processing, Condense and Helical.
  void declare_request(dealii::ParameterHandler &prm);
  /// The request of a parsed handler; InputError (naming the entry) for a bad helix or slicing,
  /// before any meshing.
  Request parse_request(dealii::ParameterHandler &prm);
} // namespace gearfem::helical
