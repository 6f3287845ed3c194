#include "loading/sweep.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::loading
{
  std::vector<double> pack_warm_start(const contact::ContactSolution &s)
  {
    std::vector<double> v = {s.q, s.load, 0.0};
    for (const auto &p : s.points)
      if (p.force != 0)
        {
          v.insert(v.end(), {double(p.slave_body), double(p.node), p.force});
          v[2] += 1;
        }
    for (const auto &f : s.forces)
      {
        v.push_back(double(f.size()));
        for (const auto &[dof, value] : f)
          v.insert(v.end(), {double(dof), value});
      }
    return v;
  }

  contact::ContactSolution unpack_warm_start(const std::vector<double> &v)
  {
    contact::ContactSolution s;
    auto bad = [] { return InputError("checkpoint warm start", "malformed", "a packed contact state"); };
    std::size_t i = 0;
    auto next = [&]() {
      if (i >= v.size())
        throw bad();
      return v[i++];
    };
    auto count = [&]() {
      const double n = next();
      if (!(n >= 0) || n != std::floor(n) || n > double(v.size()))
        throw bad();
      return std::size_t(n);
    };
    s.converged = true;
    s.q         = next();
    s.load      = next();
    const std::size_t np = count();
    for (std::size_t k = 0; k < np; ++k)
      {
        contact::ContactPoint p;
        p.x = p.normal = p.master_point = geometry::Vec2::Zero(); // not read by a warm start
        p.slave_body = int(next());
        p.node       = int(next());
        p.force      = next();
        if ((p.slave_body != 1 && p.slave_body != 2) || p.node < 0)
          throw bad();
        s.points.push_back(p);
      }
    for (auto &f : s.forces)
      {
        const std::size_t n = count();
        for (std::size_t k = 0; k < n; ++k)
          {
            const auto dof = static_cast<unsigned int>(next());
            f.emplace_back(dof, next());
          }
      }
    if (i != v.size())
      throw bad();
    return s;
  }

  contact::ContactState ModelSolver::solve(const SweepPoint &p, const contact::ContactSolution *warm)
  {
    if (!friction_.empty())
      model_.contact_solver().set_friction(friction_.at(p.torque_index));
    return model_.solve(p.phi1, p.torque, warm);
  }

  SweepOutcome run_sweep(contact::GearContactModel &model, const SweepPlan &plan,
                         const std::vector<SweepObserver *> &observers, const SweepStart &start)
  {
    ModelSolver solver(model, plan.friction);
    return run_sweep(solver, plan, observers, start);
  }

  SweepOutcome run_sweep(PositionSolver &solver, const SweepPlan &plan, const std::vector<SweepObserver *> &observers,
                         const SweepStart &start)
  {
    SweepOutcome outcome;
    const std::size_t np = plan.positions.size(), total = plan.size();
    contact::ContactSolution prev;
    bool have_prev = false;
    if (start.have_warm && start.next > 0 && start.next < total && start.next % np != 0)
      {
        prev      = start.warm;
        have_prev = true;
      }
    for (std::size_t k = start.next; k < total; ++k)
      {
        SweepPoint p;
        p.index = k, p.total = total;
        p.torque_index = k / np, p.position_index = k % np;
        p.torque = plan.torques[p.torque_index];
        p.name   = plan.positions[p.position_index].first;
        p.phi1   = plan.positions[p.position_index].second;
        if (p.position_index == 0)
          have_prev = false; // each torque starts cold, from the first position
        contact::ContactState s;
        try
          {
            s = solver.solve(p, have_prev ? &prev : nullptr);
          }
        catch (const SolverError &e)
          {
            outcome.failure      = e.what();
            outcome.failed_point = p;
            return outcome;
          }
        for (auto *o : observers)
          o->finished(p, s);
        ++outcome.finished;
        for (const auto *o : observers)
          if (o->stop_requested())
            {
              outcome.stopped = true;
              return outcome;
            }
        prev      = std::move(s.solution);
        have_prev = true;
      }
    return outcome;
  }
} // namespace gearfem::loading
