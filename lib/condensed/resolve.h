#pragma once
// Re-solving on a condensed cycle (condensed/cycle.h): any torque list and any gap-route
// micro-geometry of a design whose meshed geometry, mesh, material and contact options are
// those of the cycle. Each position is a dense complementarity problem on the stored
// candidates (contact::solve_condensed); the evaluation is post's, with the root stress from
// the stored influence coefficients instead of a displacement field. The run writes the same
// sweep.csv, pairs.csv, pressure.csv, line_of_action.csv and results.h5 as `gearfem solve`
// (no VTU: the condensed route keeps no field).
#include "condensed/cycle.h"
#include "post/position.h"
#include "solve/run.h"

#include <Eigen/Dense>

#include <vector>

namespace gearfem::condensed
{
  /// One re-solved position.
  struct Resolved
  {
    contact::ContactState state;
    post::PositionResult result;
  };

  /// The gap offsets [m] of the tip reliefs of `pair` at the candidates of `p` (zero without
  /// reliefs): what the full solver adds on the gap route (Contact/Micro-geometry = gap).
  Eigen::VectorXd relief_offsets(const contact::CondensedPosition &p, const geometry::GearPair &pair);

  class Resolver
  {
  public:
    /// Checks that `variant` can be re-solved on `cycle` (InputError naming what differs:
    /// the model key, a position the cycle does not hold, a relief meshed as geometry). Both
    /// must outlive the resolver.
    Resolver(const CondensedCycle &cycle, const solve::GearContactInput &variant);
    /// Index in the cycle of each position of the variant's `Solve` section.
    const std::vector<std::size_t> &positions() const { return index_; }
    /// Gap offsets of the variant's micro-geometry at the candidates of stored configuration
    /// `p` [m] (of the first scene of position k).
    Eigen::VectorXd offsets(const contact::CondensedPosition &p) const;
    Eigen::VectorXd offsets(std::size_t k) const;
    /// Re-solve cycle position k at pinion torque T1 [N m] (> 0) and evaluate it. SolverError
    /// when the complementarity problem fails or the contact leaves the stored candidates.
    Resolved solve(std::size_t k, double torque, const post::PostOptions &options) const;
    /// The same with given offsets at the candidates of cycle.at(k, torque) (e.g. a
    /// manufacturing deviation on top of the relief).
    Resolved solve(std::size_t k, double torque, const Eigen::VectorXd &offsets,
                   const post::PostOptions &options) const;
    /// The same with a drive advance per candidate [rad] (contact::solve_condensed; empty:
    /// none): teeth turned rigidly by manufacturing deviations (deviations/hunting.h).
    Resolved solve(std::size_t k, double torque, const Eigen::VectorXd &offsets, const Eigen::VectorXd &advance,
                   const post::PostOptions &options) const;
    /// Evaluate solution `cs` of stored configuration `p` of cycle position k at pinion torque
    /// T1 [N m] (post's evaluation, root stresses from the stored influence coefficients,
    /// equilibrium moments): what solve() does after the complementarity solve, for a caller
    /// that solves the configuration itself (helical/slicing.h).
    Resolved evaluate(std::size_t k, const contact::CondensedPosition &p, double torque,
                      contact::CondensedSolution cs, const post::PostOptions &options) const;

  private:
    /// Peak fillet sigma_1 of tooth `tooth` of body b under universe forces f: (value, radius).
    std::pair<double, double> root_stress(int b, int tooth, const std::vector<std::pair<int, double>> &f) const;
    const CondensedCycle &cycle_;
    const solve::GearContactInput &in_;
    std::vector<std::size_t> index_;
    std::vector<int> column_[2]; ///< universe index -> column of the stress influence (-1)
    fem::Elasticity material_[2];
  };

  /// The condensed backend of the one sweep of a solve (solve::run_points): point p is cycle
  /// position resolver.positions()[p.position_index] of the variant at p.torque, re-solved and
  /// evaluated at once (no warm start: each re-solve is exact on its own).
  class CycleSolver : public post::PointSolver
  {
  public:
    CycleSolver(const Resolver &resolver, const post::PostOptions &options)
      : resolver_(resolver), options_(options)
    {}
    contact::ContactState solve(const loading::SweepPoint &p, const contact::ContactSolution *warm) override;
    post::PositionResult evaluate(const loading::SweepPoint &, const contact::ContactState &, bool) override
    {
      return std::move(last_);
    }
    double seconds(const std::string &phase) const override
    {
      return phase == "contact" ? contact_ : phase == "post" ? post_ : 0.0;
    }

  protected:
    /// The re-solve of point p; a subclass adds its own offsets (deviations/hunting.h).
    virtual Resolved resolve(const loading::SweepPoint &p);
    const Resolver &resolver_;
    post::PostOptions options_;

  private:
    post::PositionResult last_;
    double contact_ = 0, post_ = 0;
  };

  /// The `solve` run of `variant` on `cycle`: solve::run_points on a CycleSolver, every torque
  /// x position, with progress, written to options.output_dir like solve::run_solve (also
  /// after a failure, with the finished positions). No journal: a condensed run takes
  /// milliseconds.
  solve::SolveRunResult run_condensed(const CondensedCycle &cycle, const solve::GearContactInput &variant,
                                      const solve::SolveRunOptions &options);
} // namespace gearfem::condensed
