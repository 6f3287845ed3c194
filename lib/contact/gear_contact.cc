// GearContactModel: the two gear bodies and the per-position contact solves.
#include "contact/gear_contact.h"
#include "base/units.h"

#include "base/errors.h"
#include "contact/hertz.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>

namespace gearfem::contact
{
  namespace
  {
    using Scope = dealii::TimerOutput::Scope;
    using units::pi;

    std::set<unsigned int> surface_ids(const std::vector<int> &teeth, bool with_fillet)
    {
      namespace b = mesh::boundary;
      std::set<unsigned int> ids;
      for (const int k : teeth)
        {
          ids.insert(b::tooth_id(k, b::flank_drive));
          ids.insert(b::tooth_id(k, b::tip));
          ids.insert(b::tooth_id(k, b::tip_round_drive));
          if (with_fillet)
            ids.insert(b::tooth_id(k, b::fillet_drive));
        }
      return ids;
    }
    unsigned int fo_refinements(const fem::FeOptions &fe, const mesh::GearMeshParameters &mp)
    {
      return fe.refinements + mp.refinements;
    }
  } // namespace

  double section_seconds(const dealii::TimerOutput &timer, const std::string &name)
  {
    const auto times = timer.get_summary_data(dealii::TimerOutput::total_wall_time);
    const auto it    = times.find(name);
    return it == times.end() ? 0.0 : it->second;
  }

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

  void check_contact_mesh(const mesh::GearMeshParameters &mp)
  {
    if (mp.model == mesh::GearMeshParameters::Model::sector && mp.sector_teeth < 3)
      throw InputError("Mesh/Sector teeth", std::to_string(mp.sector_teeth),
                       ">= 3 for contact (teeth -1, 0, 1 share the mesh cycle)");
  }

  GearBody build_gear_body(const geometry::GearPair &pair, int i, const mesh::GearMeshParameters &mp,
                           const fem::Elasticity &material, const fem::FeOptions &fe, dealii::TimerOutput *timer)
  {
    using Optional = std::optional<Scope>;
    check_contact_mesh(mp);
    const auto &tooth = pair.gear(i);
    mesh::MeshData m;
    {
      Optional scope;
      if (timer)
        scope.emplace(*timer, "mesh");
      m = mesh::mesh_gear(tooth, mp);
    }
    Optional scope;
    if (timer)
      scope.emplace(*timer, "assemble and factorise");
    fem::FeOptions fo = fe;
    fo.refinements    = fe.refinements + mp.refinements;
    // The contact solver needs selected entries of K^-1 on the surface: MUMPS computes
    // them with a pruned elimination tree, UMFPACK only with a full solve per column
    // (10x slower on a 3-tooth sector), so `automatic` means MUMPS here.
    if (fo.solver == fem::SolverKind::automatic)
      fo.solver = fem::SolverKind::mumps;
    GearBody g;
    g.body = std::make_unique<fem::ElasticBody>(m, material, fo);
    g.body->constrain(mesh::boundary::bore);
    if (mp.model == mesh::GearMeshParameters::Model::sector)
      {
        g.body->constrain(mesh::boundary::cut_cw);
        g.body->constrain(mesh::boundary::cut_ccw);
      }
    g.body->assemble_and_factorize();
    g.fine_teeth = mesh::fine_teeth(mp, tooth.teeth());
    const double m_n = tooth.parameters().rack.module;
    g.contact_size   = mesh::contact_size(mp, m_n) / std::pow(2.0, fo_refinements(fe, mp));
    return g;
  }

  GearContactModel::GearContactModel(const geometry::GearPair &pair, std::array<GearBody, 2> bodies,
                                     const ContactOptions &options)
    : pair_(&pair)
    , options_(options)
    , timer_(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times)
  {
    options_.validate();
    set_up_contact(std::move(bodies));
  }

  GearContactModel::GearContactModel(const geometry::GearPair &pair, const mesh::GearMeshParameters mp[2],
                                     const fem::Elasticity material[2], const fem::FeOptions &fe,
                                     const ContactOptions &options, const geometry::GearPair *mesh_pair)
    : pair_(&pair)
    , options_(options)
    , timer_(std::cout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times)
  {
    options_.validate();
    std::array<GearBody, 2> bodies;
    for (int i = 0; i < 2; ++i)
      bodies[i] = build_gear_body(mesh_pair ? *mesh_pair : pair, i + 1, mp[i], material[i], fe, &timer_);
    set_up_contact(std::move(bodies));
  }

  void GearContactModel::set_up_contact(std::array<GearBody, 2> bodies)
  {
    Scope scope(timer_, "contact surfaces");
    for (int i = 0; i < 2; ++i)
      {
        if (!bodies[i].body)
          throw InputError("gear body " + std::to_string(i + 1), "(none)", "a factorised body (build_gear_body)");
        bodies_[i] = std::move(bodies[i].body);
        fine_[i]   = std::move(bodies[i].fine_teeth);
        h_reach_   = std::max(h_reach_, bodies[i].contact_size);
      }
    // Either body may be the master of a tooth pair, so both surfaces carry the drive
    // fillets (a tip corner pressing into the mate's fillet); fillet nodes are slaves only
    // on the teeth of a closed rack, whose concave fillet is conjugate to the mate's tip.
    namespace bd = mesh::boundary;
    for (int i = 0; i < 2; ++i)
      {
        const bool master = options_.per_zone_slaves || i + 1 != options_.slave;
        const bool closed = pair_->gear(i + 1).rack().closed();
        surfaces_[i] = std::make_unique<ContactSurface>(*bodies_[i], surface_ids(fine_[i], master || closed));
        for (const auto &nd : surfaces_[i]->nodes())
          {
            const auto code = bd::code_of(nd.boundary_id);
            slave_capable_[i].push_back(code == bd::flank_drive || code == bd::tip || code == bd::tip_round_drive ||
                                        (closed && code == bd::fillet_drive));
          }
      }
    // Tooth of each gear at C when phi1 = 0, and the sense of each body's rotation.
    const auto &pair = *pair_;
    const Vec2 C     = pair.point("C").position;
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
    apply_micro_geometry();
  }

