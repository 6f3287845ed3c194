#pragma once
// The export grid: static transmission error and mesh stiffness over pinion roll angle x
// torque, taken from what gearfem writes (a solve result, a hunting-cycle sweep, a mesh
// table), in SI. Every export format of docs/export.md is written from it (formats.h), except
// the two-sided force table, which is written from a torque mesh table (force_table.h).
// Light module: base and io only.
#include "io/mesh_table.h"
#include "io/solve_results.h"

#include <string>
#include <vector>

namespace gearfem::exports
{
  /// The pair numbers an export needs (from geometry::GearPair in the command).
  struct PairInfo
  {
    int z1 = 0, z2 = 0;       ///< teeth of the pinion (drives) and of the gear
    double base_radius = 0;   ///< pinion base radius r_b1 [m]
    double theta_A = 0;       ///< pinion roll angle of the start of contact A [rad] (< 0; C is 0)
    std::string geometry_hash; ///< geometry::geometry_fingerprint of the pair
    double mesh_period() const; ///< 2 pi / z1 [rad]
  };

  /// STE and secant stiffness on (theta, T), theta-major.
  struct CycleGrid
  {
    std::vector<double> theta;     ///< pinion roll angle, 0 at the pitch point C, strictly increasing [rad]
    std::vector<double> torque;    ///< pinion torque T1, strictly increasing [N m]
    std::vector<double> ste;       ///< STE along the line of action [m], ste[i * n_torque + j]
    std::vector<double> stiffness; ///< secant mesh stiffness F_n / STE, F_n = T1 / r_b1 [N/m]
    /// Period of the data in theta [rad]: 2 pi / z1, or P 2 pi / z1 for a hunting-cycle sweep
    /// of P pitches (the positions cover [theta[0], theta[0] + period) uniformly then).
    double period = 0;
    int pitches = 1;               ///< P: mesh periods in `period`
    std::string source;            ///< what the grid was taken from (file and kind)
    double ste_at(std::size_t i, std::size_t j) const { return ste[i * torque.size() + j]; }
    double k_at(std::size_t i, std::size_t j) const { return stiffness[i * torque.size() + j]; }
  };

  /// From the sweep of a `gearfem solve` result (results.h5; one mesh cycle, or a hunting
  /// cycle with manufacturing deviations): STE and F_n / STE copied at `torques` (each must
  /// be one of the sweep's torques; empty: all of them). The roll angles must be the same at
  /// every torque and cover whole mesh periods uniformly. Throws InputError naming `parameter`
  /// (the torque list) or the source.
  CycleGrid grid_from_solve(const io::SolveResults &results, const PairInfo &pair,
                            const std::vector<double> &torques, const std::string &parameter);

  /// From a mesh table (docs/mesh-tables.md) at `torques` (empty: a stiffness or STE table's
  /// own load nodes), on the table's theta nodes:
  /// - torque table T(theta, delta): STE = the compression delta at which T(theta_i, .) = T,
  ///   the inverse of the piecewise-linear T along delta (exact for the bilinear TableLaw);
  /// - stiffness table k(theta, F): k at F = T / r_b1, linear in F (a copy at a load node),
  ///   STE = F / k;
  /// - STE table STE(theta, T): STE linear in T (a copy at a node), k = F / STE.
  /// Throws InputError naming `parameter` for a torque outside what every theta reaches.
  CycleGrid grid_from_table(const io::MeshTable &table, const PairInfo &pair,
                            const std::vector<double> &torques, const std::string &parameter);

  /// y(xq) of the periodic piecewise-linear interpolant through (x_i, y_i), x strictly
  /// increasing within one period (the segment from the last node wraps to x_0 + period).
  double periodic_linear(const std::vector<double> &x, const std::vector<double> &y, double period, double xq);
} // namespace gearfem::exports
