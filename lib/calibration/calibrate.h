#pragma once
// The calibration stage: the analytical mesh model (calibration/model.h) fitted to FE
// STE read from solve results (io/solve_results.h), cross-validated on held-out torques,
// and turned into the mesh tables the dynamics reads (io/mesh_table.h). Callable without
// the CLI (`gearfem calibrate` parses, calls calibrate() and write_outputs()). Light layer:
// no deal.II. SI units.
#include "calibration/model.h"
#include "base/table.h"
#include "geometry/pair.h"
#include "io/mesh_table.h"

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::calibration
{
  namespace an = analytical;

  /// FE samples of one or more results.h5 files of the pair with geometry hash `hash`.
  /// Throws InputError naming `entry` (e.g. "Calibration/Results files") and the file for a
  /// missing, foreign or corrupt file and for results of another geometry.
  std::vector<SteSample> read_fe_samples(const std::vector<std::filesystem::path> &files,
                                             const std::string &hash, const std::string &entry);

  struct TableGrid
  {
    int n_theta = 200;       ///< roll angles over one pitch (>= 8)
    int n_load = 50;         ///< loads or compressions (>= 4)
    double load_factor = 2;  ///< largest table load over the largest FE load (>= 1)
    double backlash = -1;    ///< clearance b [m] of a two-sided torque table; < 0: one-sided
  };

  struct Options
  {
    CalibrationFactors start; ///< start values (and the corner model)
    FitMask mask;
    TableGrid grid;
  };

  struct Result
  {
    FitResult fit;
    CalibrationFactors plain;                          ///< multipliers 1, no body
    std::vector<SteErrors> before, after;              ///< per torque
    std::vector<std::pair<double, SteErrors>> held_out; ///< torque left out -> its errors
    std::map<double, CalibrationFactors> held_out_factors;
    std::set<double> torques;
    io::MeshTable stiffness, torque, ste; ///< k(theta, F), T(theta, delta), STE(theta, T)
    double F_max = 0, delta_max = 0;      ///< table ranges [N], [m]
    double reverse_offset = 0;            ///< psi of a two-sided torque table [rad]
    double table_seconds = 0;             ///< wall time of the table generation
  };

  /// Fit, cross-validate (each torque held out in turn, when there are >= 2) and tabulate.
  Result calibrate(const an::PairCompliance &pc, const geometry::GearPair &pair,
                   const std::vector<SteSample> &samples, const Options &options);

  /// The tables of the calibrated model `m` on the grid (hash: the pair's fingerprint).
  void make_tables(const CalibratedMesh &m, const an::PairCompliance &pc, const geometry::GearPair &pair,
                   double max_fe_torque, const TableGrid &grid, Result &r);

  /// FE against the model per sample: STE FE, before, after [um], and held out (the model
  /// fitted without the sample's torque) when there was cross-validation.
  Table comparison_table(const Result &r, const an::PairCompliance &pc, const std::vector<SteSample> &samples);

  /// The calibrated STE(theta, T) at the FE torques over the table's roll angles [um].
  Table ste_table(const Result &r, const an::PairCompliance &pc);

  /// The cost of the calibrated model: one cycle of `positions` equally spaced roll angles
  /// over a base pitch from A at pinion torque `torque` [N m] (what a dynamics step or a
  /// design loop pays), timed; and its mean STE [m].
  struct CycleTiming
  {
    double seconds  = 0;
    double mean_ste = 0;
  };
  CycleTiming time_cycle(const CalibratedMesh &m, const an::PairCompliance &pc, double torque, int positions = 40);

  /// The Markdown report: fitted factors with standard errors, errors before/after/held out.
  std::string report(const Result &r, const std::string &model, const std::string &hash, std::size_t n_samples,
                     const std::vector<std::string> &files);
} // namespace gearfem::calibration
