// Tip-relief optimisation with the FE model in the loop (see relief.h): the problem, the
// model built once and re-targeted per evaluation, the optimiser and grid runs.
#include "optimise/relief.h"
#include "condensed/cycle.h"
#include "condensed/resolve.h"
#include "base/units.h"

#include "base/errors.h"
#include "base/progress.h"
#include "loading/sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <map>
#include <sstream>
#include <stdexcept>

namespace gearfem::optimise
{
  using geometry::TipRelief;

  const char *to_string(ReliefMeasure m)
  {
    return m == ReliefMeasure::peak_to_peak ? "peak-to-peak" : "first harmonic";
  }
  const char *to_string(TorqueAggregate a) { return a == TorqueAggregate::maximum ? "maximum" : "weighted mean"; }

  namespace
  {
    const std::string section = "Optimise/Tip relief/";
    /// Below this amount a design has no relief (build_pair wants C_a > 0) [m].
    constexpr double no_amount = 1e-9;
  } // namespace

  std::vector<double> ReliefProblem::lower() const
  {
    std::vector<double> v;
    for (int i = 0; i < n_variables() / 2; ++i)
      v.insert(v.end(), {amount_min, length_min});
    return v;
  }

  std::vector<double> ReliefProblem::upper() const
  {
    std::vector<double> v;
    for (int i = 0; i < n_variables() / 2; ++i)
      v.insert(v.end(), {amount_max, length_max});
    return v;
  }

