#include "condensed/cycle.h"

#include "base/errors.h"
#include "base/progress.h"
#include "base/units.h"
#include "mesh/domain.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <iomanip>
#include <set>
#include <sstream>

namespace gearfem::condensed
{
  std::string condensed_key(const solve::GearContactInput &in)
  {
    return solve::model_key(in, true);
  }

  void check_condensable(const solve::GearContactInput &in)
  {
    in.require_external("the condensed cycle");
    using Relief = geometry::TipRelief::Kind;
    const bool relief = in.pair->gear(1).parameters().relief.kind != Relief::none ||
                        in.pair->gear(2).parameters().relief.kind != Relief::none;
    if (relief && !in.contact.micro_geometry_as_gap)
      throw InputError("Contact/Micro-geometry", "geometry", "gap",
                       "the condensed cycle applies a tip relief as a gap modification on the unmodified "
                       "mesh; a relief meshed as geometry is a different mesh");
    if (in.contact.friction > 0 || in.friction.law != analytical::friction::Law::constant)
      throw InputError(in.friction.law == analytical::friction::Law::constant ? "Contact/Friction coefficient"
                                                                             : "Contact/Friction law",
                       in.friction.law == analytical::friction::Law::constant ? to_string_g(in.contact.friction)
                                                                             : analytical::friction::to_string(in.friction.law),
                       "0 (constant)", "the condensed cycle stores the frictionless operator (docs/friction.md)");
  }

  const contact::CondensedPosition &CondensedCycle::at(std::size_t k, double torque) const
  {
    const auto &scenes = cycle.at(k);
    if (!(torque >= torque_lo * (1 - 1e-12) && torque <= torque_hi * (1 + 1e-12)))
      throw SolverError("torque " + to_string_g(torque) + " N m is outside the torque range of the condensed cycle [" +
                        to_string_g(torque_lo) + ", " + to_string_g(torque_hi) +
                        "] N m (Condense/Torque range): rebuild the cycle with a range that covers it");
    for (const auto &s : scenes)
      if (torque <= s.load_hi * (1 + 1e-12))
        return s;
    return scenes.back();
  }

  namespace
  {
    bool same_scene(const contact::Scene &a, const contact::Scene &b)
    {
      return a.slave_nodes[0] == b.slave_nodes[0] && a.slave_nodes[1] == b.slave_nodes[1] &&
             a.master_pieces[0] == b.master_pieces[0] && a.master_pieces[1] == b.master_pieces[1];
    }

    /// The torques [N m] in (lo, hi) at which the scene of position phi1 changes: a geometric
    /// grid of 48 torques, each change located by bisection in log T.
    std::vector<double> scene_breaks(const contact::GearContactModel &model, double phi1, double lo, double hi)
    {
      const double rb1 = model.pair().base_radius(1);
      const auto scene = [&](double T) { return model.scene(phi1, T / rb1); };
      std::vector<double> out;
      if (!(hi > lo))
        return out;
      constexpr int n = 48;
      double t_prev       = lo;
      contact::Scene prev = scene(lo);
      for (int i = 1; i <= n; ++i)
        {
          const double t      = lo * std::pow(hi / lo, double(i) / n);
          contact::Scene next = scene(t);
          if (!same_scene(prev, next))
            {
              double a = t_prev, b = t;
              for (int it = 0; it < 60 && b > a * (1 + 1e-12); ++it)
                {
                  const double m = std::sqrt(a * b);
                  (same_scene(scene(m), prev) ? a : b) = m;
                }
              out.push_back(b);
            }
          t_prev = t, prev = std::move(next);
        }
      return out;
    }
  } // namespace

  CycleRange cycle_range(const std::vector<double> &torques, CycleUse use, double build)
  {
    if (torques.empty())
      throw InputError("Solve/Torques", "(none)", "at least one torque > 0 N m");
    const double lo = *std::min_element(torques.begin(), torques.end());
    const double hi = *std::max_element(torques.begin(), torques.end());
    CycleRange r;
    switch (use)
      {
        case CycleUse::given_torques:
          r.build = build > 0 ? build : std::sqrt(lo * hi);
          r.lo = std::min(lo, r.build), r.hi = std::max(hi, r.build);
          break;
        case CycleUse::variants:
          r.build = build > 0 ? build : hi;
          r.lo = std::min(0.25 * lo, r.build), r.hi = std::max(2 * hi, r.build);
          break;
        case CycleUse::slices:
          r.build = build > 0 ? build : hi;
          r.lo = std::min(lo / 8, r.build), r.hi = std::max(4 * hi, r.build);
          break;
      }
    return r;
  }

  double scene_ratio(CycleUse use, double requested)
  {
    if (requested >= 0)
      return requested;
    return use == CycleUse::slices ? 0.0 : 4.0;
  }

  CondensedCycle cycle_for(contact::GearContactModel &model, const solve::GearContactInput &in,
                           const CycleRange &range, const CycleOptions &options)
  {
    check_condensable(in);
    CondensedCycle c = cycle_for(model, in.positions(), range, options);
    c.key           = condensed_key(in);
    c.geometry_hash = geometry::geometry_fingerprint(in.unmodified_pair ? *in.unmodified_pair : *in.pair);
    c.method        = contact::to_string(in.contact.method);
    return c;
  }

