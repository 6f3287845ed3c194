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
    unsigned int fo_refinements(const fem::FeOptions &fe, const mesh::GearMeshParameters &mp)
    {
      return fe.refinements + mp.refinements;
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
        // The contact solver needs selected entries of K^-1 on the surface: MUMPS computes
        // them with a pruned elimination tree, UMFPACK only with a full solve per column
        // (10x slower on a 3-tooth sector), so `automatic` means MUMPS here.
        if (fo.solver == fem::SolverKind::automatic)
          fo.solver = fem::SolverKind::mumps;
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
    // Either body may be the master of a tooth pair, so both surfaces carry the drive
    // fillets (a tip corner pressing into the mate's fillet); fillet nodes are never slaves.
    namespace bd = mesh::boundary;
    for (int i = 0; i < 2; ++i)
      {
        const bool master = options_.per_zone_slaves || i + 1 != options_.slave;
        surfaces_[i] = std::make_unique<ContactSurface>(*bodies_[i], surface_ids(fine_[i], master));
        for (const auto &nd : surfaces_[i]->nodes())
          {
            const auto code = bd::code_of(nd.boundary_id);
            slave_capable_[i].push_back(code == bd::flank_drive || code == bd::tip || code == bd::tip_round_drive);
          }
        const double m_n = pair.gear(i + 1).parameters().rack.module;
        const double h   = mesh::contact_size(mp[i], m_n) / std::pow(2.0, fo_refinements(fe, mp[i]));
        h_reach_       = std::max(h_reach_, h);
      }
    // Tooth of each gear at C when phi1 = 0, and the sense of each body's rotation.
    const Vec2 C = pair.point("C").position;
    for (int i = 1; i <= 2; ++i)
      {
        const auto P  = pair.placement(i, 0.0);
        const double c = std::cos(-P.angle), s = std::sin(-P.angle);
        const Vec2 d   = C - P.centre;
        const Vec2 x(c * d.x() - s * d.y(), s * d.x() + c * d.y());
        const double pitch = 2 * pi / pair.gear(i).teeth();
        tooth0_[i - 1]     = int(std::lround(std::atan2(-x.x(), x.y()) / pitch));
        sense_[i - 1]      = pair.placement(i, 1e-3).angle > P.angle ? 1.0 : -1.0;
      }
    Drive drive;
    drive.kind = Drive::Kind::rotation;
    solver_    = std::make_unique<TwoBodyContact>(*surfaces_[0], *surfaces_[1], options_, drive);
    t_setup_   = since(t0);
  }

  GearContactModel::~GearContactModel() = default;

  PositionResult GearContactModel::solve(double phi1, double torque, const PositionResult *warm, bool keep)
  {
    require_greater("Solve/Torques", torque, 0.0, "N m");
    const auto t0 = Clock::now();
    const Scene sc = scene(phi1, torque / pair_->base_radius(1));
    ContactSolution s;
    try
      {
        s = solver_->solve(sc, Control::load, torque, warm ? &warm->solution : nullptr);
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
    const auto t0 = Clock::now();
    // Patch size for the corner reach: the load of a typical steel mesh stiffness
    // (ISO 6336-1 c' = 14 N/(mm um)) at this rotation.
    const double b = std::min(bodies_[0]->material().thickness, bodies_[1]->material().thickness);
    const Scene sc = scene(phi1, 14e9 * b * dtheta * pair_->base_radius(1));
    ContactSolution s = solver_->solve(sc, Control::displacement, dtheta, warm ? &warm->solution : nullptr);
    auto r    = finish(phi1, s.load, std::move(s), keep);
    r.t_total = since(t0);
    return r;
  }

  double GearContactModel::tooth_roll(int body, int tooth, double phi1) const
  {
    const int z1 = pair_->gear(1).teeth(), z = pair_->gear(body).teeth();
    const double d = std::remainder(2 * pi * (tooth - tooth0_[body - 1]) / z, 2 * pi);
    // Tooth k stands where tooth0 stands after the body turns by d, i.e. after the pinion
    // turns by d / (sense |dtheta/dphi1|), |dtheta2/dphi1| = z1/z2.
    return phi1 + d * (double(z) / z1) / sense_[body - 1];
  }

  int GearContactModel::zone_slave(double psi, double normal_force) const
  {
    const double phiA = pair_->point("A").roll_angle, phiE = pair_->point("E").roll_angle;
    // Before A the gear's tip corner leads into the pinion flank; after E the pinion's.
    if (psi <= phiA)
      return 2;
    if (psi >= phiE)
      return 1;
    // Distance along each flank from the contact point to its tip edge (involute arc
    // length (r_tf^2 - r^2) / (2 r_b)).
    const Vec2 x = pair_->path_point(psi);
    double s[2], rho[2];
    for (int i = 1; i <= 2; ++i)
      {
        const double r  = (x - pair_->placement(i, psi).centre).norm();
        const double rb = pair_->base_radius(i), rtf = pair_->gear(i).radii().tip_form;
        s[i - 1]        = std::max(0.0, (rtf * rtf - r * r) / (2 * rb));
        rho[i - 1]      = std::sqrt(std::max(r * r - rb * rb, 1e-12 * rb * rb));
      }
    const auto &m1 = bodies_[0]->material(), &m2 = bodies_[1]->material();
    HertzCase hc;
    hc.R1 = rho[0], hc.R2 = rho[1];
    hc.E1 = m1.youngs_modulus, hc.E2 = m2.youngs_modulus;
    hc.nu1 = m1.poisson_ratio, hc.nu2 = m2.poisson_ratio;
    hc.thickness = std::min(m1.thickness, m2.thickness);
    hc.force     = std::max(normal_force, 0.0);
    hc.model     = m1.model;
    const double a     = hertz_closed_form(hc).first;
    const double reach = 2 * a + 3 * h_reach_;
    if (std::min(s[0], s[1]) > reach || s[0] == s[1])
      return options_.slave;
    return s[0] < s[1] ? 1 : 2;
  }

  Scene GearContactModel::scene(double phi1, double normal_force) const
  {
    Scene sc;
    sc.placement[0] = pair_->placement(1, phi1);
    sc.placement[1] = pair_->placement(2, phi1);
    if (!options_.per_zone_slaves)
      return sc;
    std::map<int, int> slave_of_tooth[2];
    for (int i = 1; i <= 2; ++i)
      for (const int k : fine_[i - 1])
        slave_of_tooth[i - 1][k] = zone_slave(tooth_roll(i, k, phi1), normal_force);
    for (int i = 1; i <= 2; ++i)
      {
        const auto &nodes = surfaces_[i - 1]->nodes();
        sc.slave_nodes[i - 1].assign(nodes.size(), false);
        for (std::size_t n = 0; n < nodes.size(); ++n)
          {
            const auto it = slave_of_tooth[i - 1].find(nodes[n].tooth);
            sc.slave_nodes[i - 1][n] = slave_capable_[i - 1][n] && it != slave_of_tooth[i - 1].end() && it->second == i;
          }
      }
    return sc;
  }

  bool GearContactModel::at_tip_edge(const ContactPoint &p, const geometry::Placement &P1,
                                     const geometry::Placement &P2) const
  {
    namespace bd = mesh::boundary;
    const auto tip_code = [](unsigned int c) { return c == bd::tip || c == bd::tip_round_drive; };
    if (tip_code(p.slave_code) || tip_code(p.master_code) || p.master_corner)
      return true;
    // A node at the end of a flank (the sharp corner itself, or the start of a tip
    // rounding) lies on the tip-form circle; test both the slave node and the master point.
    const geometry::Placement *P[2] = {&P1, &P2};
    const int S = p.slave_body, M = 3 - S;
    const double rs = (p.x - P[S - 1]->centre).norm(), rm = (p.master_point - P[M - 1]->centre).norm();
    const double tol = 1e-9 * pair_->gear(1).parameters().rack.module;
    return rs >= pair_->gear(S).radii().tip_form - tol || rm >= pair_->gear(M).radii().tip_form - tol;
  }

  void GearContactModel::pressure_and_hertz(ToothPairResult &tp, const ContactSolution &sol,
                                            const geometry::Placement &P1, const geometry::Placement &P2) const
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
        tp.profile.push_back({s_along, (p.x - P1.centre).norm(), p.pressure});
        sp.emplace_back(s_along, p.pressure);
      }
    std::sort(tp.profile.begin(), tp.profile.end(), [](const auto &a, const auto &b) { return a[0] < b[0]; });
    const auto fit = fit_ellipse(sp);
    tp.resolved    = tp.active_nodes >= min_patch_nodes && fit[0] > 0;
    tp.half_width  = tp.resolved ? fit[0] : 0.0;
    // Hertz on the local involute radii of curvature at the peak.
    const double rb1 = pair_->base_radius(1), rb2 = pair_->base_radius(2);
    tp.radius_pinion  = (peak->x - P1.centre).norm();
    tp.radius_gear    = (peak->x - P2.centre).norm();
    const double rho1 = tp.radius_pinion > rb1 ? std::sqrt(tp.radius_pinion * tp.radius_pinion - rb1 * rb1) : 0;
    const double rho2 = tp.radius_gear > rb2 ? std::sqrt(tp.radius_gear * tp.radius_gear - rb2 * rb2) : 0;
    if (rho1 > 0 && rho2 > 0)
      {
        const auto &mat1 = bodies_[0]->material(), &mat2 = bodies_[1]->material();
        HertzCase hc;
        hc.R1 = rho1, hc.R2 = rho2;
        hc.E1 = mat1.youngs_modulus, hc.E2 = mat2.youngs_modulus;
        hc.nu1 = mat1.poisson_ratio, hc.nu2 = mat2.poisson_ratio;
        hc.thickness = std::min(mat1.thickness, mat2.thickness);
        hc.force     = tp.force;
        hc.model     = mat1.model;
        std::tie(tp.a_hertz, tp.p_hertz) = hertz_closed_form(hc);
      }
  }

  PositionResult GearContactModel::finish(double phi1, double torque, ContactSolution &&s, bool keep)
  {
    PositionResult r;
    r.phi1 = phi1, r.torque = torque;
    r.solution      = std::move(s);
    const auto &sol = r.solution;
    const double rb1 = pair_->base_radius(1);
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
    std::map<int, ToothPairResult> pairs;
    Scene rigid;
    rigid.placement[0] = pair_->placement(1, phi1);
    rigid.placement[1] = pair_->placement(2, phi1);
    const geometry::Placement P1 = solver_->placed(rigid, 1, sol.q), P2 = rigid.placement[1];
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
        ++tp.active_nodes;
        tp.edge = tp.edge || at_tip_edge(p, P1, P2);
      }
    for (auto &[k, tp] : pairs)
      {
        tp.share = total > 0 ? tp.force / total : 0.0;
        pressure_and_hertz(tp, sol, P1, P2);
        // Root stress: tension-side (drive) fillet of the loaded teeth.
        const int zp = pair_->gear(1).teeth(), zg = pair_->gear(2).teeth();
        const int kp = ((tp.pinion_tooth % zp) + zp) % zp, kg = ((tp.gear_tooth % zg) + zg) % zg;
        const auto pk1 = b1.peak_principal_stress(u[0], mesh::boundary::tooth_id(kp, mesh::boundary::fillet_drive));
        const auto pk2 = b2.peak_principal_stress(u[1], mesh::boundary::tooth_id(kg, mesh::boundary::fillet_drive));
        tp.root_stress_pinion = pk1.value, tp.root_radius_pinion = pk1.radius;
        tp.root_stress_gear = pk2.value, tp.root_radius_gear = pk2.radius;
        r.max_root_stress_pinion = std::max(r.max_root_stress_pinion, pk1.value);
        r.max_root_stress_gear   = std::max(r.max_root_stress_gear, pk2.value);
        (tp.edge ? r.p_max_edge : r.p_max) = std::max(tp.edge ? r.p_max_edge : r.p_max, tp.p_max);
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
    Scene rigid;
    rigid.placement[0] = pair_->placement(1, r.phi1);
    rigid.placement[1] = pair_->placement(2, r.phi1);
    const geometry::Placement P[2] = {solver_->placed(rigid, 1, r.rotation), rigid.placement[1]};
    // Contact traction p n at the slave nodes of each body, in its body frame.
    dealii::Vector<double> traction[2] = {dealii::Vector<double>(bodies_[0]->n_dofs()),
                                          dealii::Vector<double>(bodies_[1]->n_dofs())};
    for (const auto &p : r.solution.points)
      {
        const int S    = p.slave_body;
        const auto &nd = surfaces_[S - 1]->nodes()[p.node];
        const double c = std::cos(-P[S - 1].angle), s = std::sin(-P[S - 1].angle);
        const Vec2 n(c * p.normal.x() - s * p.normal.y(), s * p.normal.x() + c * p.normal.y());
        traction[S - 1][nd.dof_x] = p.pressure * n.x();
        traction[S - 1][nd.dof_y] = p.pressure * n.y();
      }
    std::vector<fem::PlacedBody> pb(2);
    for (int i = 0; i < 2; ++i)
      {
        pb[i].body      = bodies_[i].get();
        pb[i].u         = &r.u[i];
        pb[i].traction  = &traction[i];
        pb[i].angle     = P[i].angle;
        pb[i].centre[0] = P[i].centre.x();
        pb[i].centre[1] = P[i].centre.y();
      }
    fem::write_placed_vtu(pb, file, scale);
  }
} // namespace gearfem::contact
