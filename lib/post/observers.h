#pragma once
// Post-processing inside a loading sweep: one sweep observer (EvaluatingObserver) turns each
// converged contact state into a PositionResult once and hands both to the position
// observers (results tables, VTU, journal, progress), which run in timer section "output". The
// evaluation is the PointSolver's: the FE model's with post::Evaluator (FeSolver, timer section
// "post"), or a condensed cycle's (condensed/resolve.h). A batch driver or an optimiser adds its
// own PositionObserver to get the evaluated results of a sweep.
#include "loading/sweep.h"
#include "post/position.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gearfem::post
{
  class PositionObserver
  {
  public:
    virtual ~PositionObserver() = default;
    /// True if the displacement fields of this point are wanted (VTU output).
    virtual bool wants_fields(const loading::SweepPoint &) const { return false; }
    /// An evaluated position. `r` may be modified (e.g. its fields released) by an observer
    /// that has used them; observers run in the order given.
    virtual void finished(const loading::SweepPoint &p, const contact::ContactState &s, PositionResult &r) = 0;
    /// True ends the sweep after this point (loading::SweepObserver::stop_requested).
    virtual bool stop_requested() const { return false; }
  };

  /// A position solver that also evaluates the states it solved: the backend of the one sweep
  /// of a solve (solve::run_points).
  class PointSolver : public loading::PositionSolver
  {
  public:
    /// The evaluation of state `s` of point `p`, the last one solved; with `fields` the
    /// displacement fields are kept (only where has_fields()).
    virtual PositionResult evaluate(const loading::SweepPoint &p, const contact::ContactState &s, bool fields) = 0;
    /// The model whose displacement fields evaluate() can keep (VTU output); null: none.
    virtual const contact::GearContactModel *field_model() const { return nullptr; }
    bool has_fields() const { return field_model() != nullptr; }
    /// Wall time [s] of the solves ("contact") and of the evaluations ("post") so far.
    virtual double seconds(const std::string &phase) const = 0;
  };

  /// The FE backend: the model's solve (loading::ModelSolver) and post's Evaluator.
  class FeSolver : public PointSolver
  {
  public:
    FeSolver(contact::GearContactModel &model, const PostOptions &options, std::vector<double> friction = {});
    contact::ContactState solve(const loading::SweepPoint &p, const contact::ContactSolution *warm) override
    {
      return solver_.solve(p, warm);
    }
    PositionResult evaluate(const loading::SweepPoint &, const contact::ContactState &s, bool fields) override
    {
      return evaluator_(s, fields);
    }
    const contact::GearContactModel *field_model() const override { return &solver_.model(); }
    double seconds(const std::string &phase) const override;
    contact::GearContactModel &model() const { return solver_.model(); }

  private:
    loading::ModelSolver solver_;
    Evaluator evaluator_;
    double contact_before_;
  };

  class EvaluatingObserver : public loading::SweepObserver
  {
  public:
    /// Evaluates with `evaluator` (timer section "post"); the observers run in its timer's
    /// section "output".
    EvaluatingObserver(Evaluator &evaluator, std::vector<PositionObserver *> observers);
    /// Evaluates with `solver`; the observers run in section "output" of `output_timer`.
    EvaluatingObserver(PointSolver &solver, dealii::TimerOutput &output_timer, std::vector<PositionObserver *> observers);
    void finished(const loading::SweepPoint &p, const contact::ContactState &s) override;
    bool stop_requested() const override;

  private:
    std::function<PositionResult(const loading::SweepPoint &, const contact::ContactState &, bool)> evaluate_;
    dealii::TimerOutput &output_timer_;
    std::vector<PositionObserver *> observers_;
  };
} // namespace gearfem::post
