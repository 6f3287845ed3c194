// Evaluation of one Koronaios 2021 design: sampled range, statistics, objective, constraints and
// gearfem's design checks (see design.h).
#include "base/errors.h"
#include "geometry/curve.h"
#include "base/units.h"
#include "optimise/design.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gearfem::optimise
{
  using geometry::rotate;

  namespace
  {

    /// Flank parameter where f(at(t)) = target on a grid of the whole flank; NaN if the
    /// grid has no sign change.
    template <typename F>
    double crossing(const FlankKinematics &k, F &&f, double target, const std::string &what)
    {
      const auto &c = k.flank();
      const int   M = 64;
      double      ta = c.t_begin(), fa = f(k.at(ta)) - target;
      if (fa == 0)
        return ta;
      for (int j = 1; j <= M; ++j)
        {
          const double tb = c.t_begin() + (c.t_end() - c.t_begin()) * j / M, fb = f(k.at(tb)) - target;
          if (fb == 0)
            return tb;
          if ((fa < 0) != (fb < 0))
            return k.solve(f, target, ta, tb, what);
          ta = tb, fa = fb;
        }
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// Sampled range [ta, tb] and sampling of a design kind. Throws SolverError with the
    /// named reason when the path of contact misses a tip circle.
    struct Range
    {
      double ta, tb;
      Sampling sampling;
    };
    Range sampled_range(DesignKind kind, const FlankKinematics &k, const PairData &p,
                        const EvaluationSettings &s)
    {
      const auto &c = k.flank();
      if (kind == DesignKind::sinusoid || kind == DesignKind::case1_rack)
        return {c.t_begin(), c.t_end(), Sampling::rack_abscissa};
      auto r1 = [](const ContactSample &q) { return q.r1; };
      auto r2 = [](const ContactSample &q) { return q.r2; };
      double ta;
      if (s.start_radius > 0)
        {
          ta = crossing(k, r1, s.start_radius, "pinion flank parameter at the start radius");
          if (std::isnan(ta))
            throw InputError("Optimise/Start radius", mm_text(s.start_radius),
                             "a radius on the designed pinion flank");
        }
      else
        {
          // Where the path meets gear 2's tip circle; when it does not on the designed flank,
          // the whole flank is sampled and the constraint reaches_gear2_tip is violated.
          ta = crossing(k, r2, p.tip_radius(2), "start of active profile");
          if (std::isnan(ta))
            ta = c.t_begin();
        }
      double tb = crossing(k, r1, p.tip_radius(1), "pinion tip");
      if (std::isnan(tb))
        throw SolverError("the designed pinion flank does not reach the tip circle r_a1 = " +
                          mm_text(p.tip_radius(1)));
      return {ta, tb, Sampling::pinion_radius};
    }

    /// Case 2's constraints on the recovered rack and the reach of the path, from a grid of
    /// the whole flank: (reaches_gear2_tip, rack_above_cutter_tip, rack_monotone).
    std::array<double, 3> rack_constraints(const FlankKinematics &k, const PairData &p)
    {
      const auto         &c = k.flank();
      const int           M = 100;
      // A uniform grid plus points 1e-6 inside both ends: the slope at the ends is where
      // gearfem's own check (u' > 0 at every spline parameter) first fails.
      std::vector<double> t, u;
      for (int i = 0; i <= M; ++i)
        {
          t.push_back(c.t_begin() + (c.t_end() - c.t_begin()) * i / M);
          if (i == 0 || i == M - 1)
            t.push_back(c.t_begin() + (c.t_end() - c.t_begin()) * (i == 0 ? 1e-6 : 1 - 1e-6));
        }
      double vmin = std::numeric_limits<double>::infinity(), r2_low = 0;
      for (std::size_t i = 0; i < t.size(); ++i)
        {
          const ContactSample q = k.at(t[i]);
          u.push_back(q.rack_u), vmin = std::min(vmin, q.rack_v);
          if (i == 0)
            r2_low = q.r2;
        }
      const double trend = (u.back() - u.front()) / (t.back() - t.front());
      double       worst = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i + 1 < t.size(); ++i)
        worst = std::max(worst, -(u[i + 1] - u[i]) / (t[i + 1] - t[i]) / trend);
      const double m = p.module;
      // Margin: every slope at least 2 % of the mean slope, so that the exact end derivative
      // that gearfem checks cannot have crossed zero between the grid points.
      return {(p.tip_radius(2) - r2_low) / m, (-p.dedendum * m - vmin) / m, std::abs(trend) > 0 ? worst + 0.02 : 1.0};
    }
  } // namespace

  Evaluation Design::evaluate_unchecked(const std::vector<double> &x, const EvaluationSettings &s) const
  {
    const double    m = pair_.module;
    Evaluation      ev;
    const geometry::CurvePtr rk = rack(x);
    // Case 1: the rack must run from crest to trough with u increasing (a function v(u)).
    if (rk)
      for (int i = 0; i <= 200; ++i)
        {
          const double t = rk->t_begin() + (rk->t_end() - rk->t_begin()) * i / 200;
          if (!(rk->d1(t).x() > 0))
            throw SolverError("rack not a function v(u): u' <= 0 at rack height v = " + mm_text(rk->point(t).y()));
        }
    const geometry::CurvePtr fl = flank(x);
    const FlankKinematics    k(fl, pair_.r01(), pair_.r02());
    const Range              range = sampled_range(kind_, k, pair_, s);
    ev.samples                     = sample_flank(k, range.ta, range.tb, s.samples, range.sampling);

    std::vector<double> kap;
    double              Kmin = ev.samples.front().K, Kmax = Kmin;
    for (const auto &q : ev.samples)
      {
        if (!std::isfinite(q.kappa_eq))
          throw SolverError("singular curvature (a cusp on gear 2) at pinion radius " + mm_text(q.r1));
        kap.push_back(q.kappa_eq);
        Kmin = std::min(Kmin, q.K), Kmax = std::max(Kmax, q.K);
      }
    ev.stats         = statistics(kap);
    ev.contact_ratio = (Kmax - Kmin) / (units::pi * m);
    ev.start_radius  = ev.samples.front().r1;
    // int (1/R)^2 dx, x the flank abscissa in position 2 [mm], trapezoidal over the samples.
    const double turn = 4 * units::pi / pair_.z1;
    for (std::size_t i = 0; i + 1 < ev.samples.size(); ++i)
      {
        const double xa = rotate(fl->point(ev.samples[i].t), turn).x() * 1e3;
        const double xb = rotate(fl->point(ev.samples[i + 1].t), turn).x() * 1e3;
        const double ka = kap[i] * 1e-3, kb = kap[i + 1] * 1e-3;
        ev.integral += 0.5 * (ka * ka + kb * kb) * std::abs(xb - xa);
      }
    ev.x_extent  = std::abs(rotate(fl->point(ev.samples.back().t), turn).x() -
                            rotate(fl->point(ev.samples.front().t), turn).x()) * 1e3;
    ev.objective = objective(kind_, ev.stats, ev.integral, ev.contact_ratio, s.weights);
    if (!std::isfinite(ev.objective))
      throw SolverError("objective not finite (contact ratio " + to_string_g(ev.contact_ratio) + ")");

    // Constraints on the whole designed flank (201 points): C1 in position 2, C2 in position 1;
    // and the generated flank must not fold back (undercut cusp: radius not monotone).
    double c_dec = -1, c_ovl = -1, r_prev = 0, dr_prev = 0;
    for (int i = 0; i <= 200; ++i)
      {
        const double t = fl->t_begin() + (fl->t_end() - fl->t_begin()) * i / 200;
        const Vec2   P = fl->point(t), T = rotate(fl->d1(t), turn);
        c_dec          = std::max(c_dec, T.x() * T.y() / T.squaredNorm());
        c_ovl          = std::max(c_ovl, -P.x() / m);
        const double r = P.norm();
        if (i > 0 && dr_prev != 0 && (r - r_prev) * dr_prev < 0)
          throw SolverError("undercut: the generated pinion flank folds back near r = " + mm_text(r));
        if (i > 0)
          dr_prev = r - r_prev;
        r_prev = r;
      }
    // C1 is the thesis' condition on a flank modelled as y(x) in position 2 (case 2); a case-1
    // tooth has a horizontal tangent at its crest, where any turned flank rises.
    ev.constraints[decreasing_in_position_2]    = kind_ == DesignKind::case2_flank ? c_dec : -1.0;
    ev.constraints[flanks_do_not_overlap]       = c_ovl;
    ev.constraints[contact_ratio_minimum]       = s.min_contact_ratio - ev.contact_ratio;
    ev.constraints[positive_relative_curvature] = -ev.stats.min * m;
    if (kind_ == DesignKind::case2_flank)
      {
        const auto rc                          = rack_constraints(k, pair_);
        ev.constraints[reaches_gear2_tip]      = rc[0];
        ev.constraints[rack_above_cutter_tip]  = rc[1];
        ev.constraints[rack_monotone]          = rc[2];
      }
    else
      for (int c : {reaches_gear2_tip, rack_above_cutter_tip, rack_monotone})
        ev.constraints[c] = -1; // case 2's recovered rack only
    ev.computable                               = true;

    for (int c = 0; c < n_constraints; ++c)
      if (!(ev.constraints[c] <= 1e-9))
        {
          ev.reason = std::string(constraint_name(c)) + " violated (" + to_string_g(ev.constraints[c]) + " > 0)";
          return ev;
        }
    if (kind_ == DesignKind::case2_flank && s.design_checks)
      try
        {
          const auto g1 = geometry::ToothProfile::generate(gear_parameters(1, x));
          auto       g2 = geometry::ToothProfile::generate_mate(gear_parameters(2, x), g1);
          geometry::GearPair pair(g1, std::move(g2), geometry::PairParameters{});
        }
      catch (const InputError &e)
        {
          ev.reason = std::string("gearfem design check: ") + e.what();
          return ev;
        }
    ev.feasible = true;
    return ev;
  }
} // namespace gearfem::optimise