  std::vector<double> ReliefProblem::start_point() const
  {
    if (!start.empty())
      return start;
    const auto lo = lower(), hi = upper();
    std::vector<double> x(lo.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = 0.5 * (lo[i] + hi[i]);
    return x;
  }

  std::vector<std::string> ReliefProblem::variable_names() const
  {
    if (!per_gear)
      return {"C_a", "L"};
    return {"C_a1", "L1", "C_a2", "L2"};
  }

  void ReliefProblem::check() const
  {
    if (kind == TipRelief::Kind::none)
      throw InputError(section + "Kind", "none", "linear|parabolic");
    require_range(section + "Minimum amount", amount_min * 1e6, 0.0, 1000.0, "um");
    require_range(section + "Maximum amount", amount_max * 1e6, amount_min * 1e6 + 1e-3, 1000.0, "um");
    require_range(section + "Minimum length", length_min * 1e3, 1e-3, 1000.0, "mm");
    require_range(section + "Maximum length", length_max * 1e3, length_min * 1e3 + 1e-3, 1000.0, "mm");
    if (torques.empty())
      throw InputError("Solve/Torques", "(empty)", "one or more torques > 0 N m");
    if (!weights.empty())
      {
        if (weights.size() != torques.size())
          throw InputError(section + "Torque weights", std::to_string(weights.size()) + " values",
                           std::to_string(torques.size()) + " values (one per Solve/Torques) or none");
        double sum = 0;
        for (const double w : weights)
          require_range(section + "Torque weights", w, 0.0, 1e6), sum += w;
        if (!(sum > 0))
          throw InputError(section + "Torque weights", "all 0", "at least one weight > 0");
      }
    if (single_torque_optima && torques.size() < 2)
      throw InputError(section + "Single-torque optima", "true",
                       "false while Solve/Torques has one torque (" + to_string_g(torques[0]) + " N m)",
                       "the single-load optima are compared with the robust optimum over 2 or more torques");
    if (check_torques.size() > 50)
      throw InputError(section + "Check torques", std::to_string(check_torques.size()) + " values",
                       "0 (none) to 50 torques > 0 N m");
    for (const double t : check_torques)
      require_range(section + "Check torques", t, 1e-6, 1e6, "N m");
    require_range("Solve/Number of positions", positions, 8, 1000);
    require_range(section + "Grid points", grid_points, 0, 50);
    if (grid_points == 1)
      throw InputError(section + "Grid points", "1", "0 (no grid) or 2 to 50");
    if (!start.empty())
      {
        if (static_cast<int>(start.size()) != n_variables())
          throw InputError(section + "Start point", std::to_string(start.size()) + " values",
                           std::to_string(n_variables()) + " values (" + (per_gear ? "C_a1, L1, C_a2, L2" : "C_a, L") +
                             ")");
        const auto lo = lower(), hi = upper();
        for (std::size_t i = 0; i < start.size(); ++i)
          {
            const bool amount = i % 2 == 0;
            const double s    = amount ? 1e6 : 1e3;
            require_range(section + "Start point", start[i] * s, lo[i] * s, hi[i] * s,
                          std::string(amount ? "um" : "mm") + " (" + variable_names()[i] + ")");
          }
      }
  }

  ReliefProblem ReliefProblem::at_torques(const std::vector<double> &t) const
  {
    ReliefProblem p        = *this;
    p.torques              = t;
    p.weights              = {};
    p.aggregate            = TorqueAggregate::maximum;
    p.grid_points          = 0;
    p.single_torque_optima = false;
    p.check_torques        = {};
    return p;
  }

  geometry::GeometryInput relief_geometry(const geometry::GeometryInput &geometry, const ReliefProblem &p,
                                          const std::vector<double> &x)
  {
    geometry::GeometryInput gi = geometry;
    for (int i = 0; i < 2; ++i)
      {
        const int k    = p.per_gear ? 2 * i : 0;
        TipRelief &r   = i == 0 ? gi.gear1.relief : gi.gear2.relief;
        r              = TipRelief();
        if (x.at(k) >= no_amount)
          {
            r.kind   = p.kind;
            r.amount = x.at(k);
            r.length = x.at(k + 1);
          }
      }
    return gi;
  }

  void cycle_measures(const std::vector<double> &ste, double &pp, double &h1, double &mean)
  {
    const std::size_t n = ste.size();
    pp = h1 = mean = 0;
    if (n == 0)
      return;
    const auto [lo, hi] = std::minmax_element(ste.begin(), ste.end());
    pp                  = *hi - *lo;
    std::complex<double> c(0, 0);
    for (std::size_t k = 0; k < n; ++k)
      {
        c += ste[k] * std::polar(1.0, -2 * units::pi * double(k) / double(n));
        mean += ste[k] / double(n);
      }
    h1 = 2 * std::abs(c) / double(n);
  }

  void check_relief_geometry(const geometry::GeometryInput &geometry, const ReliefProblem &p)
  {
    // The box's corners must be valid designs (InputError naming the bound otherwise).
    for (const double L : {p.length_min, p.length_max})
      {
        std::vector<double> x;
        for (int i = 0; i < p.n_variables() / 2; ++i)
          x.insert(x.end(), {p.amount_max, L});
        try
          {
            (void)geometry::build_pair(relief_geometry(geometry, p, x));
          }
        catch (const InputError &e)
          {
            throw InputError(section + (L == p.length_max ? "Maximum length" : "Minimum length"), to_string_g(L * 1e3) + " mm",
                             "a relief the flanks can carry", e.what());
          }
      }
  }

  ReliefModel::ReliefModel(const geometry::GeometryInput &geometry, const solve::GearContactInput &in,
                           const ReliefProblem &problem, bool condensed)
    : geometry_(geometry), problem_(problem)
  {
    problem_.check();
    geometry::GeometryInput plain = geometry;
    plain.gear1.relief = plain.gear2.relief = TipRelief();
    base_pair_ = std::make_unique<geometry::GearPair>(geometry::build_pair(plain));
    contact::ContactOptions options = in.contact;
    options.micro_geometry_as_gap   = true;
    check_relief_geometry(geometry, problem_);
    model_ = std::make_unique<contact::GearContactModel>(*base_pair_, in.mesh, in.material, in.fe, options);
    positions_ = contact::cycle_positions(*base_pair_, problem_.positions, 1.0, base_pair_->point("A").roll_angle);
    if (condensed)
      {
        std::vector<double> T = problem_.torques;
        T.insert(T.end(), problem_.check_torques.begin(), problem_.check_torques.end());
        std::vector<std::pair<std::string, double>> named;
        for (const double phi : positions_)
          named.emplace_back("", phi);
        model_->set_micro_geometry(*base_pair_);
        cycle_ = std::make_unique<condensed::CondensedCycle>(
          condensed::cycle_for(*model_, named, condensed::cycle_range(T, condensed::CycleUse::given_torques)));
      }
  }

  bool ReliefModel::condensed_cycle_ste(const geometry::GearPair &pair, double T, std::vector<double> &ste) const
  {
    ste.assign(positions_.size(), 0.0);
    const double rb1 = base_pair_->base_radius(1);
    try
      {
        for (std::size_t k = 0; k < positions_.size(); ++k)
          {
            const auto &p = cycle_->at(k, T);
            ste[k] = contact::solve_condensed(p, condensed::relief_offsets(p, pair), T).solution.q * rb1 * 1e6;
          }
        return true;
      }
    catch (const SolverError &)
      {
        return false;
      }
  }

  ReliefModel::~ReliefModel() = default;

  double ReliefModel::setup_seconds() const { return model_->setup_seconds(); }

  namespace
  {
    /// Collects the STE [um] of each point of the sweep.
    class SteObserver : public loading::SweepObserver
    {
    public:
      SteObserver(double rb1, std::size_t nt, std::size_t np)
        : rb1_(rb1), ste(nt, std::vector<double>(np, 0.0))
      {}
      void finished(const loading::SweepPoint &p, const contact::ContactState &s) override
      {
        ste[p.torque_index][p.position_index] = s.rotation() * rb1_ * 1e6;
      }
      double rb1_;
      std::vector<std::vector<double>> ste;
    };
  } // namespace

  ReliefResult ReliefModel::evaluate(const std::vector<double> &x, const ReliefProblem &problem)
  {
    if (problem.kind != problem_.kind || problem.per_gear != problem_.per_gear ||
        problem.positions != problem_.positions)
      throw std::invalid_argument("ReliefModel::evaluate: the problem's variables or positions differ from the "
                                  "model's");
    const auto t0 = std::chrono::steady_clock::now();
    auto pair     = std::make_unique<geometry::GearPair>(geometry::build_pair(relief_geometry(geometry_, problem_, x)));
    ++evaluations_;
    loading::SweepPlan plan;
    for (const double phi : positions_)
      plan.positions.emplace_back("", phi);
    plan.torques = problem.torques;
    SteObserver obs(base_pair_->base_radius(1), plan.torques.size(), plan.positions.size());
    bool on_cycle = cycle_ != nullptr;
    for (std::size_t k = 0; k < plan.torques.size() && on_cycle; ++k)
      on_cycle = condensed_cycle_ste(*pair, plan.torques[k], obs.ste[k]);
    loading::SweepOutcome o;
    if (!on_cycle)
      {
        fallbacks_ += cycle_ != nullptr;
        model_->set_micro_geometry(*pair);
        current_ = std::move(pair); // the model now points to it; the previous design is freed
        o        = loading::run_sweep(*model_, plan, {&obs});
      }
    ReliefResult r;
    r.ok      = o.failure.empty();
    r.failure = o.failure;
    if (r.ok)
      {
        double sum = 0, wsum = 0;
        for (std::size_t k = 0; k < plan.torques.size(); ++k)
          {
            double pp, h1, mean;
            cycle_measures(obs.ste[k], pp, h1, mean);
            r.peak_to_peak.push_back(pp), r.harmonic.push_back(h1), r.mean.push_back(mean);
            const double m = problem.measure == ReliefMeasure::peak_to_peak ? pp : h1;
            const double w = problem.weights.empty() ? 1.0 : problem.weights[k];
            r.objective    = k == 0 ? m : std::max(r.objective, m);
            sum += w * m, wsum += w;
          }
        if (problem.aggregate == TorqueAggregate::weighted_mean)
          r.objective = sum / wsum;
        r.ste = std::move(obs.ste);
      }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }

  namespace
  {
    /// A run's bookkeeping: every FE evaluation once (repeated points come from the memo).
    class Recorder
    {
    public:
      Recorder(ReliefModel &m, const ReliefProblem &p, ReliefRun &run)
        : m_(m), p_(p), run_(run), t0_(std::chrono::steady_clock::now())
      {
        run_.torques = p.torques;
      }
      const ReliefRow &operator()(const std::vector<double> &x)
      {
        auto it = memo_.find(x);
        if (it != memo_.end())
          return run_.history[it->second];
        ReliefRow row;
        row.evaluation = static_cast<int>(run_.history.size()) + 1;
        row.x          = x;
        row.result     = m_.evaluate(x, p_);
        const bool better =
          row.result.ok && (run_.best < 0 || row.result.objective < run_.history[run_.best].result.objective);
        if (better)
          run_.best = static_cast<int>(run_.history.size());
        row.best    = run_.best < 0 ? 0.0 : (better ? row.result.objective : run_.history[run_.best].result.objective);
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
        memo_[x]    = run_.history.size();
        run_.history.push_back(std::move(row));
        return run_.history.back();
      }
      double seconds() const
      {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
      }

    private:
      ReliefModel &m_;
      const ReliefProblem &p_;
      ReliefRun &run_;
      std::chrono::steady_clock::time_point t0_;
      std::map<std::vector<double>, std::size_t> memo_;
    };

    std::string design_text(const ReliefProblem &p, const std::vector<double> &x)
    {
      std::string s;
      const auto names = p.variable_names();
      for (std::size_t i = 0; i < x.size(); ++i)
        s += (i ? ", " : "") + names[i] + " " + (i % 2 == 0 ? to_string_g(x[i] * 1e6, 4) + " um" : to_string_g(x[i] * 1e3, 4) + " mm");
      return s;
    }
  } // namespace

  ReliefRun optimise_relief(ReliefModel &model, const ReliefProblem &p, const OptimiserSettings &settings,
                            std::ostream *out)
  {
    p.check();
    settings.check();
    ReliefRun run;
    run.name = to_string(settings.method);
    Recorder   rec(model, p, run);
    const auto lo = p.lower(), hi = p.upper();
    const std::size_t n = lo.size();
    // The optimiser works on u in [0, 1]^n: amounts [um] and lengths [mm] on one scale.
    auto to_x = [&](const std::vector<double> &u) {
      std::vector<double> x(n);
      for (std::size_t i = 0; i < n; ++i)
        x[i] = lo[i] + std::clamp(u[i], 0.0, 1.0) * (hi[i] - lo[i]);
      return x;
    };
    const auto x0 = p.start_point();
    std::vector<double> u0(n);
    for (std::size_t i = 0; i < n; ++i)
      u0[i] = (x0[i] - lo[i]) / (hi[i] - lo[i]);
    const ReliefRow &start = rec(to_x(u0));
    if (!start.result.ok)
      throw SolverError("the sweep of the start point (" + design_text(p, start.x) + ") failed: " + start.result.failure);
    Progress progress(out, static_cast<std::size_t>(settings.max_evaluations),
                      std::string("optimise [") + run.name + "] evaluations");
    const EvaluateFunction f = [&](const std::vector<double> &u) {
      const ReliefRow &row = rec(to_x(u));
      Evaluation e;
      e.computable  = row.result.ok;
      e.feasible    = row.result.ok;
      e.reason      = row.result.ok ? "" : "solver failure: " + row.result.failure;
      e.objective   = row.result.objective;
      e.constraints = std::vector<double>(n_constraints, -1.0); // the box is the only constraint
      return e;
    };
    const ProgressCallback cb = [&](int k, int, double) {
      progress.step(static_cast<std::size_t>(k),
                    "best " + to_string_g(run.best_row().result.objective, 5) + " um (" + design_text(p, run.best_row().x) + ")");
    };
    // First steps of a quarter of the box: the FE objective is too costly for small ones.
    OptimiseResult r = optimise(f, u0, std::vector<double>(n, 0.0), std::vector<double>(n, 1.0), settings, cb, 0.25);
    run.stop_reason  = r.stop_reason;
    run.seconds      = rec.seconds();
    return run;
  }

  ReliefRun relief_grid(ReliefModel &model, const ReliefProblem &p, int points, std::ostream *out)
  {
    p.check();
    require_range(section + "Grid points", points, 2, 50);
    ReliefRun run;
    const int n = p.n_variables();
    run.name    = "grid " + std::to_string(points) + "^" + std::to_string(n);
    Recorder   rec(model, p, run);
    const auto lo = p.lower(), hi = p.upper();
    std::size_t total = 1;
    for (int i = 0; i < n; ++i)
      total *= static_cast<std::size_t>(points);
    Progress progress(out, total, "grid evaluations");
    for (std::size_t k = 0; k < total; ++k)
      {
        std::vector<double> x(n);
        std::size_t rest = k;
        for (int i = n - 1; i >= 0; --i) // the last variable fastest
          {
            x[i] = lo[i] + (hi[i] - lo[i]) * double(rest % points) / (points - 1);
            rest /= points;
          }
        rec(x);
        progress.step(k + 1, run.best < 0 ? std::string("no successful point yet") :
                                            "best " + to_string_g(run.best_row().result.objective, 5) + " um");
      }
    run.stop_reason = "grid complete";
    run.seconds     = rec.seconds();
    return run;
  }

  ReliefStudyResult run_relief_study(const ReliefStudy &s, std::ostream *out)
  {
    s.problem.check();
    ReliefModel model(s.geometry, *s.input, s.problem, s.condensed);
    ReliefStudyResult r;
    r.setup_seconds = model.setup_seconds();
    r.condensed     = model.cycle() != nullptr;
    r.cycle_seconds = r.condensed ? model.cycle()->build_seconds : 0.0;
    if (out)
      *out << "model: " << model.model().n_dofs() << " DoFs, set-up (mesh, assemble, factorise) " << to_string_g(r.setup_seconds, 3)
           << " s, built once; " << model.positions().size() << " positions x " << s.problem.torques.size()
           << " torque(s) per evaluation"
           << (r.condensed ? "; designs on a condensed cycle built in " + to_string_g(r.cycle_seconds, 3) + " s" : std::string())
           << std::endl;
    r.unrelieved.x      = std::vector<double>(s.problem.n_variables(), 0.0);
    for (std::size_t i = 1; i < r.unrelieved.x.size(); i += 2)
      r.unrelieved.x[i] = s.problem.length_min;
    r.unrelieved.result = model.evaluate(r.unrelieved.x);
    if (!r.unrelieved.result.ok)
      throw SolverError("the sweep of the unrelieved pair failed: " + r.unrelieved.result.failure);
    if (out)
      *out << "no relief: objective " << to_string_g(r.unrelieved.result.objective, 5) << " um (" << to_string(s.problem.measure)
           << ", " << to_string(s.problem.aggregate) << " over " << s.problem.torques.size() << " torque(s)), sweep "
           << to_string_g(r.unrelieved.result.seconds, 3) << " s" << std::endl;
    r.optimiser = optimise_relief(model, s.problem, s.optimiser, out);
    if (out)
      *out << "optimise [" << r.optimiser.name << "]: " << r.optimiser.history.size() << " FE evaluations, "
           << to_string_g(r.optimiser.seconds, 3) << " s, objective " << to_string_g(r.optimiser.history.front().result.objective, 5)
           << " -> " << to_string_g(r.optimiser.best_row().result.objective, 5) << " um at "
           << design_text(s.problem, r.optimiser.best_row().x) << " (" << r.optimiser.stop_reason << ")" << std::endl;
    if (s.problem.grid_points > 0)
      {
        r.grid = relief_grid(model, s.problem, s.problem.grid_points, out);
        if (out && r.grid.best >= 0)
          *out << r.grid.name << ": " << r.grid.history.size() << " FE evaluations, " << to_string_g(r.grid.seconds, 3)
               << " s, best " << to_string_g(r.grid.best_row().result.objective, 5) << " um at "
               << design_text(s.problem, r.grid.best_row().x) << std::endl;
      }
    if (s.problem.single_torque_optima)
      r.single = single_load_optima(model, s.problem, s.optimiser, out);
    if (!s.problem.check_torques.empty())
      {
        std::vector<std::pair<std::string, std::vector<double>>> designs = {{"no relief", r.unrelieved.x},
                                                                            {"optimum", r.optimiser.best_row().x}};
        for (const auto &single : r.single)
          designs.emplace_back("optimum at " + to_string_g(single.torque) + " N m", single.run.best_row().x);
        if (r.grid.best >= 0)
          designs.emplace_back("grid best", r.grid.best_row().x);
        r.check = check_designs(model, s.problem, designs, s.problem.check_torques, out);
      }
    r.fallbacks = model.fallbacks();
    if (out && r.condensed)
      *out << "condensed cycle: " << model.evaluations() << " evaluations, " << r.fallbacks
           << " of them fell back to the full FE sweep" << std::endl;
    return r;
  }
} // namespace gearfem::optimise
