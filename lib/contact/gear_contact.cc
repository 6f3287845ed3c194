// GearContactModel: the two gear bodies, per-position contact solves and post-processing.
#include "contact/gear_contact.h"

#include "base/errors.h"
#include "contact/hertz.h"
#include "fem/output.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace gearfem::contact
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    double since(Clock::time_point t0)
    {
      return std::chrono::duration<double>(Clock::now() - t0).count();
    }
    const double pi = 3.14159265358979323846;

    std::set<unsigned int> surface_ids(const std::vector<int> &teeth, bool master)
    {
      namespace b = mesh::boundary;
      std::set<unsigned int> ids;
      for (const int k : teeth)
        {
          ids.insert(b::tooth_id(k, b::flank_drive));
          ids.insert(b::tooth_id(k, b::tip));
          ids.insert(b::tooth_id(k, b::tip_round_drive));
          if (master)
            ids.insert(b::tooth_id(k, b::fillet_drive));
        }
      return ids;
    }
  } // namespace

  std::vector<double> cycle_positions(const geometry::GearPair &pair, int n, double pitches, double start)
  {
    if (n < 1)
      throw InputError("Solve/Number of positions", std::to_string(n), ">= 1");
    require_greater("Solve/Pitches", pitches, 0.0, "-");
    const double p1 = 2 * pi / pair.gear(1).teeth();
    std::vector<double> phi(n);
    for (int i = 0; i < n; ++i)
      phi[i] = start + pitches * p1 * i / n;
    return phi;
  }

  GearContactModel::GearContactModel(const geometry::GearPair &pair,
                                     const mesh::GearMeshParameters mp[2],
                                     const fem::Elasticity material[2], const fem::FeOptions &fe,
                                     const ContactOptions &options)
    : pair_(&pair)
    , options_(options)
  {
    options_.validate();
    const auto t0 = Clock::now();
    for (int i = 0; i < 2; ++i)
      {
        const auto &tooth = pair.gear(i + 1);
        auto t1           = Clock::now();
        const auto m      = mesh::mesh_gear(tooth, mp[i]);
        t_mesh_ += since(t1);
        fem::FeOptions fo = fe;
        fo.refinements    = fe.refinements + mp[i].refinements;
        bodies_[i]        = std::make_unique<fem::ElasticBody>(m, material[i], fo);
        bodies_[i]->constrain(mesh::boundary::bore);
        if (mp[i].model == mesh::GearMeshParameters::Model::sector)
          {
            bodies_[i]->constrain(mesh::boundary::cut_cw);
            bodies_[i]->constrain(mesh::boundary::cut_ccw);
          }
        bodies_[i]->assemble_and_factorize();
        fine_[i] = mesh::fine_teeth(mp[i], tooth.teeth());
        if (mp[i].model == mesh::GearMeshParameters::Model::sector && mp[i].sector_teeth < 3)
          throw InputError("Mesh/Sector teeth", std::to_string(mp[i].sector_teeth),
                           ">= 3 for contact (teeth -1, 0, 1 share the mesh cycle)");
      }
    const int slave = options_.slave, master = 3 - slave;
    surfaces_[slave - 1]  = std::make_unique<ContactSurface>(*bodies_[slave - 1], surface_ids(fine_[slave - 1], false));
    surfaces_[master - 1] = std::make_unique<ContactSurface>(*bodies_[master - 1], surface_ids(fine_[master - 1], true));
    Drive drive;
    drive.kind = Drive::Kind::rotation;
    solver_    = std::make_unique<TwoBodyContact>(*surfaces_[0], *surfaces_[1], options_, drive);
    t_setup_   = since(t0);
  }

  GearContactModel::~GearContactModel() = default;

  PositionResult GearContactModel::solve(double phi1, double torque, const PositionResult *warm, bool keep)
  {
    require_greater("Solve/Torques", torque, 0.0, "N m");
    Scene scene;
    scene.placement[0] = pair_->placement(1, phi1);
    scene.placement[1] = pair_->placement(2, phi1);
    const auto t0 = Clock::now();
    ContactSolution s;
    try
      {
        s = solver_->solve(scene, Control::load, torque, warm ? &warm->solution : nullptr);
      }
    catch (const SolverError &e)
      {
        throw SolverError("position phi1 = " + to_string_g(phi1 * 180 / pi) + " deg, torque " +
                          to_string_g(torque) + " N m: " + e.what());
      }
    auto r    = finish(phi1, torque, std::move(s), keep);
    r.t_total = since(t0);
    return r;
  }

  PositionResult GearContactModel::solve_rotation(double phi1, double dtheta, const PositionResult *warm, bool keep)
  {
    if (!(dtheta >= 0))
      throw InputError("Solve/Rotation", to_string_g(dtheta), ">= 0 rad");
    Scene scene;
    scene.placement[0] = pair_->placement(1, phi1);
    scene.placement[1] = pair_->placement(2, phi1);
    const auto t0 = Clock::now();
    ContactSolution s = solver_->solve(scene, Control::displacement, dtheta, warm ? &warm->solution : nullptr);
    auto r    = finish(phi1, s.load, std::move(s), keep);
    r.t_total = since(t0);
    return r;
  }

  PositionResult GearContactModel::finish(double phi1, double torque, ContactSolution &&s, bool keep)
  {
    PositionResult r;
    r.phi1 = phi1, r.torque = torque;
    r.solution      = std::move(s);
    const auto &sol = r.solution;
    const double rb1 = pair_->base_radius(1), rb2 = pair_->base_radius(2);
    r.rotation     = sol.q;
    r.ste          = sol.q * rb1;
    r.normal_force = sol.load / rb1;
    r.k_secant     = r.ste > 0 ? r.normal_force / r.ste : 0.0;
    r.k_tangent    = sol.tangent / (rb1 * rb1);
    r.t_search = sol.t_search, r.t_compliance = sol.t_compliance, r.t_solve = sol.t_solve;
    const auto t0 = Clock::now();

    // Full displacement fields and equilibrium checks.
    fem::ElasticBody &b1 = *bodies_[0], &b2 = *bodies_[1];
    dealii::Vector<double> f[2] = {dealii::Vector<double>(b1.n_dofs()), dealii::Vector<double>(b2.n_dofs())};
    for (int b = 0; b < 2; ++b)
      for (const auto &[d, v] : sol.forces[b])
        f[b][d] += v;
    dealii::Vector<double> u[2] = {b1.solve(f[0]), b2.solve(f[1])};
    r.torque_contact  = -b1.moment(f[0]);
    r.torque_reaction = b1.moment(b1.reactions(u[0], f[0]));
    r.torque_gear     = std::abs(b2.moment(f[1]));

    // Load sharing by pinion tooth.
    const int S = options_.slave;
    std::map<int, ToothPairResult> pairs;
    const geometry::Placement P1 = solver_->placed({{pair_->placement(1, phi1), pair_->placement(2, phi1)}, {}, {}}, 1, sol.q);
    const geometry::Placement P2 = pair_->placement(2, phi1);
    double total = 0;
    for (const auto &p : sol.points)
      {
        if (!(p.force > 0))
          continue;
        const int pt = S == 1 ? p.slave_tooth : p.master_tooth;
        const int gt = S == 1 ? p.master_tooth : p.slave_tooth;
        auto &tp        = pairs[pt];
        tp.pinion_tooth = pt, tp.gear_tooth = gt;
        tp.force += p.force;
        total += p.force;
        ++tp.active_nodes;
      }
    const auto &mat1 = b1.material(), &mat2 = b2.material();
    for (auto &[k, tp] : pairs)
      {
        tp.share = total > 0 ? tp.force / total : 0.0;
        // Pressure profile along the pinion flank of this pair (slave nodes of this tooth).
        const ContactPoint *peak = nullptr;
        for (const auto &p : sol.points)
          {
            const int pt = S == 1 ? p.slave_tooth : p.master_tooth;
            if (pt == k && (!peak || p.pressure > peak->pressure))
              peak = &p;
          }
        if (!peak)
          continue;
        tp.p_max = peak->pressure;
        const Vec2 tau(-peak->normal.y(), peak->normal.x());
        std::vector<std::pair<double, double>> sp;
        for (const auto &p : sol.points)
          {
            const int pt = S == 1 ? p.slave_tooth : p.master_tooth;
            if (pt != k || !(p.pressure > 0))
              continue;
            const double s_along = (p.x - peak->x).dot(tau);
            tp.profile.push_back({s_along, (p.x - P1.centre).norm(), p.pressure});
            sp.emplace_back(s_along, p.pressure);
          }
        std::sort(tp.profile.begin(), tp.profile.end(),
                  [](const auto &a, const auto &b) { return a[0] < b[0]; });
        const auto fit = fit_ellipse(sp);
        tp.resolved    = tp.active_nodes >= 5 && fit[0] > 0;
        tp.half_width  = tp.resolved ? fit[0] : 0.0;
        // Hertz on the local involute radii of curvature at the peak.
        tp.radius_pinion = (peak->x - P1.centre).norm();
        tp.radius_gear   = (peak->x - P2.centre).norm();
        const double rho1 = tp.radius_pinion > rb1 ? std::sqrt(tp.radius_pinion * tp.radius_pinion - rb1 * rb1) : 0;
        const double rho2 = tp.radius_gear > rb2 ? std::sqrt(tp.radius_gear * tp.radius_gear - rb2 * rb2) : 0;
        const auto &k1 = pair_->gear(1).radii(), &k2 = pair_->gear(2).radii();
        // A peak within 2 % of a module of the end of either flank is corner (tip) contact.
        const double m_n = pair_->gear(1).parameters().rack.module;
        tp.on_involute   = tp.radius_pinion < k1.tip_form - 0.02 * m_n &&
                         tp.radius_gear < k2.tip_form - 0.02 * m_n && rho1 > 0 && rho2 > 0;
        if (rho1 > 0 && rho2 > 0)
          {
            HertzCase hc;
            hc.R1 = rho1, hc.R2 = rho2;
            hc.E1 = mat1.youngs_modulus, hc.E2 = mat2.youngs_modulus;
            hc.nu1 = mat1.poisson_ratio, hc.nu2 = mat2.poisson_ratio;
            hc.thickness = std::min(mat1.thickness, mat2.thickness);
            hc.force     = tp.force;
            hc.model     = mat1.model;
            std::tie(tp.a_hertz, tp.p_hertz) = hertz_closed_form(hc);
          }
        // Root stress: tension-side (drive) fillet of the loaded teeth.
        const int zp = pair_->gear(1).teeth(), zg = pair_->gear(2).teeth();
        const int kp = ((tp.pinion_tooth % zp) + zp) % zp, kg = ((tp.gear_tooth % zg) + zg) % zg;
        const auto pk1 = b1.peak_principal_stress(u[0], mesh::boundary::tooth_id(kp, mesh::boundary::fillet_drive));
        const auto pk2 = b2.peak_principal_stress(u[1], mesh::boundary::tooth_id(kg, mesh::boundary::fillet_drive));
        tp.root_stress_pinion = pk1.value, tp.root_radius_pinion = pk1.radius;
        tp.root_stress_gear = pk2.value, tp.root_radius_gear = pk2.radius;
        r.max_root_stress_pinion = std::max(r.max_root_stress_pinion, pk1.value);
        r.max_root_stress_gear   = std::max(r.max_root_stress_gear, pk2.value);
      }
    for (auto &[k, tp] : pairs)
      {
        if (tp.share > 1e-6)
          ++r.n_pairs;
        r.pairs.push_back(std::move(tp));
      }
    if (keep)
      r.u[0] = std::move(u[0]), r.u[1] = std::move(u[1]);
    r.t_post = since(t0);
    return r;
  }

  void GearContactModel::write_vtu(const PositionResult &r, const std::filesystem::path &file, double scale) const
  {
    if (r.u[0].size() == 0)
      throw SolverError("write_vtu: the position was solved without keeping displacements");
    const int S = options_.slave;
    const auto &ss = *surfaces_[S - 1];
    const geometry::Placement P[2] = {
      solver_->placed({{pair_->placement(1, r.phi1), pair_->placement(2, r.phi1)}, {}, {}}, 1, r.rotation),
      pair_->placement(2, r.phi1)};
    // Contact traction p n at the slave nodes, in the slave body frame.
    dealii::Vector<double> traction(bodies_[S - 1]->n_dofs());
    for (const auto &p : r.solution.points)
      {
        const auto &nd = ss.nodes()[p.node];
        const double c = std::cos(-P[S - 1].angle), s = std::sin(-P[S - 1].angle);
        const Vec2 n(c * p.normal.x() - s * p.normal.y(), s * p.normal.x() + c * p.normal.y());
        traction[nd.dof_x] = p.pressure * n.x();
        traction[nd.dof_y] = p.pressure * n.y();
      }
    std::vector<fem::PlacedBody> pb(2);
    for (int i = 0; i < 2; ++i)
      {
        pb[i].body      = bodies_[i].get();
        pb[i].u         = &r.u[i];
        pb[i].traction  = i == S - 1 ? &traction : nullptr;
        pb[i].angle     = P[i].angle;
        pb[i].centre[0] = P[i].centre.x();
        pb[i].centre[1] = P[i].centre.y();
      }
    fem::write_placed_vtu(pb, file, scale);
  }
} // namespace gearfem::contact
