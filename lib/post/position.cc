// Evaluation of one converged contact state into the per-position results, and its VTU.
#include "post/position.h"
#include "fem/stress_peak.h"

#include "base/errors.h"
#include "contact/hertz.h"
#include "fem/output.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

namespace gearfem::post
{
  namespace
  {
    using contact::ContactPoint;
    using contact::ContactSolution;
    using geometry::Vec2;

    /// The contact point touches a tip edge (corner, tip rounding or tip land) of either gear.
    bool at_tip_edge(const geometry::MeshingPair &pair, const ContactPoint &p,
                     const std::array<geometry::Placement, 2> &P, double band)
    {
      namespace bd = mesh::boundary;
      const auto tip_code = [](unsigned int c) { return c == bd::tip || c == bd::tip_round_drive; };
      if (tip_code(p.slave_code) || tip_code(p.master_code) || p.master_corner)
        return true;
      // A node at the end of a flank (the sharp corner itself, or the start of a tip
      // rounding) lies on the tip-form circle; test both the slave node and the master point.
      const int S = p.slave_body, M = 3 - S;
      const double rs = (p.x - P[S - 1].centre).norm(), rm = (p.master_point - P[M - 1].centre).norm();
      const double tol = band * pair.module();
      return pair.beyond_tip_form(S, rs, tol) || pair.beyond_tip_form(M, rm, tol);
    }

    /// Peak pressure, profile, ellipse fit and Hertz comparison of one loaded pair.
    void pressure_and_hertz(const geometry::MeshingPair &pair, const fem::Elasticity material[2], ToothPairResult &tp,
                            const ContactSolution &sol, const std::array<geometry::Placement, 2> &P,
                            int min_patch_nodes)
    {
      // Pressure profile along the flank of this pair (its slave nodes, pair frame).
      const ContactPoint *peak = nullptr;
      for (const auto &p : sol.points)
        if (p.tooth(1) == tp.pinion_tooth && (!peak || p.pressure > peak->pressure))
          peak = &p;
      if (!peak)
        return;
      tp.p_max = peak->pressure;
      const Vec2 tau(-peak->normal.y(), peak->normal.x());
      std::vector<std::pair<double, double>> sp;
      for (const auto &p : sol.points)
        {
          if (p.tooth(1) != tp.pinion_tooth || !(p.pressure > 0))
            continue;
          // s along the pinion flank, increasing towards the pinion tip whichever body is slave.
          // (the normal is the master's: flip it when the gear is the slave)
          const double s_along = (p.x - peak->x).dot(tau) * (peak->slave_body == 1 ? 1.0 : -1.0);
          tp.profile.push_back({s_along, (p.x - P[0].centre).norm(), p.pressure});
          sp.emplace_back(s_along, p.pressure);
        }
      std::sort(tp.profile.begin(), tp.profile.end(), [](const auto &a, const auto &b) { return a[0] < b[0]; });
      const auto fit = contact::fit_ellipse(sp);
      tp.resolved    = tp.active_nodes >= min_patch_nodes && fit[0] > 0;
      tp.half_width  = tp.resolved ? fit[0] : 0.0;
      // Hertz on the local radii of curvature at the peak: the involute's sqrt(r^2 - r_b^2),
      // negative for an internal gear's concave flank, or for other profiles (B-spline
      // flanks, closed racks) the curvature of the outline itself (a hollow flank has a
      // negative one; the sum must be positive).
      tp.radius_pinion      = (peak->x - P[0].centre).norm();
      tp.radius_gear        = (peak->x - P[1].centre).norm();
      const auto [rho1, rho2] = pair.radii_of_curvature(peak->x, P);
      if (rho1 != 0 && rho2 != 0)
        {
          const auto &mat1 = material[0], &mat2 = material[1];
          contact::HertzCase hc;
          hc.R1 = rho1, hc.R2 = rho2;
          hc.E1 = mat1.youngs_modulus, hc.E2 = mat2.youngs_modulus;
          hc.nu1 = mat1.poisson_ratio, hc.nu2 = mat2.poisson_ratio;
          hc.thickness = std::min(mat1.thickness, mat2.thickness);
          hc.force     = tp.force;
          hc.model     = mat1.model;
          std::tie(tp.a_hertz, tp.p_hertz) = contact::hertz_closed_form(hc);
        }
    }

