#include "post/observers.h"

namespace gearfem::post
{
  FeSolver::FeSolver(contact::GearContactModel &model, const PostOptions &options, std::vector<double> friction)
    : solver_(model, std::move(friction))
    , evaluator_(model, options)
    , contact_before_(contact::section_seconds(model.timer(), "contact"))
  {}

  double FeSolver::seconds(const std::string &phase) const
  {
    if (phase == "contact")
      return contact::section_seconds(solver_.model().timer(), "contact") - contact_before_;
    return contact::section_seconds(evaluator_.timer(), phase);
  }

  EvaluatingObserver::EvaluatingObserver(Evaluator &evaluator, std::vector<PositionObserver *> observers)
    : evaluate_([&evaluator](const loading::SweepPoint &, const contact::ContactState &s, bool fields) {
      return evaluator(s, fields);
    })
    , output_timer_(evaluator.timer())
    , observers_(std::move(observers))
  {}

  EvaluatingObserver::EvaluatingObserver(PointSolver &solver, dealii::TimerOutput &output_timer,
                                         std::vector<PositionObserver *> observers)
    : evaluate_([&solver](const loading::SweepPoint &p, const contact::ContactState &s, bool fields) {
      return solver.evaluate(p, s, fields);
    })
    , output_timer_(output_timer)
    , observers_(std::move(observers))
  {}

  void EvaluatingObserver::finished(const loading::SweepPoint &p, const contact::ContactState &s)
  {
    bool fields = false;
    for (const auto *o : observers_)
      fields = fields || o->wants_fields(p);
    PositionResult r = evaluate_(p, s, fields);
    dealii::TimerOutput::Scope scope(output_timer_, "output");
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
