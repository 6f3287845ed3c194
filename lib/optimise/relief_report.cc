// The report of a tip-relief study (relief.h): summary table, optimise.csv, ste.csv,
// summary.md and optimum.prm, each written atomically.
#include "base/atomic_file.h"
#include "optimise/relief.h"

#include <iomanip>
#include <sstream>

namespace gearfem::optimise
{
  namespace
  {
    std::string g(double v, int digits = 6)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << v;
      return s.str();
    }

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
        s += (k ? ", " : "") + g(p.torques[k]) +
             (p.weights.empty() || p.aggregate == TorqueAggregate::maximum ? "" : " (w " + g(p.weights[k]) + ")");
      return s + " N m";
    }
  } // namespace

  void print_relief_summary(const ReliefStudy &s, const ReliefStudyResult &r, std::ostream &out)
  {
    const auto &p = s.problem;
    out << "Objective: " << to_string(p.measure) << " STE, " << to_string(p.aggregate) << " over " << torque_list(p)
        << "; " << (p.kind == geometry::TipRelief::Kind::linear ? "linear" : "parabolic") << " tip relief, "
        << (p.per_gear ? "per gear" : "the same on both gears") << "; box C_a " << g(p.amount_min * 1e6) << "-"
        << g(p.amount_max * 1e6) << " um, L " << g(p.length_min * 1e3) << "-" << g(p.length_max * 1e3) << " mm; "
        << p.positions << " positions per mesh cycle; model set-up " << g(r.setup_seconds, 3)
        << " s (once).\n\n| design | ";
    for (const auto &n : p.variable_names())
      out << n << (n[0] == 'C' ? " [um]" : " [mm]") << " | ";
    out << "objective [um] | ";
    for (const double T : p.torques)
      out << "p-p at " << g(T) << " N m [um] | H1 at " << g(T) << " N m [um] | ";
    out << "FE evaluations | wall time [s] |\n|---|";
    for (std::size_t i = 0; i < p.variable_names().size() + 1 + 2 * p.torques.size() + 2; ++i)
      out << "---|";
    out << "\n";
    auto row = [&](const std::string &name, const ReliefRow &row, const std::string &ev, const std::string &t) {
      out << "| " << name << " | ";
      const bool none = name == "no relief";
      for (const double v : engineering(row.x))
        out << (none ? std::string("0") : g(v, 4)) << " | ";
      out << g(row.result.objective, 4) << " | ";
      for (std::size_t k = 0; k < p.torques.size(); ++k)
        out << g(row.result.peak_to_peak.at(k), 4) << " | " << g(row.result.harmonic.at(k), 4) << " | ";
      out << ev << " | " << t << " |\n";
    };
    row("no relief", r.unrelieved, "1", g(r.unrelieved.result.seconds, 3));
    row("start", r.optimiser.history.front(), "1", g(r.optimiser.history.front().result.seconds, 3));
    row("optimum (" + r.optimiser.name + ")", r.optimiser.best_row(), std::to_string(r.optimiser.history.size()),
        g(r.optimiser.seconds, 3));
    if (r.grid.best >= 0)
      row("best of " + r.grid.name, r.grid.best_row(), std::to_string(r.grid.history.size()), g(r.grid.seconds, 3));
    out << "\nOptimiser stop: " << r.optimiser.stop_reason << ".\n";
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
        o << ",p-p at " << g(T) << " N m [um],H1 at " << g(T) << " N m [um]";
      o << ",sweep time [s],time [s]\n";
      for (const ReliefRun *run : {&r.optimiser, &r.grid})
        for (const auto &h : run->history)
          {
            o << run->name << ',' << h.evaluation;
            for (const double v : engineering(h.x))
              o << ',' << g(v, 10);
            // A failed sweep has no objective: empty cells, never NaN.
            o << ',' << (h.result.ok ? 1 : 0) << ',' << (h.result.ok ? g(h.result.objective, 10) : "") << ','
              << g(h.best, 10);
            for (std::size_t k = 0; k < p.torques.size(); ++k)
              o << ',' << (h.result.ok ? g(h.result.peak_to_peak[k], 10) : "") << ','
                << (h.result.ok ? g(h.result.harmonic[k], 10) : "");
            o << ',' << g(h.result.seconds, 6) << ',' << g(h.seconds, 6) << '\n';
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
            o << name << ',' << g(p.torques[k]) << ',' << i << ',' << g(double(i) / double(row.result.ste[k].size()))
              << ',' << g(row.result.ste[k][i], 10) << '\n';
      };
      put("no relief", r.unrelieved);
      put("start", r.optimiser.history.front());
      put("optimum", r.optimiser.best_row());
      if (r.grid.best >= 0)
        put("grid best", r.grid.best_row());
      f.commit();
    }
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
                 << to_string(p.measure) << " STE " << g(best.result.objective, 5) << " um, " << to_string(p.aggregate)
                 << " over " << torque_list(p) << ".\n"
                 << s.solve_case(best.x);
      f.commit();
    }
  }
} // namespace gearfem::optimise
