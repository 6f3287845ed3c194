// The report of a tip-relief study (relief.h): summary table, optimise.csv, ste.csv,
// summary.md and optimum.prm, each written atomically.
#include "base/atomic_file.h"
#include "base/errors.h"
#include "optimise/relief.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace gearfem::optimise
{
  namespace
  {

    /// Design vector in engineering units: amounts [um], lengths [mm].
    std::vector<double> engineering(const std::vector<double> &x)
    {
      std::vector<double> v(x.size());
      for (std::size_t i = 0; i < x.size(); ++i)
        v[i] = x[i] * (i % 2 == 0 ? 1e6 : 1e3);
      return v;
    }

    std::string torque_list(const ReliefProblem &p)
    {
      std::string s;
      for (std::size_t k = 0; k < p.torques.size(); ++k)
        s += (k ? ", " : "") + to_string_g(p.torques[k]) +
             (p.weights.empty() || p.aggregate == TorqueAggregate::maximum ? "" : " (w " + to_string_g(p.weights[k]) + ")");
      return s + " N m";
    }

    /// The check at other torques: p-p of each design (rows) at each check torque.
    void print_check_table(const ReliefStudy &s, const ReliefStudyResult &r, std::ostream &out)
    {
      if (r.check.empty())
        return;
      const auto &t = s.problem.check_torques;
      out << "\nPeak-to-peak STE [um] at the check torques (" << to_string(s.problem.measure)
          << " objective aside), on the same model:\n\n| design | ";
      for (const double T : t)
        out << to_string_g(T) << " N m | ";
      out << "worst |\n|---|";
      for (std::size_t k = 0; k <= t.size(); ++k)
        out << "---|";
      out << "\n";
      for (const auto &c : r.check)
        {
          out << "| " << c.design << " | ";
          double worst = 0;
          for (std::size_t k = 0; k < t.size(); ++k)
            {
              out << (c.result.ok ? to_string_g(c.result.peak_to_peak[k], 4) : std::string("–")) << " | ";
              worst = c.result.ok ? std::max(worst, c.result.peak_to_peak[k]) : worst;
            }
          out << (c.result.ok ? to_string_g(worst, 4) : std::string("failed")) << " |\n";
        }
    }

    /// Column k of a study torque in a run's results (-1: not evaluated at that torque).
    int torque_column(const ReliefRun &run, double T)
    {
      for (std::size_t k = 0; k < run.torques.size(); ++k)
        if (run.torques[k] == T)
          return static_cast<int>(k);
      return -1;
    }
  } // namespace

  void print_relief_summary(const ReliefStudy &s, const ReliefStudyResult &r, std::ostream &out)
  {
    const auto &p = s.problem;
    out << "Objective: " << to_string(p.measure) << " STE, " << to_string(p.aggregate) << " over " << torque_list(p)
        << "; " << (p.kind == geometry::TipRelief::Kind::linear ? "linear" : "parabolic") << " tip relief, "
        << (p.per_gear ? "per gear" : "the same on both gears") << "; box C_a " << to_string_g(p.amount_min * 1e6) << "-"
        << to_string_g(p.amount_max * 1e6) << " um, L " << to_string_g(p.length_min * 1e3) << "-" << to_string_g(p.length_max * 1e3) << " mm; "
        << p.positions << " positions per mesh cycle; model set-up " << to_string_g(r.setup_seconds, 3) << " s (once)"
        << (r.condensed ? "; designs evaluated on a condensed cycle of the model (built in " + to_string_g(r.cycle_seconds, 3) +
                            " s; " + std::to_string(r.fallbacks) + " evaluations fell back to the full FE sweep)" :
                          std::string())
        << ".\n\n| design | ";
    for (const auto &n : p.variable_names())
      out << n << (n[0] == 'C' ? " [um]" : " [mm]") << " | ";
    out << "objective [um] | ";
    for (const double T : p.torques)
      out << "p-p at " << to_string_g(T) << " N m [um] | H1 at " << to_string_g(T) << " N m [um] | ";
    out << "FE evaluations | wall time [s] |\n|---|";
    for (std::size_t i = 0; i < p.variable_names().size() + 1 + 2 * p.torques.size() + 2; ++i)
      out << "---|";
    out << "\n";
    auto row = [&](const std::string &name, const ReliefRow &row, const std::string &ev, const std::string &t) {
      out << "| " << name << " | ";
      const bool none = name == "no relief";
      for (const double v : engineering(row.x))
        out << (none ? std::string("0") : to_string_g(v, 4)) << " | ";
      out << (row.result.ok ? to_string_g(row.result.objective, 4) : std::string("–")) << " | ";
      for (std::size_t k = 0; k < p.torques.size(); ++k) // a failed sweep: dashes, never NaN
        out << (row.result.ok ? to_string_g(row.result.peak_to_peak.at(k), 4) + " | " + to_string_g(row.result.harmonic.at(k), 4)
                              : std::string("– | –"))
            << " | ";
      out << ev << " | " << t << " |\n";
    };
    row("no relief", r.unrelieved, "1", to_string_g(r.unrelieved.result.seconds, 3));
    row("start", r.optimiser.history.front(), "1", to_string_g(r.optimiser.history.front().result.seconds, 3));
    row("optimum (" + r.optimiser.name + ")", r.optimiser.best_row(), std::to_string(r.optimiser.history.size()),
        to_string_g(r.optimiser.seconds, 3));
    if (r.grid.best >= 0)
      row("best of " + r.grid.name, r.grid.best_row(), std::to_string(r.grid.history.size()), to_string_g(r.grid.seconds, 3));
    for (const auto &single : r.single)
      {
        ReliefRow at_study;
        at_study.x      = single.run.best_row().x;
        at_study.result = single.at_study;
        row("optimum at " + to_string_g(single.torque) + " N m alone (" + r.optimiser.name + ")", at_study,
            std::to_string(single.run.history.size()) + " + 1", to_string_g(single.run.seconds + single.at_study.seconds, 3));
      }
    out << "\nOptimiser stop: " << r.optimiser.stop_reason << ".";
    if (!r.single.empty())
      out << " The single-load optima were optimised at their torque alone, then evaluated at every torque "
             "(+ 1 FE evaluation); their objective is the study's.";
    out << "\n";
    print_check_table(s, r, out);
  }

  void write_check_csv(const ReliefStudy &s, const ReliefStudyResult &r, const std::filesystem::path &file)
  {
    const auto &p = s.problem;
    AtomicOutputFile f(file);
    auto &o = f.stream();
    o << "design";
    for (const auto &n : p.variable_names())
      o << ',' << n << (n[0] == 'C' ? " [um]" : " [mm]");
    o << ",torque [N m],ok,p-p [um],H1 [um],mean STE [um],sweep time [s]\n";
    for (const auto &c : r.check)
      for (std::size_t k = 0; k < p.check_torques.size(); ++k)
        {
          o << c.design;
          for (const double v : engineering(c.x))
            o << ',' << to_string_g(c.design == "no relief" ? 0.0 : v, 10);
          // A failed sweep: ok 0 and empty cells, never NaN.
          const bool ok = c.result.ok;
          o << ',' << to_string_g(p.check_torques[k]) << ',' << (ok ? 1 : 0) << ','
            << (ok ? to_string_g(c.result.peak_to_peak[k], 10) : "") << ',' << (ok ? to_string_g(c.result.harmonic[k], 10) : "") << ','
            << (ok ? to_string_g(c.result.mean[k], 10) : "") << ',' << to_string_g(c.result.seconds, 6) << '\n';
        }
    f.commit();
  }

  void write_relief_study(const ReliefStudy &s, const ReliefStudyResult &r, const std::filesystem::path &dir)
  {
    const auto &p = s.problem;
    {
      AtomicOutputFile f(dir / "optimise.csv");
      auto &o = f.stream();
      o << "run,evaluation";
      for (const auto &n : p.variable_names())
        o << ',' << n << (n[0] == 'C' ? " [um]" : " [mm]");
      o << ",ok,objective [um],best [um]";
      for (const double T : p.torques)
        o << ",p-p at " << to_string_g(T) << " N m [um],H1 at " << to_string_g(T) << " N m [um]";
      o << ",sweep time [s],time [s]\n";
      std::vector<const ReliefRun *> runs = {&r.optimiser, &r.grid};
      for (const auto &single : r.single)
        runs.push_back(&single.run);
      for (const ReliefRun *run : runs)
        for (const auto &h : run->history)
          {
            o << run->name << ',' << h.evaluation;
            for (const double v : engineering(h.x))
              o << ',' << to_string_g(v, 10);
            // A failed sweep has no objective: empty cells, never NaN.
            o << ',' << (h.result.ok ? 1 : 0) << ',' << (h.result.ok ? to_string_g(h.result.objective, 10) : "") << ','
              << to_string_g(h.best, 10);
            // A single-load run has figures at its own torque only: the other cells empty.
            for (const double T : p.torques)
              {
                const int k    = torque_column(*run, T);
                const bool has = h.result.ok && k >= 0;
                o << ',' << (has ? to_string_g(h.result.peak_to_peak[k], 10) : "") << ','
                  << (has ? to_string_g(h.result.harmonic[k], 10) : "");
              }
            o << ',' << to_string_g(h.result.seconds, 6) << ',' << to_string_g(h.seconds, 6) << '\n';
          }
      f.commit();
    }
    {
      // The STE cycles over one mesh cycle from A: before (no relief, start) and after.
      AtomicOutputFile f(dir / "ste.csv");
      auto &o = f.stream();
      o << "design,torque [N m],position,cycle fraction,STE [um]\n";
      auto put = [&](const std::string &name, const ReliefRow &row) {
        for (std::size_t k = 0; k < row.result.ste.size(); ++k)
          for (std::size_t i = 0; i < row.result.ste[k].size(); ++i)
            o << name << ',' << to_string_g(p.torques[k]) << ',' << i << ',' << to_string_g(double(i) / double(row.result.ste[k].size()))
              << ',' << to_string_g(row.result.ste[k][i], 10) << '\n';
      };
      put("no relief", r.unrelieved);
      put("start", r.optimiser.history.front());
      put("optimum", r.optimiser.best_row());
      if (r.grid.best >= 0)
        put("grid best", r.grid.best_row());
      for (const auto &single : r.single)
        {
          ReliefRow at_study;
          at_study.result = single.at_study;
          put("optimum at " + to_string_g(single.torque) + " N m", at_study);
        }
      f.commit();
    }
    if (!r.check.empty())
      write_check_csv(s, r, dir / "robust.csv");
    {
      AtomicOutputFile f(dir / "summary.md");
      f.stream() << "# Tip-relief optimisation (gearfem optimise, Problem = tip relief)\n\n";
      print_relief_summary(s, r, f.stream());
      f.commit();
    }
    {
      const auto &best = r.optimiser.best_row();
      AtomicOutputFile f(dir / "optimum.prm");
      f.stream() << "# gearfem solve\n# Tip-relief optimum by " << r.optimiser.name << " (gearfem optimise): "
                 << to_string(p.measure) << " STE " << to_string_g(best.result.objective, 5) << " um, " << to_string(p.aggregate)
                 << " over " << torque_list(p) << ".\n"
                 << s.solve_case(best.x);
      f.commit();
    }
  }
} // namespace gearfem::optimise
