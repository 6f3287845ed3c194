// A Koronaios 2021 optimisation study: run the optimisers, re-evaluate, write the report files.
#include "optimise/study.h"
#include "geometry/limits.h"
#include "base/units.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/progress.h"

#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace gearfem::optimise
{
  namespace
  {
    /// Thesis rows (Koronaios 2021, Table 5.2 and the second Table 6.1): mean, max, std
    /// [1/mm] of the optimum and, for case 2, its contact ratio ("overlap 1.04").
    struct ThesisRow
    {
      double mean, max, std, eps;
    };
    ThesisRow thesis(DesignKind k)
    {
      return k == DesignKind::case1_rack ? ThesisRow{0.0708, 0.1644, 0.0490, 0.0} :
                                           ThesisRow{0.1130, 0.1148, 0.0014, 1.04};
    }
  } // namespace

  void check_study(const Study &s)
  {
    require_range("Optimise/Samples", s.eval.samples, 11, 1000000);
    require_range("Optimise/Report samples", s.report_samples, 11, 1000000);
    require_range("Optimise/Minimum contact ratio", s.eval.min_contact_ratio, 0.0, 5.0);
    geometry::limits::check_teeth("Optimise/Pinion teeth", s.pair.z1);
    geometry::limits::check_teeth("Optimise/Gear teeth", s.pair.z2);
    geometry::limits::check_module("Optimise/Module", s.pair.module);
    geometry::limits::check_pressure_angle("Optimise/Pressure angle", s.pair.pressure_angle);
    geometry::limits::check_addendum("Optimise/Addendum coefficient", s.pair.addendum);
    geometry::limits::check_face_width("Optimise/Face width", s.face_width);
    if (s.eval.start_radius != 0)
      require_range("Optimise/Start radius", s.eval.start_radius * 1e3, s.pair.r01() * (1 - 0.3) * 1e3,
                    s.pair.tip_radius(1) * 1e3, "mm");
    if (s.runs.empty())
      throw InputError("Optimiser/Methods", "(empty)", "a list of " + method_names());
    for (const auto &o : s.runs)
      o.check();
    const Design d(s.kind, s.pair, s.fixed_end);
    const auto   x0 = s.start.empty() ? d.default_start() : s.start;
    if (static_cast<int>(x0.size()) != d.n_free())
      throw InputError("Optimise/Start point", std::to_string(x0.size()) + " coordinates",
                       std::to_string(d.n_free()) + " coordinates for " + to_string(s.kind));
    for (double w : s.eval.weights)
      require_range("Optimise/Objective weights", w, 0.0, 1e6);
    if (s.eval.weights[0] + s.eval.weights[1] + s.eval.weights[2] <= 0)
      throw InputError("Optimise/Objective weights", "all zero", "at least one weight > 0");
    if (s.kind != DesignKind::case2_flank && s.eval.weights != EvaluationSettings{}.weights)
      throw InputError("Optimise/Objective weights", "other than 2.5, 1, 0.1 for case 1",
                       "the default (case 1's objective max + mean + std has no weights)");
    if (s.kind != DesignKind::case2_flank && s.fixed_end != FixedEnd::tip)
      throw InputError("Optimise/Fixed end", "root for case 1", "tip (case 1 fixes its own points)");
    // With a multistart, the start point is the centre of the box and may be infeasible
    // (optimise() then needs a feasible random point, or names Optimiser/Multistart).
    bool multistart = true;
    for (const auto &o : s.runs)
      multistart = multistart && o.multistart > 0;
    const Evaluation e = d.evaluate(x0, s.eval);
    if (!e.feasible && !multistart)
      throw InputError("Optimise/Start point", "the start design", "a feasible design",
                       "infeasible start: " + e.reason);
  }

  StudyResult run_study(const Study &s, std::ostream *out)
  {
    check_study(s);
    const Design d(s.kind, s.pair, s.fixed_end);
    const auto   x0 = s.start.empty() ? d.default_start() : s.start;
    EvaluationSettings rep = s.eval;
    rep.samples            = s.report_samples;
    StudyResult r;
    r.start = d.evaluate(x0, rep);
    EvaluationSettings ref = rep;
    ref.start_radius       = 0;
    r.involute = Design(DesignKind::involute, s.pair).evaluate({}, ref);
    r.sinusoid = Design(DesignKind::sinusoid, s.pair).evaluate({}, ref);
    for (std::size_t i = 0; i < s.runs.size(); ++i)
      {
        const auto &o = s.runs[i];
        Progress    progress(out, static_cast<std::size_t>(o.max_evaluations),
                             std::string("optimise [") + to_string(o.method) + "] evaluations");
        auto cb = [&](int k, int, double best) { progress.step(k, "best feasible objective " + to_string_g(best) + " 1/mm"); };
        StudyRun run;
        run.result  = optimise(d, x0, s.eval, o, cb);
        run.optimum = d.evaluate(run.result.x_best, rep);
        if (out)
          *out << "optimise [" << to_string(o.method) << "]: " << run.result.evaluations << " evaluations, "
               << to_string_g(run.result.seconds, 3) << " s, objective " << to_string_g(run.result.start.objective) << " -> "
               << to_string_g(run.result.best.objective) << " 1/mm (" << run.result.stop_reason << ")\n";
        if (out) // the constraints that bound the optimum (c within 1e-3 of 0)
          for (int c = 0; c < n_constraints; ++c)
            if (run.optimum.computable && run.optimum.constraints[c] > -1e-3)
              *out << "  near-active constraint: " << constraint_name(c) << " (c = " << to_string_g(run.optimum.constraints[c], 3)
                   << ")\n";
        r.runs.push_back(std::move(run));
        if (r.runs.back().optimum.objective < r.runs[r.best_run].optimum.objective)
          r.best_run = static_cast<int>(r.runs.size()) - 1;
      }
    return r;
  }

  void print_summary(const Study &s, const StudyResult &r, std::ostream &out)
  {
    out << "| design | evaluations | wall time [s] | objective [1/mm] | mean abs(1/R) [1/mm] | max abs(1/R) [1/mm] | "
           "std(1/R) [1/mm] | contact ratio | stop |\n|---|---|---|---|---|---|---|---|---|\n";
    auto row = [&](const std::string &name, const std::string &ev, const std::string &t, const Evaluation &e,
                   const std::string &stop) {
      out << "| " << name << " | " << ev << " | " << t << " | " << to_string_g(objective(s.kind, e.stats, e.integral, e.contact_ratio, s.eval.weights), 5)
          << " | " << to_string_g(e.stats.mean_abs * 1e-3, 4) << " | " << to_string_g(e.stats.max_abs * 1e-3, 4) << " | "
          << to_string_g(e.stats.std * 1e-3, 4) << " | " << to_string_g(e.contact_ratio, 4) << " | " << stop << " |\n";
    };
    row("involute (SAP to tip)", "", "", r.involute, "reference");
    row("sinusoid", "", "", r.sinusoid, "reference");
    row("start", "", "", r.start, "");
    for (const auto &run : r.runs)
      row(to_string(run.result.method), std::to_string(run.result.evaluations), to_string_g(run.result.seconds, 3),
          run.optimum, run.result.stop_reason);
    // The thesis' objective: case 1 from its row; case 2 estimated with int (1/R)^2 dx =
    // (mean^2 + std^2) times the position-2 extent of our best optimum (the thesis gives
    // neither its flank nor its integral), with the study's weights.
    const ThesisRow t = thesis(s.kind);
    const auto     &w = s.eval.weights;
    const double    f = s.kind == DesignKind::case1_rack ?
                          t.mean + t.max + t.std :
                          w[0] * (t.mean * t.mean + t.std * t.std) * r.runs[r.best_run].optimum.x_extent + w[1] * t.std +
                            w[2] / t.eps;
    out << "| thesis optimum (" << to_string(s.kind) << ") | | | " << (s.kind == DesignKind::case1_rack ? "" : "~") << to_string_g(f, 5)
        << " | " << t.mean << " | " << t.max << " | " << t.std << " | "
        << (t.eps > 0 ? to_string_g(t.eps) : std::string("not stated")) << " | steepest descent |\n";
  }

  void write_study(const Study &s, const StudyResult &r, const std::filesystem::path &dir)
  {
    const Design d(s.kind, s.pair, s.fixed_end);
    {
      AtomicOutputFile f(dir / "optimise.csv");
      f.stream() << "method,evaluation,objective [1/mm],feasible,best feasible [1/mm],time [s]\n";
      for (const auto &run : r.runs)
        for (const auto &h : run.result.history)
          f.stream() << to_string(run.result.method) << ',' << h.evaluation << ',' << to_string_g(h.objective, 10) << ','
                     << (h.feasible ? 1 : 0) << ',' << to_string_g(h.best, 10) << ',' << to_string_g(h.seconds, 6) << '\n';
      f.commit();
    }
    {
      AtomicOutputFile f(dir / "summary.md");
      const auto &w = s.eval.weights;
      f.stream() << "# Koronaios 2021 " << to_string(s.kind) << " optimisation";
      if (s.kind == DesignKind::case2_flank && (w[0] != 2.5 || w[1] != 1.0 || w[2] != 0.1))
        f.stream() << " (objective weights " << to_string_g(w[0]) << ", " << to_string_g(w[1]) << ", " << to_string_g(w[2]) << ")";
      if (s.kind == DesignKind::case2_flank && s.fixed_end == FixedEnd::root)
        f.stream() << " (P0 fixed)";
      f.stream() << "\n\n";
      print_summary(s, r, f.stream());
      f.commit();
    }
    {
      // 1/R along the path: position = pinion radius (radius-sampled designs) or rack u [mm],
      // and the same normalised to [0, 1] over the sampled range.
      AtomicOutputFile f(dir / "curvature.csv");
      f.stream() << "design,position [mm],normalised position [-],pinion radius [mm],1/R [1/mm]\n";
      auto put = [&](const std::string &name, const Evaluation &e, bool by_radius) {
        const auto &S = e.samples;
        if (S.empty())
          return;
        auto pos = [&](const ContactSample &q) { return (by_radius ? q.r1 : q.rack_u) * 1e3; };
        for (const auto &q : S)
          f.stream() << name << ',' << to_string_g(pos(q), 8) << ',' << to_string_g((pos(q) - pos(S.front())) / (pos(S.back()) - pos(S.front())), 6)
                     << ',' << to_string_g(q.r1 * 1e3, 8) << ',' << to_string_g(q.kappa_eq * 1e-3, 8) << '\n';
      };
      const bool radius = s.kind == DesignKind::case2_flank;
      put("involute", r.involute, true);
      put("sinusoid", r.sinusoid, false);
      put("start", r.start, radius);
      put("optimum", r.runs[r.best_run].optimum, radius);
      f.commit();
    }
    {
      AtomicOutputFile f(dir / "profiles.csv");
      f.stream() << "design,x [mm],y [mm]\n";
      auto put = [&](const std::string &name, const geometry::CurvePtr &c) {
        for (int i = 0; i <= 200; ++i)
          {
            const Vec2 p = c->point(c->t_begin() + (c->t_end() - c->t_begin()) * i / 200) * 1e3;
            f.stream() << name << ',' << to_string_g(p.x(), 8) << ',' << to_string_g(p.y(), 8) << '\n';
          }
      };
      put("involute", Design(DesignKind::involute, s.pair).flank({}));
      put("sinusoid", Design(DesignKind::sinusoid, s.pair).flank({}));
      put("start", d.flank(s.start.empty() ? d.default_start() : s.start));
      put("optimum", d.flank(r.runs[r.best_run].result.x_best));
      f.commit();
    }
    {
      const auto       &best = r.runs[r.best_run].result;
      AtomicOutputFile  f(dir / "optimum.prm");
      const bool        c2 = s.kind == DesignKind::case2_flank;
      std::ostream     &o  = f.stream();
      o << (c2 ? "# gearfem solve\n" : "# gearfem profile (case 1: see the note below)\n");
      o << "# Koronaios 2021 " << to_string(s.kind) << " optimum by " << to_string(best.method) << " (gearfem optimise): objective "
        << to_string_g(r.runs[r.best_run].optimum.objective) << " 1/mm.\n";
      const auto cp = d.control_points(best.x_best);
      if (!c2)
        o << "# Case 1: a closed rack (level crest at u = 0, level trough at u = p/2) whose crest and\n"
             "# trough set the addendum and dedendum; the tips are shortened by 0.05 m so that they are\n"
             "# not pointed. gearfem builds the teeth but refuses the pair (exit 2) when its path of\n"
             "# contact reverses (several points of one flank in contact at once, as for the sinusoid)\n"
             "# or its contact ratio is below 1: see docs/optimise.md.\n";
      o << "subsection Rack\n  set Module                  = " << to_string_g(s.pair.module * 1e3, 10)
        << "\n  set Pressure angle          = " << to_string_g(s.pair.pressure_angle / units::deg, 10)
        << "\n  set Addendum coefficient    = " << to_string_g(c2 ? s.pair.addendum : cp.front().y(), 10)
        << "\n  set Dedendum coefficient    = " << to_string_g(c2 ? s.pair.dedendum : -cp.back().y(), 10)
        << "\n  set Root radius coefficient = " << to_string_g(s.pair.root_radius, 10)
        << "\n  set Profile type            = " << (c2 ? "bspline flank" : "bspline rack") << "\n  set Control points          = ";
      for (std::size_t i = 0; i < cp.size(); ++i)
        o << (i ? "; " : "") << to_string_g(cp[i].x(), 12) << ", " << to_string_g(cp[i].y(), 12);
      o << "\n  set Spline degree           = 4\nend\n";
      for (int i : {1, 2})
        o << "subsection Gear " << i << "\n  set Number of teeth = " << (i == 1 ? s.pair.z1 : s.pair.z2)
          << "\n  set Face width      = " << to_string_g(s.face_width * 1e3, 10)
          << (c2 ? "" : "\n  set Tip shortening coefficient = 0.05") << "\nend\n";
      if (c2) // the FE check of Koronaios 2021 (ch. 7), as inputs/seed003_opt_fe_involute.prm
        o << "subsection Mesh\n  set Model        = sector\n  set Sector teeth = 3\n  set h_fillet     = 0.15\n"
             "  set h_body       = 2\nend\nsubsection Solve\n  set Torques             = 5\n"
             "  set Number of positions = 20\n  set VTU                 = none\nend\n";
      f.commit();
    }
  }
} // namespace gearfem::optimise
