// Steepest descent with golden-section line search (Koronaios 2021) and the NLopt methods.
#include "optimise/optimisers.h"

#include "base/errors.h"

#include <nlopt.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace gearfem::optimise
{
  namespace
  {
    struct MethodInfo
    {
      Method m;
      const char *name;
      nlopt::algorithm alg;
      bool gradient, constraints;
    };
    const MethodInfo methods[] = {
      {Method::steepest_descent, "steepest descent", nlopt::LD_SLSQP, true, false},
      {Method::slsqp, "slsqp", nlopt::LD_SLSQP, true, true},
      {Method::mma, "mma", nlopt::LD_MMA, true, true},
      {Method::cobyla, "cobyla", nlopt::LN_COBYLA, false, true},
      {Method::bobyqa, "bobyqa", nlopt::LN_BOBYQA, false, false},
      {Method::isres, "isres", nlopt::GN_ISRES, false, true},
      {Method::crs2, "crs2", nlopt::GN_CRS2_LM, false, false},
      {Method::esch, "esch", nlopt::GN_ESCH, false, false},
    };
    const MethodInfo &info(Method m)
    {
      for (const auto &i : methods)
        if (i.m == m)
          return i;
      return methods[0];
    }

    /// Raised inside the evaluation loop when the evaluation budget is used up.
    struct BudgetExhausted
    {};

    /// The design as an optimisation problem: counted, recorded evaluations.
    class Problem
    {
    public:
      Problem(const EvaluateFunction &f, const OptimiserSettings &o, const ProgressCallback &cb,
              OptimiseResult &r)
        : f_(f), o_(o), cb_(cb), r_(r), t0_(std::chrono::steady_clock::now())
      {}

      const Evaluation &eval(const std::vector<double> &x)
      {
        if (r_.evaluations >= o_.max_evaluations)
          throw BudgetExhausted{};
        last_x_ = x;
        last_   = f_(x);
        ++r_.evaluations;
        if (last_.feasible && last_.objective < r_.best.objective)
          r_.best = last_, r_.x_best = x;
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
        r_.history.push_back({r_.evaluations, last_.computable ? last_.objective : 0.0, last_.feasible,
                              r_.best.objective, t});
        const int every = std::max(1, o_.max_evaluations / 20);
        if (cb_ && r_.evaluations % every == 0)
          cb_(r_.evaluations, o_.max_evaluations, r_.best.objective);
        return last_;
      }
      /// Objective of the thesis method: exact (L1) penalty of the constraints, +inf where
      /// the design cannot be evaluated. (The thesis does not say how it imposed them; a
      /// barrier stalls at the start, where the path-reach constraint is nearly active.)
      double barrier(const std::vector<double> &x)
      {
        const Evaluation &e = eval(x);
        if (!e.computable || (!e.feasible && constraints_met(e)))
          return std::numeric_limits<double>::infinity(); // a design check failed
        double p = 0;
        for (double c : e.constraints)
          p += std::max(0.0, c) * std::max(0.0, c);
        return e.objective + 1e4 * p;
      }
      /// Objective for NLopt: with constraints handled by NLopt, or by an exterior penalty.
      double nlopt_value(const Evaluation &e, bool penalty) const
      {
        if (!e.computable)
          return big();
        if (!penalty)
          return e.objective + (e.feasible || !constraints_met(e) ? 0.0 : big());
        double p = 0;
        for (double c : e.constraints)
          p += std::max(0.0, c);
        return e.objective + 10.0 * p + (e.feasible || !constraints_met(e) ? 0.0 : big());
      }
      static bool constraints_met(const Evaluation &e)
      {
        for (double c : e.constraints)
          if (c > 1e-9)
            return false;
        return true;
      }
      double big() const { return 10.0 * (std::abs(r_.start.objective) + 1.0); }
      std::vector<double> constraints(const Evaluation &e) const
      {
        return e.computable ? e.constraints : std::vector<double>(n_constraints, 1.0);
      }
      const Evaluation &last() const { return last_; }
      const std::vector<double> &last_x() const { return last_x_; }
      const OptimiserSettings &settings() const { return o_; }

    private:
      const EvaluateFunction &f_;
      const OptimiserSettings &o_;
      const ProgressCallback &cb_;
      OptimiseResult &r_;
      std::chrono::steady_clock::time_point t0_;
      std::vector<double> last_x_;
      Evaluation last_;
    };

    /// Line search of the thesis method: bracket the first minimum along the ray by steps
    /// growing by the golden ratio from 1e-5 (module units), at most `line_search_steps`
    /// ("searching steps"), then golden section down to `golden_tolerance`. Returns (alpha,
    /// phi) of the best point evaluated; phi(0) = f0 is included.
    template <typename Phi>
    std::pair<double, double> line_search(Phi &&phi, double amax, double f0, const OptimiserSettings &o)
    {
      const double g = 0.5 * (std::sqrt(5.0) - 1);
      double lo = 0, mid = 0, fmid = f0, hi = std::min(1e-5, amax), fhi = phi(hi);
      double best_a = 0, best_f = f0;
      if (fhi < best_f)
        best_a = hi, best_f = fhi;
      for (int k = 0; k < o.line_search_steps && fhi < fmid && hi < amax; ++k)
        {
          lo = mid, mid = hi, fmid = fhi;
          hi  = std::min(amax, mid + (mid - lo) / g);
          fhi = phi(hi);
          if (fhi < best_f)
            best_a = hi, best_f = fhi;
        }
      double a = lo, b = hi, c = b - g * (b - a), e = a + g * (b - a);
      double fc = phi(c), fe = phi(e);
      for (int k = 0; k < o.line_search_steps && b - a > o.golden_tolerance; ++k)
        {
          if (fc < best_f)
            best_f = fc, best_a = c;
          if (fe < best_f)
            best_f = fe, best_a = e;
          if (fc <= fe)
            b = e, e = c, fe = fc, c = b - g * (b - a), fc = phi(c);
          else
            a = c, c = e, fc = fe, e = a + g * (b - a), fe = phi(e);
        }
      if (fc < best_f)
        best_f = fc, best_a = c;
      if (fe < best_f)
        best_f = fe, best_a = e;
      return {best_a, best_f};
    }

    void steepest_descent(Problem &P, std::vector<double> x, double f, const std::vector<double> &lb,
                          const std::vector<double> &ub, OptimiseResult &r)
    {
      const auto  &o = P.settings();
      const size_t n = x.size();
      for (int it = 0; it < o.iterations; ++it)
        {
          // Forward differences (backward where the forward point is infeasible).
          std::vector<double> g(n, 0.0);
          for (size_t i = 0; i < n; ++i)
            {
              auto xp = x;
              xp[i] += o.fd_step;
              double fp = xp[i] <= ub[i] ? P.barrier(xp) : INFINITY;
              if (std::isfinite(fp))
                g[i] = (fp - f) / o.fd_step;
              else
                {
                  xp[i] = x[i] - o.fd_step;
                  fp    = xp[i] >= lb[i] ? P.barrier(xp) : INFINITY;
                  g[i]  = std::isfinite(fp) ? (f - fp) / o.fd_step : 0.0;
                }
            }
          double gn = 0;
          for (double v : g)
            gn += v * v;
          gn = std::sqrt(gn);
          if (!(gn > 0))
            {
              r.stop_reason = "zero gradient";
              return;
            }
          std::vector<double> d(n);
          double              amax = std::numeric_limits<double>::infinity();
          for (size_t i = 0; i < n; ++i)
            {
              d[i] = -g[i] / gn;
              if (d[i] > 0)
                amax = std::min(amax, (ub[i] - x[i]) / d[i]);
              else if (d[i] < 0)
                amax = std::min(amax, (lb[i] - x[i]) / d[i]);
            }
          auto phi = [&](double a) {
            std::vector<double> y(n);
            for (size_t i = 0; i < n; ++i)
              y[i] = x[i] + a * d[i];
            return P.barrier(y);
          };
          const auto [a, fa] = line_search(phi, amax, f, o);
          if (!(fa < f))
            {
              r.stop_reason = "no descent along -grad f (iteration " + std::to_string(it + 1) + ")";
              return;
            }
          for (size_t i = 0; i < n; ++i)
            x[i] += a * d[i];
          const bool small = f - fa <= o.ftol_rel * std::abs(f);
          f                = fa;
          if (small)
            {
              r.stop_reason = "relative decrease below tolerance (iteration " + std::to_string(it + 1) + ")";
              return;
            }
        }
      r.stop_reason = "iteration limit (" + std::to_string(o.iterations) + ")";
    }

    struct NloptData
    {
      Problem *P;
      nlopt::opt *opt;
      bool gradient, penalty;
      std::vector<double> x;      ///< the point of `cur`
      Evaluation cur;
      bool fd_valid = false;
      std::vector<Evaluation> fd; ///< forward-difference evaluations at x
    };

    /// Evaluate at x once (objective and constraints share it), and the forward-difference
    /// points once when a gradient is wanted.
    const Evaluation &nlopt_eval(NloptData &D, const std::vector<double> &x, bool want_gradient)
    {
      if (x != D.x)
        {
          D.cur = D.P->eval(x), D.x = x, D.fd_valid = false;
        }
      if (want_gradient && !D.fd_valid)
        {
          D.fd.clear();
          for (size_t i = 0; i < x.size(); ++i)
            {
              auto xp = x;
              xp[i] += D.P->settings().fd_step;
              D.fd.push_back(D.P->eval(xp));
            }
          D.fd_valid = true;
        }
      return D.cur;
    }

    double nlopt_objective(unsigned n, const double *xp, double *grad, void *data)
    {
      auto &D = *static_cast<NloptData *>(data);
      try
        {
          const std::vector<double> x(xp, xp + n);
          const Evaluation &e = nlopt_eval(D, x, grad != nullptr);
          const double      f = D.P->nlopt_value(e, D.penalty);
          if (grad)
            for (unsigned i = 0; i < n; ++i)
              grad[i] = (D.P->nlopt_value(D.fd[i], D.penalty) - f) / D.P->settings().fd_step;
          return f;
        }
      catch (const BudgetExhausted &)
        {
          D.opt->force_stop();
          return 0.0;
        }
    }

    void nlopt_constraints(unsigned m, double *result, unsigned n, const double *xp, double *grad, void *data)
    {
      auto &D = *static_cast<NloptData *>(data);
      try
        {
          const std::vector<double> x(xp, xp + n);
          const Evaluation &e = nlopt_eval(D, x, grad != nullptr);
          const auto        c = D.P->constraints(e);
          for (unsigned j = 0; j < m; ++j)
            result[j] = c[j];
          if (grad)
            for (unsigned i = 0; i < n; ++i)
              {
                const auto cp = D.P->constraints(D.fd[i]);
                for (unsigned j = 0; j < m; ++j)
                  grad[j * n + i] = (cp[j] - c[j]) / D.P->settings().fd_step;
              }
        }
      catch (const BudgetExhausted &)
        {
          D.opt->force_stop();
          for (unsigned j = 0; j < m; ++j)
            result[j] = 0.0;
        }
    }

    void run_nlopt(Problem &P, const MethodInfo &mi, std::vector<double> x, const std::vector<double> &lb,
                   const std::vector<double> &ub, double step_fraction, OptimiseResult &r)
    {
      const auto &o = P.settings();
      nlopt::srand(o.seed);
      nlopt::opt opt(mi.alg, x.size());
      NloptData  D{&P, &opt, mi.gradient, !mi.constraints, {}, {}, false, {}};
      opt.set_lower_bounds(lb);
      opt.set_upper_bounds(ub);
      opt.set_min_objective(nlopt_objective, &D);
      if (mi.constraints)
        opt.add_inequality_mconstraint(nlopt_constraints, &D, std::vector<double>(n_constraints, 1e-9));
      opt.set_maxeval(o.max_evaluations);
      if (!mi.gradient && mi.alg != nlopt::GN_ISRES && mi.alg != nlopt::GN_CRS2_LM && mi.alg != nlopt::GN_ESCH)
        {
          // COBYLA, BOBYQA: first steps of a fraction of the box (Koronaios 2021: 5 % of its width,
          // i.e. 10 % of the half-width `Bound`).
          std::vector<double> step(x.size());
          for (std::size_t i = 0; i < x.size(); ++i)
            step[i] = step_fraction * (ub[i] - lb[i]);
          opt.set_initial_step(step);
        }
      opt.set_xtol_rel(o.xtol_rel);
      opt.set_ftol_rel(o.ftol_rel);
      if (o.population > 0)
        opt.set_population(o.population);
      double f = 0;
      try
        {
          const nlopt::result res = opt.optimize(x, f);
          r.stop_reason = "nlopt result " + std::to_string(static_cast<int>(res));
        }
      catch (const nlopt::forced_stop &)
        {
          r.stop_reason = "evaluation limit (" + std::to_string(o.max_evaluations) + ")";
        }
      catch (const std::exception &e)
        {
          r.stop_reason = std::string("nlopt stopped: ") + e.what();
        }
    }
  } // namespace

  const char *to_string(Method m) { return info(m).name; }

  std::string method_names()
  {
    std::string s;
    for (const auto &i : methods)
      s += (s.empty() ? "" : "|") + std::string(i.name);
    return s;
  }

  Method method_from_string(const std::string &name, const std::string &parameter)
  {
    for (const auto &i : methods)
      if (name == i.name)
        return i.m;
    throw InputError(parameter, name, method_names());
  }

  void OptimiserSettings::check() const
  {
    require_range("Optimiser/Max evaluations", max_evaluations, 1, 10000000);
    require_greater("Optimiser/Bound", bound, 0.0, "module units");
    require_range("Optimiser/Bound", bound, 0.0, 2.0, "module units");
    require_range("Optimiser/Finite-difference step", fd_step, 1e-12, 1e-2, "module units");
    require_range("Optimiser/Relative x tolerance", xtol_rel, 0.0, 1.0);
    require_range("Optimiser/Relative f tolerance", ftol_rel, 0.0, 1.0);
    require_range("Optimiser/Iterations", iterations, 1, 100000);
    require_greater("Optimiser/Golden-section tolerance", golden_tolerance, 0.0, "module units");
    require_range("Optimiser/Line-search steps", line_search_steps, 1, 10000);
    require_range("Optimiser/Population", population, 0, 100000);
    require_range("Optimiser/Multistart", multistart, 0, 1000);
  }

  OptimiseResult optimise(const EvaluateFunction &f, const std::vector<double> &x0, const std::vector<double> &lb,
                          const std::vector<double> &ub, const OptimiserSettings &settings,
                          const ProgressCallback &progress, double initial_step)
  {
    settings.check();
    if (lb.size() != x0.size() || ub.size() != x0.size())
      throw std::logic_error("optimise: bounds and start point differ in size");
    OptimiseResult r;
    r.method  = settings.method;
    r.x_start = x0;
    r.start   = f(x0);
    if (!r.start.feasible)
      throw InputError("Optimise/Start point", "the start design", "a feasible design",
                       "infeasible start: " + r.start.reason);
    r.best   = r.start;
    r.x_best = x0;
    const auto t0 = std::chrono::steady_clock::now();
    Problem    P(f, settings, progress, r);
    try
      {
        if (settings.method == Method::steepest_descent)
          steepest_descent(P, x0, P.barrier(x0), lb, ub, r);
        else
          run_nlopt(P, info(settings.method), x0, lb, ub, initial_step, r);
      }
    catch (const BudgetExhausted &)
      {
        r.stop_reason = "evaluation limit (" + std::to_string(settings.max_evaluations) + ")";
      }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
  }

  OptimiseResult multistart(const EvaluateFunction &f, const std::vector<double> &x0, const std::vector<double> &lb,
                            const std::vector<double> &ub, const OptimiserSettings &settings,
                            const ProgressCallback &progress)
  {
    settings.check();
    const auto    t0 = std::chrono::steady_clock::now();
    auto          seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    OptimiseResult r;
    r.method  = settings.method;
    r.x_start = x0;
    r.start   = f(x0);
    r.best    = r.start;
    r.x_best  = x0;
    bool found = false;
    // Sampling phase: every point is an evaluation of the history.
    std::vector<std::pair<double, std::vector<double>>> feasible;
    auto record = [&](const std::vector<double> &x, const Evaluation &e) {
      ++r.evaluations;
      if (e.feasible)
        {
          feasible.emplace_back(e.objective, x);
          if (!found || e.objective < r.best.objective)
            r.best = e, r.x_best = x, found = true;
        }
      r.history.push_back({r.evaluations, e.computable ? e.objective : 0.0, e.feasible,
                           found ? r.best.objective : r.start.objective, seconds()});
    };
    std::mt19937                           rng(settings.seed);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    const int                              n_draw = 20 * settings.multistart;
    std::vector<double>                    x(x0.size());
    for (int k = 0; k < n_draw; ++k)
      {
        for (std::size_t i = 0; i < x.size(); ++i)
          x[i] = lb[i] + U(rng) * (ub[i] - lb[i]);
        record(x, f(x));
      }
    if (feasible.empty() && !r.start.feasible)
      throw InputError("Optimiser/Multistart", std::to_string(settings.multistart),
                       "a number of starts whose box holds a feasible design",
                       "neither the start point (" + r.start.reason + ") nor any of " + std::to_string(n_draw) +
                         " random points of the box is feasible");
    std::sort(feasible.begin(), feasible.end(),
              [](const auto &a, const auto &b) { return a.first < b.first; });
    if (static_cast<int>(feasible.size()) > settings.multistart)
      feasible.resize(settings.multistart);
    if (r.start.feasible)
      feasible.insert(feasible.begin(), {r.start.objective, x0});
    OptimiserSettings one = settings;
    one.multistart        = 0;
    int    improved_by    = -1;
    double best_so_far    = found ? r.best.objective : r.start.objective;
    for (std::size_t j = 0; j < feasible.size(); ++j)
      {
        const OptimiseResult q = optimise(f, feasible[j].second, lb, ub, one, progress, 0.05);
        for (const auto &h : q.history)
          {
            ++r.evaluations;
            if (h.feasible && h.objective < best_so_far)
              best_so_far = h.objective;
            r.history.push_back({r.evaluations, h.objective, h.feasible, best_so_far, seconds()});
          }
        if (q.best.feasible && (!r.best.feasible || q.best.objective < r.best.objective))
          r.best = q.best, r.x_best = q.x_best, improved_by = static_cast<int>(j);
      }
    r.seconds     = seconds();
    r.stop_reason = "multistart: best of " + std::to_string(feasible.size()) + " runs (" + std::to_string(n_draw) +
                    " random points), best from " +
                    (improved_by < 0 ? std::string("the sampling") :
                     improved_by == 0 && r.start.feasible ? std::string("the start point") :
                                                            "random start " + std::to_string(improved_by));
    return r;
  }

  OptimiseResult optimise(const Design &design, const std::vector<double> &x0, const EvaluationSettings &eval,
                          const OptimiserSettings &settings, const ProgressCallback &progress)
  {
    settings.check();
    std::vector<double> lb(x0.size()), ub(x0.size());
    for (size_t i = 0; i < x0.size(); ++i)
      lb[i] = x0[i] - settings.bound, ub[i] = x0[i] + settings.bound;
    const EvaluateFunction f = [&](const std::vector<double> &x) { return design.evaluate(x, eval); };
    if (settings.multistart == 0)
      return optimise(f, x0, lb, ub, settings, progress, 0.05);
    return multistart(f, x0, lb, ub, settings, progress);
  }
} // namespace gearfem::optimise
