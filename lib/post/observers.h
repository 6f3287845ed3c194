#pragma once
// Post-processing inside a loading sweep: one sweep observer (EvaluatingObserver) turns each
// converged contact state into a PositionResult once (post::Evaluator, timer section
// "post") and hands both to the position observers (results tables, VTU, journal, progress),
// which run in timer section "output". A batch driver or an optimiser adds its own
// PositionObserver to get the evaluated results of a sweep.
#include "loading/sweep.h"
#include "post/position.h"

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

  class EvaluatingObserver : public loading::SweepObserver
  {
  public:
    EvaluatingObserver(Evaluator &evaluator, std::vector<PositionObserver *> observers)
      : evaluator_(evaluator), observers_(std::move(observers))
    {}
    void finished(const loading::SweepPoint &p, const contact::ContactState &s) override;
    bool stop_requested() const override;

  private:
    Evaluator &evaluator_;
    std::vector<PositionObserver *> observers_;
  };
} // namespace gearfem::post