    /// The loaded tooth pairs (by pinion tooth) with their forces, node counts and edge flags.
    std::map<int, ToothPairResult> load_sharing(const geometry::MeshingPair &pair, const ContactSolution &sol,
                                                const std::array<geometry::Placement, 2> &P, double band)
    {
      std::map<int, ToothPairResult> pairs;
      double total = 0;
      for (const auto &p : sol.points)
        {
          if (!(p.force > 0))
            continue;
          auto &tp        = pairs[p.tooth(1)];
          tp.pinion_tooth = p.tooth(1), tp.gear_tooth = p.tooth(2);
          tp.slave_body   = p.slave_body;
          tp.force += p.force;
          total += p.force;
          if (p.friction != 0)
            {
              // On the pinion along t = (-n_y, n_x), then towards its tip.
              const Vec2 t(-p.normal.y(), p.normal.x());
              const double on_pinion = p.slave_body == 1 ? p.friction : -p.friction;
              tp.friction += t.dot(p.x - P[0].centre) > 0 ? on_pinion : -on_pinion;
              tp.power_loss += std::abs(p.friction * p.sliding);
            }
          ++tp.active_nodes;
          tp.edge = tp.edge || at_tip_edge(pair, p, P, band);
        }
      for (auto &[k, tp] : pairs)
        tp.share = total > 0 ? tp.force / total : 0.0;
      return pairs;
    }

    /// Peak tension-side (drive) fillet stress of the loaded teeth of pair `tp`.
    void root_stress(const contact::GearContactModel &model, const dealii::Vector<double> u[2], ToothPairResult &tp)
    {
      const int zp = model.pair().teeth(1), zg = model.pair().teeth(2);
      const int kp = ((tp.pinion_tooth % zp) + zp) % zp, kg = ((tp.gear_tooth % zg) + zg) % zg;
      namespace b    = mesh::boundary;
      const auto pk1 = model.body(1).peak_principal_stress(u[0], b::tooth_id(kp, b::fillet_drive));
      const auto pk2 = model.body(2).peak_principal_stress(u[1], b::tooth_id(kg, b::fillet_drive));
      tp.root_stress_pinion = pk1.value, tp.root_radius_pinion = pk1.radius;
      tp.root_stress_gear = pk2.value, tp.root_radius_gear = pk2.radius;
    }
  } // namespace

  void validate(const PostOptions &o)
  {
    if (o.min_patch_nodes < 3)
      throw InputError("Post/Min patch nodes", std::to_string(o.min_patch_nodes), ">= 3",
                       "the ellipse fit of the pressure patch has three parameters");
    if (!(o.loaded_share >= 0 && o.loaded_share < 1))
      throw InputError("Post/Loaded pair share", to_string_g(o.loaded_share), "[0, 1)");
    if (!(o.unresolved_share >= 0 && o.unresolved_share < 1))
      throw InputError("Post/Unresolved share", to_string_g(o.unresolved_share), "[0, 1)");
    require_range("Post/Tip edge band", o.tip_edge_band, 0.0, 0.5, "m_n");
  }

