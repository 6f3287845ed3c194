#pragma once
// Writers of the export targets (docs/export.md): ROSS-style mesh-stiffness arrays, spline
// tables of STE and stiffness over angle x torque, and transmission-error tables per mesh
// cycle and per revolution. Every file is written to a temporary name and renamed.
#include "export/grid.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gearfem::exports
{
  /// ROSS's Mesh arrays (petrobras/ross, ross/gear_element.py, class Mesh at commit
  /// 82d2c69: theta_range = linspace(0, n_mesh_period 2 pi / z_driving, n), stiffness_range
  /// [N/m] at each theta, read back by numpy.interp after theta mod max(theta_range)).
  /// theta_range [rad] is the driving pinion's rotation from the start of contact A, closed
  /// (first 0, last the grid's period); one stiffness_range per torque.
  struct RossArrays
  {
    std::vector<double> theta_range;                  ///< [rad], 0 at A, strictly increasing
    std::vector<double> torque;                       ///< [N m]
    std::vector<std::vector<double>> stiffness_range; ///< [torque][theta] [N/m]
    int mesh_periods = 1;                             ///< ROSS's n_mesh_period
  };

  /// The grid's own nodes shifted to A (theta - theta_A, wrapped into [0, period)): copies;
  /// plus the closing nodes 0 and period (periodic linear interpolation when no node is at A).
  RossArrays ross_arrays(const CycleGrid &g, const PairInfo &pair);
  void write_ross_json(const std::filesystem::path &file, const RossArrays &r, const PairInfo &pair,
                       const std::string &source);

  /// Spline tables (Simpack/Adams input functions): roll angle [deg] from the pitch point C,
  /// one column per torque, rows over one period closed by a repeat of the first row at
  /// theta_0 + period. `which`: "ste" ([um]) or "stiffness" ([N/m]). 17 significant digits.
  void write_spline_csv(const std::filesystem::path &file, const CycleGrid &g, const std::string &which);

  /// Transmission error as an interpolation-function table (COMSOL Multibody Dynamics
  /// "Transmission error of gear pair", function of the pinion mesh cycle or full revolution;
  /// NX/Simcenter Motion user-defined TE): '%' comment lines, then rows "angle TE_1 TE_2 ..."
  /// with the pinion rotation from A [rad] and the TE fluctuation STE - mean(STE) [m] per
  /// torque (the mean of each torque is in the header). `revolution` false: one mesh cycle
  /// [0, period]; true: the pinion revolutions the grid covers (the cycle repeated z1 times, or
  /// the hunting sweep as recorded), closed.
  void write_te_table(const std::filesystem::path &file, const CycleGrid &g, const PairInfo &pair, bool revolution,
                      const std::string &source);
} // namespace gearfem::exports
