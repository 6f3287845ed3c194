#pragma once
// The quasi-static sweep over the mesh cycle: torques x positions of a GearContactModel,
// with torque targeting per position (GearContactModel::solve), warm starts along each
// torque's positions, and failure handling. Each converged contact state goes to the
// observers (post-processing, which feeds the output tables, VTU files, progress and the
// checkpoint journal); the sweep itself evaluates and writes nothing (loading does not
// depend on post). A sweep can start from a checkpoint (SweepStart): the positions before
// it are skipped and the warm start is the one the uninterrupted run had, so the resumed
// results equal those of an uninterrupted run to the contact tolerance.
#include "contact/gear_contact.h"

#include <string>
#include <utility>
#include <vector>

namespace gearfem::loading
{
  /// What to solve: every position for each torque, torques in the given order.
  struct SweepPlan
  {
    std::vector<std::pair<std::string, double>> positions; ///< (name or "", pinion roll phi1 [rad])
    std::vector<double> torques;                           ///< pinion torques T1 [N m]
    /// Friction coefficient per torque (a load-dependent law); empty: the model's own.
    std::vector<double> friction;
    std::size_t size() const { return positions.size() * torques.size(); }
  };

  /// One point of the plan; `index` = torque_index * n_positions + position_index.
  struct SweepPoint
  {
    std::size_t index = 0, torque_index = 0, position_index = 0, total = 0;
    double torque = 0, phi1 = 0;
    std::string name;
  };

  class SweepObserver
  {
  public:
    virtual ~SweepObserver() = default;
    /// A converged position; observers run in the order given. The state is the warm start
    /// of the next position of the same torque.
    virtual void finished(const SweepPoint &p, const contact::ContactState &s) = 0;
    /// Asked after every point has reached all observers: true ends the sweep there
    /// (SweepOutcome::stopped), e.g. when the torques done already show that the run will be
    /// discarded.
    virtual bool stop_requested() const { return false; }
  };

  /// Where a sweep starts: the first point to solve and the warm start it would have had.
  struct SweepStart
  {
    std::size_t next = 0;                ///< points 0 .. next-1 are done
    bool have_warm   = false;            ///< false: cold start (first position of a torque)
    contact::ContactSolution warm;       ///< the converged state of point next-1
  };

  struct SweepOutcome
  {
    std::size_t finished = 0; ///< points finished in this call
    bool stopped         = false; ///< an observer asked to stop (not a failure)
    std::string failure;      ///< empty, or the SolverError message of the point that failed
    SweepPoint failed_point;  ///< valid when failure is not empty
  };

  /// The part of a converged state that a warm start reads (q, load, the slave forces and
  /// the nodal forces of both bodies), as numbers for a checkpoint, and back. Exact.
  std::vector<double> pack_warm_start(const contact::ContactSolution &s);
  /// Throws InputError if `v` is not a packed warm start.
  contact::ContactSolution unpack_warm_start(const std::vector<double> &v);

  /// What solves the points of a sweep: the FE model (ModelSolver), or a condensed cycle's
  /// re-solve (condensed/resolve.h: CycleSolver), behind the one sweep loop run_sweep.
  class PositionSolver
  {
  public:
    virtual ~PositionSolver() = default;
    /// The converged state of point p from `warm`, the solution of the previous point of the
    /// same torque (null: a cold start; a backend without warm starts ignores it). Throws
    /// SolverError when the point does not converge.
    virtual contact::ContactState solve(const SweepPoint &p, const contact::ContactSolution *warm) = 0;
  };

  /// The FE backend: GearContactModel::solve, with the friction coefficient of each torque of
  /// `friction` (SweepPlan::friction; empty: the model's own).
  class ModelSolver : public PositionSolver
  {
  public:
    explicit ModelSolver(contact::GearContactModel &model, std::vector<double> friction = {})
      : model_(model), friction_(std::move(friction))
    {}
    contact::ContactState solve(const SweepPoint &p, const contact::ContactSolution *warm) override;
    contact::GearContactModel &model() const { return model_; }

  private:
    contact::GearContactModel &model_;
    std::vector<double> friction_;
  };

  /// The one sweep loop: run the plan from `start` on `solver`, each torque's positions warm
  /// started from the previous one (cold at its first), every converged point handed to the
  /// observers in order. A SolverError at a point stops the sweep and is returned in the
  /// outcome (the finished points have reached the observers); other exceptions propagate.
  SweepOutcome run_sweep(PositionSolver &solver, const SweepPlan &plan, const std::vector<SweepObserver *> &observers,
                         const SweepStart &start = SweepStart());
  /// The same on the FE model (ModelSolver with the plan's friction coefficients).
  SweepOutcome run_sweep(contact::GearContactModel &model, const SweepPlan &plan,
                         const std::vector<SweepObserver *> &observers,
                         const SweepStart &start = SweepStart());
} // namespace gearfem::loading
