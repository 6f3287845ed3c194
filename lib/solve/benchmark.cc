// The solve benchmark.
#include "solve/benchmark.h"

#include "base/errors.h"
#include "base/memory.h"
#include "solve/input.h"
#include "loading/sweep.h"
#include "post/observers.h"
#include "post/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace gearfem::solve
{
  using post::EvaluatingObserver;
  using post::Evaluator;
  using post::PositionObserver;
  using post::PositionResult;
  using post::PostOptions;

  namespace
  {
    /// Sums the per-position figures of a sweep.
    class Totals : public PositionObserver
    {
    public:
      void finished(const loading::SweepPoint &, const contact::ContactState &s, PositionResult &r) override
      {
        ts += s.solution.t_search, tc += s.solution.t_compliance, tl += s.solution.t_solve;
        tp += r.t_post, tt += s.t_contact + r.t_post;
        git += s.solution.geometry_iterations, ait += s.solution.active_set_iterations;
        ste += r.ste, loss += r.power_loss;
      }
      double ts = 0, tc = 0, tl = 0, tp = 0, tt = 0, ste = 0, loss = 0;
      long git = 0, ait = 0;
    };
    /// One sweep of `plan` on `model` at friction coefficient mu: per-position contact +
    /// post time [s], its totals.
    Totals timed_sweep(contact::GearContactModel &model, const loading::SweepPlan &plan, const PostOptions &post,
                       double mu)
    {
      model.contact_solver().set_friction(mu);
      Evaluator evaluator(model, post);
      Totals sum;
      EvaluatingObserver evaluate(evaluator, {&sum});
      const auto outcome = loading::run_sweep(model, plan, {&evaluate});
      if (!outcome.failure.empty())
        throw SolverError(outcome.failure);
      return sum;
    }

    /// The cost of friction on a model whose flexibility columns are cached: frictionless and
    /// frictional sweeps alternated three times, the least process CPU time of each kept.
    std::string friction_cost(contact::GearContactModel &model, const loading::SweepPlan &plan,
                              const PostOptions &post, double mu)
    {
      // Process CPU time, not wall time: on a shared machine the wall time of a sweep depends
      // on the other processes more than on friction. Alternated three times, the least kept.
      Totals best0, best1;
      double cpu0 = 1e300, cpu1 = 1e300;
      for (int rep = 0; rep < 3; ++rep)
        {
          double c = process_cpu_seconds();
          const Totals a = timed_sweep(model, plan, post, 0.0);
          const double ca = process_cpu_seconds() - c;
          c = process_cpu_seconds();
          const Totals b = timed_sweep(model, plan, post, mu);
          const double cb = process_cpu_seconds() - c;
          if (ca < cpu0)
            cpu0 = ca, best0 = a;
          if (cb < cpu1)
            cpu1 = cb, best1 = b;
        }
      model.contact_solver().set_friction(0.0);
      const double n = double(plan.size());
      std::ostringstream row;
      row << std::fixed << std::setprecision(4) << cpu0 / n << " | " << cpu1 / n << " | " << std::setprecision(3)
          << cpu1 / cpu0 << " | " << std::setprecision(4) << best0.ste / n * 1e6 << " / "
          << best1.ste / n * 1e6 << " | " << std::setprecision(2) << best1.loss / n << " |\n";
      return row.str();
    }
  } // namespace

  void benchmark(const std::filesystem::path &prm_file, std::ostream &out)
  {
    if (!std::filesystem::is_regular_file(prm_file))
      throw InputError("input file", prm_file.string(), "an existing readable file");
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
    post::declare_post_parameters(prm);
    prm.parse_input(prm_file.string(), "", true, false); // other commands' sections are ignored
    solve::GearContactInput in = solve::parse_gear_contact_input(prm);
    in.require_external("gearfem bench solve");
    PostOptions post_options = post::parse_post_parameters(prm);
    post_options.pinion_speed = in.friction.pinion_speed;
    const auto positions = in.positions();
    const double T       = in.solve.torques.front();
    out << "solve benchmark: " << prm_file.filename().string() << ", z " << in.pair->gear(1).teeth() << "/"
        << in.pair->gear(2).teeth() << ", h_contact " << mesh::contact_size(in.mesh[0], in.pair->gear(1).parameters().rack.module) * 1e3 << " mm, Q"
        << in.fe.degree << ", " << positions.size() << " positions at T1 = " << T << " N m\n\n"
        << "| method | DoFs | mesh [s] | set-up [s] | search [s/pos] | flexibility [s/pos] | contact solve "
           "[s/pos] | post [s/pos] | total [s/pos] | sweep [s] | geometry it/pos | active-set it/pos | "
           "mean STE [um] | peak memory [MB] |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    // Friction: the input's coefficient, else 0.05.
    const double mu = in.friction_coefficients({T}).front() > 0 ? in.friction_coefficients({T}).front() : 0.05;
    in.contact.friction = 0;
    std::vector<std::string> friction_rows;
    for (const contact::Method m : {contact::Method::lagrange, contact::Method::penalty})
      {
        in.contact.method = m;
        auto model        = in.model();
        model->observe_root_stress(); // as run_solve: root stress from influence coefficients
        loading::SweepPlan plan;
        plan.positions = positions;
        plan.torques   = {T};
        Evaluator evaluator(*model, post_options);
        Totals sum;
        EvaluatingObserver evaluate(evaluator, {&sum});
        const auto outcome = loading::run_sweep(*model, plan, {&evaluate});
        if (!outcome.failure.empty())
          throw SolverError(outcome.failure);
        const double sweep = contact::section_seconds(model->timer(), "contact") +
                             contact::section_seconds(evaluator.timer(), "post") +
                             contact::section_seconds(evaluator.timer(), "output");
        const double n     = double(positions.size());
        out << std::fixed << std::setprecision(3) << "| " << contact::to_string(m) << " | " << model->n_dofs()
            << " | " << model->mesh_seconds() << " | " << model->setup_seconds() << " | " << sum.ts / n << " | "
            << sum.tc / n << " | " << sum.tl / n << " | " << sum.tp / n << " | " << sum.tt / n << " | "
            << std::setprecision(2) << sweep << " | " << sum.git / n << " | " << sum.ait / n << " | "
            << std::setprecision(4) << sum.ste / n * 1e6 << " | " << std::setprecision(0) << peak_memory_mb()
            << " |" << std::endl;
        friction_rows.push_back(friction_cost(*model, plan, post_options, mu));
      }
    out << std::defaultfloat << "\nfriction (the same model and positions, flexibility cached; mu = " << mu << "):\n\n"
        << "| method | frictionless [CPU s/pos] | with friction [CPU s/pos] | ratio | mean STE frictionless / with "
           "friction [um] | mean power loss [W] |\n|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < friction_rows.size(); ++i)
      out << std::setprecision(4) << "| " << (i == 0 ? "lagrange" : "penalty") << " | " << friction_rows[i];
    out << std::defaultfloat
        << "\nflexibility: block solves for the contact DoFs not yet cached (the first positions pay most);"
           "\nset-up: meshing, assembly and factorisation of both gears (once per run).\n"
           "Targets (2-core machine, mesh level with <= 1 % STE error): <= 5 s per position, <= 3 min per "
           "40-position cycle.\n";
  }
} // namespace gearfem::solve
