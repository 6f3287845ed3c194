// Route::target (route/route.h): choose the model, prove it at sample positions, refine, then
// sweep the accepted level, in full or on a condensed cycle (model_choice/to_target.h,
// model_choice/route.h).
#include "route/detail.h"

#include "base/errors.h"
#include "base/memory.h"
#include "model_choice/route.h"
#include "model_choice/target.h"
#include "model_choice/to_target.h"

#include <chrono>

namespace gearfem::route::detail
{
  void run_target(Request &r, Outcome &o)
  {
    if (r.validate_only)
      return;
    solve::GearContactInput &in               = r.input;
    const model_choice::AccuracyTarget target = model_choice::parse_target(in.solve.target);
    std::ostream *out                         = r.out;
    model_choice::TargetOptions options;
    options.cost_cap = in.solve.cost_cap;
    options.post     = r.post;
    options.out      = out;
    if (out)
      *out << "model choice: target " << model_choice::to_string(target) << ", cost cap " << in.solve.cost_cap
           << " s" << std::endl;
    const model_choice::FixedSettings &fixed = r.fixed;
    model_choice::TargetOutcome to           = model_choice::run_to_target(in, target, fixed, options);
    for (;;)
      {
        // A second sweep records its own cost.
        auto &m = o.record;
        m.erase(std::remove_if(m.begin(), m.end(),
                               [](const auto &e) { return e.first == "cost" || e.first == "friction"; }),
                m.end());
        const double cpu_setup = process_cpu_seconds();
        const auto t0          = std::chrono::steady_clock::now();
        model_choice::CycleSweep cs = model_choice::sweep_on_cycle(to, in, fixed, options, run_options(r), r.resume);
        const model_choice::Swept how = cs.how;
        const bool on_cycle           = how == model_choice::Swept::on_cycle;
        solve::SolveRunResult res     = std::move(cs.result);
        if (on_cycle)
          res = report_condensed(std::move(res), r, o, cpu_setup, cs.dofs, cs.build_seconds);
        if (how == model_choice::Swept::full_fe)
          {
            // The p-p check after each torque: a sweep the torques done already condemn stops.
            const auto check = [&](std::size_t t, const Table &sweep, double seconds) {
              return !model_choice::abandon_sweep(to, in, fixed, options,
                                                  model_choice::swept_pp(sweep, in.solve.torques), t + 1, seconds);
            };
            res = full_fe_sweep(*to.model, r, o,
                                {to.model->setup_seconds(), cpu_setup, to.model->mesh_seconds(), ""}, check);
          }
        if (!o.failure.empty())
          {
            o.run = std::move(res);
            return;
          }
        const model_choice::SweptPp swept = model_choice::swept_pp(res.results.sweep, in.solve.torques);
        model_choice::rescale_pp(to, swept);
        if (on_cycle)
          model_choice::add_condensation_error(
            to, model_choice::condensation_error(*to.model, in, res.results.sweep, r.post));
        const double seconds =
          how != model_choice::Swept::full_fe ?
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() :
            res.seconds.at("contact") + res.seconds.at("post");
        o.run = std::move(res);
        if (!model_choice::refine_after_sweep(to, in, fixed, options, seconds,
                                              o.run.stopped ? swept.pp.size() : 0))
          break;
      }
    if (out)
      *out << "\n" << model_choice::model_choice_summary(to);
    set_member(o.record, "model_choice", model_choice::model_choice_json(to));
    o.why += "; the delivered sweep: " + to.route + (to.route_why.empty() ? "" : " (" + to.route_why + ")");
    if (!to.met && out)
      *out << "warning: Solve/Target not met (" << to.stop_reason
           << "); the results are those of the finest level, with the estimates above\n";
  }
} // namespace gearfem::route::detail
