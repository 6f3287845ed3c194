// Single-load against robust tip relief (relief.h): the optimiser at each study torque
// alone, and a set of designs evaluated over a list of torques, all on the one FE model
// (Tavakoli & Houser 1986; Palmer & Fish 2010: the best relief at one load is poor at
// another).
#include "base/errors.h"
#include "base/progress.h"
#include "optimise/relief.h"


namespace gearfem::optimise
{
  std::vector<ReliefSingleLoad> single_load_optima(ReliefModel &model, const ReliefProblem &p,
                                                   const OptimiserSettings &settings, std::ostream *out)
  {
    p.check();
    std::vector<ReliefSingleLoad> v;
    for (const double T : p.torques)
      {
        ReliefSingleLoad s;
        s.torque = T;
        s.run    = optimise_relief(model, p.at_torques({T}), settings, out);
        s.run.name += " at " + to_string_g(T) + " N m";
        // The single-load optimum at every study torque: its robust objective.
        s.at_study = model.evaluate(s.run.best_row().x, p);
        if (out)
          *out << "optimise [" << s.run.name << "]: " << s.run.history.size() << " FE evaluations, "
               << to_string_g(s.run.seconds) << " s, objective at " << to_string_g(T) << " N m "
               << to_string_g(s.run.history.front().result.objective) << " -> "
               << to_string_g(s.run.best_row().result.objective)
               << " um; at the study's torques "
               << (s.at_study.ok ? to_string_g(s.at_study.objective) + " um" : "failed: " + s.at_study.failure) << " ("
               << s.run.stop_reason << ")" << std::endl;
        v.push_back(std::move(s));
      }
    return v;
  }

  std::vector<ReliefCheck> check_designs(ReliefModel &model, const ReliefProblem &p,
                                         const std::vector<std::pair<std::string, std::vector<double>>> &designs,
                                         const std::vector<double> &torques, std::ostream *out)
  {
    const ReliefProblem pc = p.at_torques(torques);
    pc.check();
    std::vector<ReliefCheck> v;
    Progress progress(out, designs.size(), "check at " + std::to_string(torques.size()) + " torques, designs");
    for (const auto &[name, x] : designs)
      {
        ReliefCheck c;
        c.design = name;
        c.x      = x;
        c.result = model.evaluate(x, pc);
        progress.step(v.size() + 1, name + (c.result.ok ? ": worst " + to_string_g(c.result.objective) + " um"
                                                        : ": failed (" + c.result.failure + ")"));
        v.push_back(std::move(c));
      }
    return v;
  }
} // namespace gearfem::optimise