  void GearContactModel::apply_micro_geometry()
  {
    for (int i = 1; i <= 2; ++i)
      {
        const geometry::ToothProfile *tooth = &pair_->gear(i);
        if (options_.micro_geometry_as_gap && tooth->parameters().relief.kind != geometry::TipRelief::Kind::none)
          // The relief is a function of the radius (docs/geometry.md); the body frame is
          // centred on the gear axis.
          solver_->set_gap_modification(i, [tooth](const Vec2 &x) { return tooth->relief_at_radius(x.norm()); });
        else
          solver_->set_gap_modification(i, nullptr);
      }
  }

  void GearContactModel::set_micro_geometry(const geometry::GearPair &pair)
  {
    if (!options_.micro_geometry_as_gap)
      throw InputError("Contact/Micro-geometry", "geometry",
                       "gap (a model re-targeted to another micro-geometry applies it as a gap modification)");
    // The macro-geometry the bodies were meshed from: what a relief does not change.
    auto same = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(a) + std::abs(b)); };
    const auto &old = *pair_;
    std::string differs;
    if (!same(pair.center_distance(), old.center_distance()))
      differs = "centre distance";
    for (int i = 1; i <= 2 && differs.empty(); ++i)
      {
        const auto &a = pair.gear(i), &b = old.gear(i);
        const auto &ra = a.radii(), &rb = b.radii();
        if (a.teeth() != b.teeth() || !same(ra.tip, rb.tip) || !same(ra.root, rb.root) || !same(ra.base, rb.base) ||
            !same(ra.reference, rb.reference) || !same(a.parameters().face_width, b.parameters().face_width) ||
            !same(a.parameters().profile_shift, b.parameters().profile_shift) ||
            !same(a.parameters().thickness_allowance, b.parameters().thickness_allowance) ||
            !same(a.parameters().rack.module, b.parameters().rack.module))
          differs = "gear " + std::to_string(i) + " (teeth, module, radii, shift, thickness or face width)";
      }
    if (!differs.empty())
      throw InputError("micro-geometry variant", differs + " differs from the meshed design",
                       "a design that differs only in tip relief (Contact/Micro-geometry = gap)");
    pair_ = &pair;
    apply_micro_geometry();
  }

  GearContactModel::~GearContactModel() = default;

  double GearContactModel::mesh_seconds() const { return section_seconds(timer_, "mesh"); }

  double GearContactModel::setup_seconds() const
  {
    return mesh_seconds() + section_seconds(timer_, "assemble and factorise") +
           section_seconds(timer_, "contact surfaces");
  }

  ContactState GearContactModel::timed_solve(double phi1, double normal_force, Control control, double value,
                                             const ContactSolution *warm)
  {
    const double before = section_seconds(timer_, "contact");
    ContactState state;
    state.phi1 = phi1;
    {
      Scope scope(timer_, "contact");
      state.solution = solver_->solve(scene(phi1, normal_force), control, value, warm);
    }
    state.torque    = control == Control::load ? value : state.solution.load;
    state.t_contact = section_seconds(timer_, "contact") - before;
    return state;
  }

  ContactState GearContactModel::solve(double phi1, double torque, const ContactSolution *warm)
  {
    require_greater("Solve/Torques", torque, 0.0, "N m");
    try
      {
        return timed_solve(phi1, torque / pair_->base_radius(1), Control::load, torque, warm);
      }
    catch (const SolverError &e)
      {
        throw SolverError("position phi1 = " + to_string_g(phi1 / units::deg) + " deg, torque " +
                          to_string_g(torque) + " N m: " + e.what());
      }
  }

  ContactState GearContactModel::solve_rotation(double phi1, double dtheta, const ContactSolution *warm)
  {
    if (!(dtheta >= 0))
      throw InputError("Solve/Rotation", to_string_g(dtheta), ">= 0 rad");
    // Patch size for the corner reach: the load of a typical steel mesh stiffness
    // (ISO 6336-1 c' = 14 N/(mm um)) at this rotation.
    const double b = std::min(bodies_[0]->material().thickness, bodies_[1]->material().thickness);
    return timed_solve(phi1, 14e9 * b * dtheta * pair_->base_radius(1), Control::displacement, dtheta, warm);
  }

  std::array<geometry::Placement, 2> GearContactModel::placements(double phi1, double rotation) const
  {
    Scene rigid;
    rigid.placement[0] = pair_->placement(1, phi1);
    rigid.placement[1] = pair_->placement(2, phi1);
    return {solver_->placed(rigid, 1, rotation), rigid.placement[1]};
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

} // namespace gearfem::contact