  PositionResult evaluate_contact(const geometry::MeshingPair &pair, const fem::Elasticity material[2],
                                  const contact::ContactState &state, const std::array<geometry::Placement, 2> &P,
                                  const PostOptions &options,
                                  const std::function<void(ToothPairResult &)> &root_stress)
  {
    validate(options);
    PositionResult r;
    r.phi1 = state.phi1, r.torque = state.torque;
    const auto &sol  = state.solution;
    const double rb1 = pair.base_radius(1);
    r.rotation     = sol.q;
    r.ste          = sol.q * rb1;
    r.normal_force = sol.load / rb1;
    r.k_secant     = r.ste > 0 ? r.normal_force / r.ste : 0.0;
    r.k_tangent    = sol.tangent / (rb1 * rb1);
    for (const auto &p : sol.points)
      {
        r.friction_force += std::abs(p.friction);
        // T1 w1 - T2 w2 = -sum F_1 . (v_1 - v_2) = -sum lambda (n + mu s t) . (v_S - v_M) for
        // either slave body: the friction term is the loss, the normal term this.
        r.normal_power -= options.pinion_speed * p.force * p.approach;
      }

    // Load sharing, pressure and root stress by tooth pair.
    auto pairs = load_sharing(pair, sol, P, options.tip_edge_band);
    for (auto &[k, tp] : pairs)
      {
        pressure_and_hertz(pair, material, tp, sol, P, options.min_patch_nodes);
        if (root_stress)
          root_stress(tp);
        r.max_root_stress_pinion = std::max(r.max_root_stress_pinion, tp.root_stress_pinion);
        r.max_root_stress_gear   = std::max(r.max_root_stress_gear, tp.root_stress_gear);
        tp.power_loss *= options.pinion_speed;
        r.power_loss += tp.power_loss;
        (tp.edge ? r.p_max_edge : r.p_max) = std::max(tp.edge ? r.p_max_edge : r.p_max, tp.p_max);
      }
    for (auto &[k, tp] : pairs)
      {
        if (tp.share > options.loaded_share)
          ++r.n_pairs;
        r.pairs.push_back(std::move(tp));
      }
    return r;
  }

  namespace
  {
    /// Peak fillet sigma_1 of tooth `tooth` of gear i from its observed stresses `s`.
    std::pair<double, double> observed_root_stress(const contact::GearContactModel &model, int i, int tooth,
                                                   const Eigen::VectorXd &s)
    {
      for (const auto &o : model.fillets(i))
        {
          if (o.tooth != tooth)
            continue;
          std::vector<double> s1(o.x.size());
          for (std::size_t k = 0; k < o.x.size(); ++k)
            {
              const Eigen::Index r = o.first_row + Eigen::Index(3 * k);
              s1[k]                = fem::principal_stresses(s[r], s[r + 1], s[r + 2])[0];
            }
          const auto pk = fem::fitted_peak(o.arc, s1, fem::fillet_samples_per_face);
          return {pk.value, o.x.at(pk.index).norm()};
        }
      throw SolverError("root stress: tooth " + std::to_string(tooth) + " of gear " + std::to_string(i) +
                        " is loaded but not observed (not a fine tooth)");
    }

    /// evaluate_position without displacement fields: root stresses and the bore reaction
    /// from the influence coefficients of the flexibility cache (the same linear maps).
    PositionResult evaluate_observed(const contact::GearContactModel &model, const contact::ContactState &state,
                                     const PostOptions &options)
    {
      const auto &sol = state.solution;
      const Eigen::VectorXd s[2] = {model.solver().observed_response(1, sol.forces[0]),
                                    model.solver().observed_response(2, sol.forces[1])};
      const int z[2] = {model.pair().teeth(1), model.pair().teeth(2)};
      const fem::Elasticity material[2] = {model.body(1).material(), model.body(2).material()};
      PositionResult r = evaluate_contact(model.pair(), material, state, model.placements(state.phi1, sol.q), options,
                                          [&](ToothPairResult &tp) {
                                            const int kp = ((tp.pinion_tooth % z[0]) + z[0]) % z[0];
                                            const int kg = ((tp.gear_tooth % z[1]) + z[1]) % z[1];
                                            std::tie(tp.root_stress_pinion, tp.root_radius_pinion) =
                                              observed_root_stress(model, 1, kp, s[0]);
                                            std::tie(tp.root_stress_gear, tp.root_radius_gear) =
                                              observed_root_stress(model, 2, kg, s[1]);
                                          });
      double m[2] = {0, 0};
      for (int b = 0; b < 2; ++b)
        {
          const auto &pts = model.body(b + 1).dof_points();
          const auto &cmp = model.body(b + 1).dof_components();
          for (const auto &[d, v] : sol.forces[b])
            m[b] += cmp[d] == 0 ? -pts[d][1] * v : pts[d][0] * v;
        }
      r.torque_contact  = -m[0];
      r.torque_reaction = s[0][model.reaction_row(1)];
      r.torque_gear     = std::abs(m[1]);
      return r;
    }
  } // namespace

