#include "condensed/resolve.h"

#include "base/errors.h"
#include "base/progress.h"
#include "base/units.h"
#include "fem/elasticity.h"
#include "fem/stress_peak.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::condensed
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
  } // namespace

  Resolver::Resolver(const CondensedCycle &cycle, const solve::GearContactInput &variant)
    : cycle_(cycle)
    , in_(variant)
  {
    check_condensable(variant);
    if (condensed_key(variant) != cycle.key)
      throw InputError("--condensed", cycle.input_name.empty() ? "(the cycle)" : cycle.input_name,
                       "a condensed cycle built from the same geometry, mesh, material, finite elements and "
                       "contact options",
                       "the variant's model differs from the cycle's (only torques, positions, outputs and a "
                       "gap-route tip relief may differ); build its own cycle with `gearfem condense`");
    for (const auto &[name, phi] : variant.positions())
      {
        std::size_t best = cycle.positions.size();
        for (std::size_t k = 0; k < cycle.positions.size(); ++k)
          if (std::abs(cycle.positions[k].second - phi) <= 1e-12 * std::max(1.0, std::abs(phi)))
            best = k;
        if (best == cycle.positions.size())
          throw InputError("Solve (positions)", to_string_g(phi / units::deg) + " deg",
                           "a roll angle of the condensed cycle (" + std::to_string(cycle.positions.size()) +
                             " positions from " + to_string_g(cycle.positions.front().second / units::deg) +
                             " deg)",
                           "the condensed route re-solves the stored positions only");
        index_.push_back(best);
      }
    for (int b = 0; b < 2; ++b)
      {
        column_[b].assign(cycle.body[b].x.size(), -1);
        for (std::size_t j = 0; j < cycle.body[b].stress_columns.size(); ++j)
          column_[b][cycle.body[b].stress_columns[j]] = int(j);
        material_[b] = variant.material[b];
      }
  }

  Eigen::VectorXd Resolver::offsets(std::size_t k) const
  {
    return offsets(cycle_.cycle.at(k).front());
  }

  Eigen::VectorXd relief_offsets(const contact::CondensedPosition &p, const geometry::GearPair &pair)
  {
    Eigen::VectorXd o = Eigen::VectorXd::Zero(Eigen::Index(p.size()));
    using Relief      = geometry::TipRelief::Kind;
    const geometry::ToothProfile *g[2] = {&pair.gear(1), &pair.gear(2)};
    const bool any[2] = {g[0]->parameters().relief.kind != Relief::none, g[1]->parameters().relief.kind != Relief::none};
    if (!any[0] && !any[1])
      return o;
    for (std::size_t c = 0; c < p.size(); ++c)
      for (const auto &s : p.modification[c])
        if (any[s.body - 1])
          o[Eigen::Index(c)] += s.weight * g[s.body - 1]->relief_at_radius(s.x.norm());
    return o;
  }

  Eigen::VectorXd Resolver::offsets(const contact::CondensedPosition &p) const { return relief_offsets(p, *in_.pair); }

  std::pair<double, double> Resolver::root_stress(int b, int tooth, const std::vector<std::pair<int, double>> &f) const
  {
    const auto &body = cycle_.body[b];
    for (const auto &fs : body.fillets)
      {
        if (fs.tooth != tooth)
          continue;
        // sigma = sum over the forces of their stress column times the force: column by column
        // (contiguous in the column-major influence matrix), each entry summed in the order of
        // the forces as before, so the values are the same to the last bit.
        const Eigen::Index n_rows = Eigen::Index(3 * fs.size());
        Eigen::VectorXd sigma = Eigen::VectorXd::Zero(n_rows);
        for (const auto &[u, v] : f)
          {
            const int j = column_[b][u];
            if (j < 0)
              throw SolverError("condensed re-solve: a force at universe DoF " + std::to_string(u) + " of body " +
                                std::to_string(b + 1) + " has no stored stress influence (corrupt cycle?)");
            const double *col = body.stress.data() + Eigen::Index(j) * body.stress.rows() + fs.first_row;
            for (Eigen::Index r = 0; r < n_rows; ++r)
              sigma[r] += col[r] * v;
          }
        std::vector<double> s1(fs.size());
        for (std::size_t i = 0; i < fs.size(); ++i)
          s1[i] = fem::principal_stresses(sigma[Eigen::Index(3 * i)], sigma[Eigen::Index(3 * i + 1)],
                                          sigma[Eigen::Index(3 * i + 2)])[0];
        const auto pk = fem::fitted_peak(fs.arc, s1, fem::fillet_samples_per_face);
        return {pk.value, std::hypot(fs.x.at(pk.index), fs.y.at(pk.index))};
      }
    throw SolverError("condensed re-solve: tooth " + std::to_string(tooth) + " of gear " + std::to_string(b + 1) +
                      " is loaded but the cycle holds no fillet influence for it (not a fine tooth)");
  }

  Resolved Resolver::solve(std::size_t k, double torque, const post::PostOptions &options) const
  {
    require_greater("Solve/Torques", torque, 0.0, "N m");
    return solve(k, torque, offsets(cycle_.at(k, torque)), options);
  }

  Resolved Resolver::solve(std::size_t k, double torque, const Eigen::VectorXd &off,
                           const post::PostOptions &options) const
  {
    return solve(k, torque, off, Eigen::VectorXd(), options);
  }

  Resolved Resolver::solve(std::size_t k, double torque, const Eigen::VectorXd &off, const Eigen::VectorXd &advance,
                           const post::PostOptions &options) const
  {
    require_greater("Solve/Torques", torque, 0.0, "N m");
    const auto t0 = Clock::now();
    Resolved r;
    contact::CondensedSolution cs;
    const contact::CondensedPosition *pp = nullptr;
    try
      {
        pp = &cycle_.at(k, torque);
        cs = contact::solve_condensed(*pp, off, advance, torque);
      }
    catch (const SolverError &e)
      {
        throw SolverError("position phi1 = " + to_string_g(cycle_.positions[k].second / units::deg) + " deg, torque " +
                          to_string_g(torque) + " N m: " + e.what());
      }
    r = evaluate(k, *pp, torque, std::move(cs), options);
    r.state.t_contact = since(t0) - r.result.t_post;
    return r;
  }

  Resolved Resolver::evaluate(std::size_t k, const contact::CondensedPosition &p, double torque,
                              contact::CondensedSolution cs, const post::PostOptions &options) const
  {
    Resolved r;
    r.state.phi1      = cycle_.positions[k].second;
    r.state.torque    = torque;
    r.state.solution  = std::move(cs.solution);

    const auto t1 = Clock::now();
    std::array<geometry::Placement, 2> P = {p.placement[0], p.placement[1]};
    P[0].angle += r.state.solution.q;
    const int z[2] = {cycle_.body[0].teeth, cycle_.body[1].teeth};
    r.result = post::evaluate_contact(*in_.pair, material_, r.state, P, options, [&](post::ToothPairResult &tp) {
      const int kp = ((tp.pinion_tooth % z[0]) + z[0]) % z[0], kg = ((tp.gear_tooth % z[1]) + z[1]) % z[1];
      std::tie(tp.root_stress_pinion, tp.root_radius_pinion) = root_stress(0, kp, cs.universe_forces[0]);
      std::tie(tp.root_stress_gear, tp.root_radius_gear)     = root_stress(1, kg, cs.universe_forces[1]);
    });
    // Moments of the nodal forces about each body's centre (body frame, centre at the origin),
    // as fem::ElasticBody::moment; the bore reaction balances the applied moment exactly
    // (discrete equilibrium of the clamped body), so it is the same number here.
    double m[2] = {0, 0};
    for (int b = 0; b < 2; ++b)
      for (const auto &[u, v] : cs.universe_forces[b])
        m[b] += cycle_.body[b].component[u] == 0 ? -cycle_.body[b].y[u] * v : cycle_.body[b].x[u] * v;
    r.result.torque_contact  = -m[0];
    r.result.torque_reaction = -m[0];
    r.result.torque_gear     = std::abs(m[1]);
    r.result.t_post          = since(t1);
    return r;
  }

  contact::ContactState CycleSolver::solve(const loading::SweepPoint &p, const contact::ContactSolution *)
  {
    Resolved r = resolve(p);
    contact_ += r.state.t_contact;
    post_ += r.result.t_post;
    last_ = std::move(r.result);
    return std::move(r.state);
  }

  Resolved CycleSolver::resolve(const loading::SweepPoint &p)
  {
    return resolver_.solve(resolver_.positions()[p.position_index], p.torque, options_);
  }

  solve::SolveRunResult run_condensed(const CondensedCycle &cycle, const solve::GearContactInput &in,
                                      const solve::SolveRunOptions &options)
  {
    post::validate(options.post);
    const Resolver resolver(cycle, in);
    CycleSolver solver(resolver, options.post);
    loading::SweepPlan plan;
    plan.positions = in.positions();
    plan.torques   = in.solve.torques;
    solve::PointsSettings settings;
    settings.program        = "gearfem solve --condensed";
    settings.journal        = false;
    settings.progress_every = 0; // a line per millisecond position would cost more than the solve
    return solve::run_points(solver, in, plan, options, settings);
  }
} // namespace gearfem::condensed