  CondensedCycle cycle_for(contact::GearContactModel &model,
                           const std::vector<std::pair<std::string, double>> &positions, const CycleRange &range,
                           const CycleOptions &options)
  {
    const double build_torque = range.build, torque_lo = range.lo, torque_hi = range.hi;
    const double scene_ratio  = options.scene_ratio;
    std::ostream *out         = options.out;
    if (!(scene_ratio == 0 || (scene_ratio > 1 && std::isfinite(scene_ratio))))
      throw InputError("Condense/Scene torque ratio", to_string_g(scene_ratio), "0 (no split) or > 1");
    require_greater("Condense/Build torque", build_torque, 0.0, "N m");
    if (!(torque_lo > 0 && torque_lo <= build_torque && build_torque <= torque_hi && std::isfinite(torque_hi)))
      throw InputError("Condense/Torque range", to_string_g(torque_lo) + ", " + to_string_g(torque_hi),
                       "0 < low <= build torque (" + to_string_g(build_torque) + " N m) <= high");
    const auto t0 = std::chrono::steady_clock::now();
    CondensedCycle c;
    c.build_torque  = build_torque;
    c.torque_lo = torque_lo, c.torque_hi = torque_hi;
    c.positions     = positions;
    c.setup_seconds = model.setup_seconds();
    c.dofs          = int(model.n_dofs());
    auto &solver    = model.contact_solver();
    model.observe_root_stress();
    for (int i = 1; i <= 2; ++i)
      {
        c.body[i - 1].teeth = model.pair().teeth(i);
        for (const auto &o : model.fillets(i))
          {
            FilletSamples fs;
            fs.tooth = o.tooth, fs.first_row = o.first_row, fs.arc = o.arc;
            for (const auto &x : o.x)
              fs.x.push_back(x.x()), fs.y.push_back(x.y());
            c.body[i - 1].fillets.push_back(std::move(fs));
          }
      }

    Progress progress(out, c.positions.size(), "condense position");
    const double rb1 = model.pair().base_radius(1);
    std::map<double, contact::ContactSolution> warm; // the last solution at each solve torque
    for (std::size_t k = 0; k < c.positions.size(); ++k)
      {
        const double phi1 = c.positions[k].second;
        std::vector<double> bounds = {torque_lo};
        for (const double b : scene_breaks(model, phi1, torque_lo, torque_hi))
          bounds.push_back(b);
        bounds.push_back(torque_hi);
        if (scene_ratio > 1)
          {
            // Splits at build * ratio^(j + 1/2), strictly inside the range and apart from the
            // slave breaks: no re-solve more than sqrt(ratio) from its build.
            std::vector<double> cuts;
            for (double b = build_torque * std::sqrt(scene_ratio); b < torque_hi * (1 - 1e-9); b *= scene_ratio)
              cuts.push_back(b);
            for (double b = build_torque / std::sqrt(scene_ratio); b > torque_lo * (1 + 1e-9); b /= scene_ratio)
              cuts.push_back(b);
            for (const double b : cuts)
              if (std::none_of(bounds.begin(), bounds.end(),
                               [b](double x) { return std::abs(x - b) <= 1e-9 * std::abs(b); }))
                bounds.push_back(b);
            std::sort(bounds.begin(), bounds.end());
          }
        c.cycle.emplace_back();
        for (std::size_t s = 0; s + 1 < bounds.size(); ++s)
          {
            // Solve the scene at the build torque, or at the geometric middle of its range.
            const double lo = bounds[s], hi = bounds[s + 1];
            const double T  = build_torque >= lo && build_torque < hi ? build_torque :
                              s + 2 == bounds.size() && build_torque == hi ? build_torque :
                                                                              std::sqrt(lo * hi);
            const auto w       = warm.find(T);
            const auto state   = model.solve(phi1, T, w == warm.end() ? nullptr : &w->second);
            const double sd    = solver.options().search_distance;
            const double band  = options.band_factor > 0 ?
                                   std::min(sd, std::max(options.band_factor * std::abs(state.solution.q) * rb1 * torque_hi / T,
                                                         sd / 20)) :
                                   0.0;
            auto p             = solver.condense(model.scene(phi1, T / rb1), state.solution, band);
            p.load_lo = lo, p.load_hi = hi;
            c.cycle.back().push_back(std::move(p));
            warm[T] = state.solution;
          }
        std::ostringstream d;
        d << "roll " << std::fixed << std::setprecision(3) << phi1 / units::deg << " deg, "
          << c.cycle.back().front().size() << " candidates, " << c.cycle.back().size() << " scene(s)";
        progress.step(k + 1, d.str());
      }

    for (int b = 0; b < 2; ++b)
      {
        auto &body      = c.body[b];
        const auto &uni = solver.universe(b + 1);
        const auto &pts = model.body(b + 1).dof_points();
        const auto &cmp = model.body(b + 1).dof_components();
        for (const unsigned int d : uni)
          {
            body.x.push_back(pts[d][0]);
            body.y.push_back(pts[d][1]);
            body.component.push_back(cmp[d]);
          }
        std::set<int> used;
        for (const auto &scenes : c.cycle)
          for (const auto &p : scenes)
            for (const auto &row : p.B[b])
              for (const auto &[i, v] : row)
                used.insert(i);
        body.stress_columns.assign(used.begin(), used.end());
        solver.compute_columns(b + 1, body.stress_columns);
        const Eigen::MatrixXd &S = solver.observed(b + 1);
        body.stress.resize(S.rows(), Eigen::Index(body.stress_columns.size()));
        for (std::size_t j = 0; j < body.stress_columns.size(); ++j)
          body.stress.col(Eigen::Index(j)) = S.col(body.stress_columns[j]);
      }
    c.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return c;
  }
} // namespace gearfem::condensed