  PositionResult evaluate_position(const contact::GearContactModel &model, const contact::ContactState &state,
                                   const PostOptions &options, bool keep)
  {
    if (model.observes_root_stress() && !keep)
      return evaluate_observed(model, state, options);
    const auto &sol = state.solution;
    // Full displacement fields and equilibrium checks.
    const fem::ElasticBody &b1 = model.body(1), &b2 = model.body(2);
    dealii::Vector<double> f[2] = {dealii::Vector<double>(b1.n_dofs()), dealii::Vector<double>(b2.n_dofs())};
    for (int b = 0; b < 2; ++b)
      for (const auto &[d, v] : sol.forces[b])
        f[b][d] += v;
    dealii::Vector<double> u[2] = {b1.solve(f[0]), b2.solve(f[1])};
    const fem::Elasticity material[2] = {b1.material(), b2.material()};
    PositionResult r = evaluate_contact(model.pair(), material, state, model.placements(state.phi1, sol.q), options,
                                        [&](ToothPairResult &tp) { root_stress(model, u, tp); });
    r.torque_contact  = -b1.moment(f[0]);
    r.torque_reaction = b1.moment(b1.reactions(u[0], f[0]));
    r.torque_gear     = std::abs(b2.moment(f[1]));
    if (keep)
      r.u[0] = std::move(u[0]), r.u[1] = std::move(u[1]);
    return r;
  }

  void write_vtu(const contact::GearContactModel &model, const contact::ContactState &state,
                 const PositionResult &r, const std::filesystem::path &file, double scale)
  {
    if (r.u[0].size() == 0)
      throw SolverError("write_vtu: the position was evaluated without keeping displacements");
    const auto P = model.placements(state.phi1, state.rotation());
    // Contact traction p n at the slave nodes of each body, in its body frame.
    dealii::Vector<double> traction[2] = {dealii::Vector<double>(model.body(1).n_dofs()),
                                          dealii::Vector<double>(model.body(2).n_dofs())};
    for (const auto &p : state.solution.points)
      {
        const int S    = p.slave_body;
        const auto &nd = model.surface(S).nodes()[p.node];
        const double c = std::cos(-P[S - 1].angle), s = std::sin(-P[S - 1].angle);
        const geometry::Vec2 n(c * p.normal.x() - s * p.normal.y(), s * p.normal.x() + c * p.normal.y());
        traction[S - 1][nd.dof_x] = p.pressure * n.x();
        traction[S - 1][nd.dof_y] = p.pressure * n.y();
      }
    std::vector<fem::PlacedBody> pb(2);
    for (int i = 0; i < 2; ++i)
      {
        pb[i].body      = &model.body(i + 1);
        pb[i].u         = &r.u[i];
        pb[i].traction  = &traction[i];
        pb[i].angle     = P[i].angle;
        pb[i].centre[0] = P[i].centre.x();
        pb[i].centre[1] = P[i].centre.y();
      }
    fem::write_placed_vtu(pb, file, scale);
  }

  Evaluator::Evaluator(const contact::GearContactModel &model, const PostOptions &options)
    : model_(model)
    , options_(options)
    , timer_(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times)
  {}

  PositionResult Evaluator::operator()(const contact::ContactState &s, bool keep)
  {
    const double before = contact::section_seconds(timer_, "post");
    PositionResult r;
    {
      dealii::TimerOutput::Scope scope(timer_, "post");
      r = evaluate_position(model_, s, options_, keep);
    }
    r.t_post = contact::section_seconds(timer_, "post") - before;
    return r;
  }
} // namespace gearfem::post
