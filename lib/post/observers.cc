#include "post/observers.h"

namespace gearfem::post
{
  void EvaluatingObserver::finished(const loading::SweepPoint &p, const contact::ContactState &s)
  {
    bool fields = false;
    for (const auto *o : observers_)
      fields = fields || o->wants_fields(p);
    PositionResult r = evaluator_(s, fields);
    dealii::TimerOutput::Scope scope(evaluator_.timer(), "output");
    for (auto *o : observers_)
      o->finished(p, s, r);
  }

  bool EvaluatingObserver::stop_requested() const
  {
    for (const auto *o : observers_)
      if (o->stop_requested())
        return true;
    return false;
  }
} // namespace gearfem::post
