// The `Solve` section and the whole input of `gearfem solve` (GearContactInput).
#include "solve/input.h"

#include "geometry/limits.h"

#include "base/errors.h"
#include "base/number.h"
#include "base/units.h"
#include "params/checked.h"
#include "contact/parameters.h"
#include "fem/parameters.h"
#include "geometry/parameters.h"
#include "io/journal.h"
#include "mesh/parameters.h"
#include "mesh/gear_mesh.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearfem::solve
{
  namespace
  {
    constexpr double pi = units::pi;
    std::vector<double> doubles(const std::string &entry, const std::string &text)
    {
      return parse_double_list(entry, text);
    }
  } // namespace

  void declare_solve_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Solve");
    prm.declare_entry("Positions", "cycle", Selection("cycle|named|list"),
                      "cycle: N positions over the given pitches; named: the points of the line "
                      "of action; list: explicit roll angles. Units: none.");
    prm.declare_entry("Number of positions", "40", Integer(),
                      "N for `cycle`. Units: none. Allowed: 1 to 100000.");
    prm.declare_entry("Pitches", "1", Double(),
                      "Angular pitches covered by `cycle`. Units: none. Allowed: > 0 and <= 1000.");
    prm.declare_entry("Start", "A", Anything(),
                      "First roll angle of `cycle`: A (start of contact) or a number. Units: deg "
                      "(pinion roll angle, 0 at the pitch point C). Allowed: A or -360 to 360.");
    prm.declare_entry("Named positions", "A, B, C, D, E", MultipleSelection("A|B|C|D|E"),
                      "Points for `named`. Units: none.");
    prm.declare_entry("Roll angles", "", Anything(),
                      "Comma-separated pinion roll angles for `list`. Units: deg (0 at C). Allowed: -360 "
                      "to 360 each.");
    params::declare_torques(prm, "Torques", "200", "Pinion torques, one sweep each.");
    prm.declare_entry("VTU", "named", Selection("none|named|all"),
                      "Deformed-pair VTU files: none, at B/C/D (named), or every position. Units: none.");
    prm.declare_entry("VTU displacement scale", "1", Double(),
                      "Magnification of the displacement in the VTU files. Units: none. Allowed: > 0.");
    prm.declare_entry("Plots", "true", Bool(), "Write the PNG plots (needs /usr/bin/python3 with matplotlib).");
    prm.declare_entry("Error estimate", "false", Bool(),
                      "After the sweep, re-solve three sample positions at each torque (mid single-pair "
                      "zone (B+D)/2, mid double-pair zone (A+B)/2, transition D) on a model whose fine mesh "
                      "sizes (h_contact, h_fillet, h_coast, h_corner) are halved, and report the estimated "
                      "discretisation error of STE, root stress and p_max (Richardson, order 2) in the "
                      "summary and run.json (docs/output-format.md). Costs one more set-up on the finer "
                      "mesh and 6 solves per torque. Units: none.");
    prm.declare_entry("Target", "none", Anything(),
                      "The accuracy the run asks for; gearfem then chooses the mesh (h_contact, h_fillet) "
                      "and the degree, estimates the error of the choice on the run, refines where needed "
                      "and reports the achieved estimate (docs/model-choice.md). none (the mesh as given), a "
                      "preset (dynamics tables: mean STE 1 %, p-p STE 2 %; rating check: root stress 3 %, "
                      "p_max 5 %; micro-geometry design: mean STE 2 %, p-p STE 1 %, p_max 10 %), or a list "
                      "such as 'mean STE 1, p-p STE 1, root stress 3' (percent). Mesh and Finite elements "
                      "entries set in the input are kept. Units: %. Allowed: 0.01 to 50 each.");
    prm.declare_entry("Cost cap", "1800", Double(),
                      "With a Target: the wall time the choice may spend (levels, samples and the "
                      "predicted sweep); 0: none. Units: s. Allowed: >= 0.");
    prm.declare_entry("Target route", "auto", Selection("auto|full FE"),
                      "With a Target: how the delivered model sweeps the torques. auto: on one condensed "
                      "cycle of that model where the torques are enough to pay for its build (8 or more "
                      "over a torque range within 4:1, docs/model-choice.md), with the condensation's error "
                      "measured on the run and added to the estimates; else the full FE sweep. full FE: "
                      "always the full FE sweep.");
    prm.leave_subsection();
  }

  SolveParameters parse_solve_parameters(dealii::ParameterHandler &prm)
  {
    SolveParameters p;
    prm.enter_subsection("Solve");
    const std::string pos = prm.get("Positions");
    p.positions   = pos == "cycle" ? SolveParameters::Positions::cycle :
                    pos == "named" ? SolveParameters::Positions::named : SolveParameters::Positions::list;
    p.n_positions = params::get_integer(prm, "Number of positions");
    p.pitches     = params::get_double(prm, "Pitches");
    const std::string start = prm.get("Start");
    if (start == "A")
      p.start_at_A = true;
    else
      {
        const auto v = doubles("Solve/Start", start);
        if (v.size() != 1)
          throw InputError("Solve/Start", start, "A or one roll angle in deg");
        p.start_at_A = false;
        p.start      = v[0] * units::deg;
      }
    p.names = dealii::Utilities::split_string_list(prm.get("Named positions"), ',');
    for (const double a : doubles("Solve/Roll angles", prm.get("Roll angles")))
      p.roll_angles.push_back(a * units::deg);
    p.torques = params::get_torques(prm, "Torques", "Solve/Torques");
    const std::string vtu = prm.get("VTU");
    p.vtu       = vtu == "none" ? SolveParameters::Vtu::none :
                  vtu == "all" ? SolveParameters::Vtu::all : SolveParameters::Vtu::named;
    p.vtu_scale = params::get_double(prm, "VTU displacement scale");
    p.plots     = params::get_bool(prm, "Plots");
    p.error_estimate = params::get_bool(prm, "Error estimate");
    p.target         = prm.get("Target");
    p.cost_cap       = params::get_double(prm, "Cost cap");
    p.target_route_auto = prm.get("Target route") == "auto";
    prm.leave_subsection();
    require_range("Solve/Cost cap", p.cost_cap, 0.0, 1e7, "s");

    // Roll angles beyond a revolution are not a position of the pair but a typing error (and
    // 1e308 deg would reach the solver as an infinite rotation): refused here, before meshing.
    if (p.positions == SolveParameters::Positions::cycle)
      require_range("Solve/Number of positions", p.n_positions, 1, 100000);
    require_greater("Solve/Pitches", p.pitches, 0.0, "-");
    require_range("Solve/Pitches", p.pitches, 0.0, 1000.0);
    if (!p.start_at_A)
      require_range("Solve/Start", p.start / units::deg, -360.0, 360.0, "deg");
    for (const double a : p.roll_angles)
      require_range("Solve/Roll angles", a / units::deg, -360.0, 360.0, "deg");
    // The accuracy target's p-p STE estimate and its ripple resolution read a cycle of evenly
    // spaced positions: a list of roll angles would be taken for mesh ripple, and the choice
    // would refine for it (docs/model-choice.md).
    if (p.target != "none" && p.positions != SolveParameters::Positions::cycle)
      throw InputError("Solve/Target", p.target, "none with Solve/Positions = " +
                                                   std::string(p.positions == SolveParameters::Positions::list ? "list" : "named"),
                       "an accuracy target needs Solve/Positions = cycle (evenly spaced positions: its p-p STE "
                       "estimate reads their ripple); set the mesh instead, or sweep a cycle");
    if (p.positions == SolveParameters::Positions::list && p.roll_angles.empty())
      throw InputError("Solve/Roll angles", "(empty)", "at least one roll angle when Positions = list");
    if (p.positions == SolveParameters::Positions::named && p.names.empty())
      throw InputError("Solve/Named positions", "(empty)", "at least one of A, B, C, D, E");
    require_greater("Solve/VTU displacement scale", p.vtu_scale, 0.0, "-");
    return p;
  }

  namespace
  {
  void check_small_strain(const geometry::MeshingPair &pair, const geometry::PairMaterial &pm,
                          const std::vector<double> &torques)
  {
    // geometry::limits::check_small_strain: p0/E* <= 5 % at the pitch point, E' of the plane model.
    const double E1 = pm.gear1.effective_modulus(pm.plane_strain);
    const double E2 = pm.gear2.effective_modulus(pm.plane_strain);
    const double Es = 1.0 / (1.0 / E1 + 1.0 / E2);
    const double b  = std::min(pair.face_width(1), pair.face_width(2));
    const auto *external   = dynamic_cast<const geometry::GearPair *>(&pair);
    const auto rho         = pair.radii_of_curvature(pair.point("C").position, {pair.placement(1, 0), pair.placement(2, 0)});
    const double curvature = external ? external->equivalent_curvature(0.0) : 1 / rho[0] + 1 / rho[1]; // 1/R* at C [1/m]
    for (const double T : torques)
      geometry::limits::check_small_strain("Solve/Torques", T, pair.base_radius(1), b, Es, curvature);
  }

  /// The friction-law entries of `Contact` (declared with the section in contact/parameters.h),
  /// checked: InputError naming the entry the chosen law needs.
  analytical::friction::LawInputs parse_friction_law(dealii::ParameterHandler &prm)
  {
    analytical::friction::LawInputs f;
    prm.enter_subsection("Contact");
    f.law          = analytical::friction::law_from_string(prm.get("Friction law"));
    f.mu           = params::get_double(prm, "Friction coefficient");
    f.pinion_speed = params::get_double(prm, "Pinion speed") * units::pi / 30.0;
    f.eta_oil      = params::get_double(prm, "Oil viscosity") * 1e-3;
    f.Ra1          = params::get_double(prm, "Roughness gear 1") * 1e-6;
    f.Ra2          = params::get_double(prm, "Roughness gear 2") * 1e-6;
    f.X_L          = params::get_double(prm, "Lubricant factor");
    prm.leave_subsection();
    analytical::friction::check(f);
    return f;
  }
  } // namespace

  void declare_gear_contact_input(dealii::ParameterHandler &prm)
  {
    geometry::declare_geometry_parameters(prm);
    geometry::declare_material_parameters(prm);
    mesh::declare_mesh_parameters(prm);
    fem::declare_fe_parameters(prm);
    contact::declare_contact_parameters(prm);
    declare_solve_parameters(prm);
    declare_ring_parameters(prm);
  }

  namespace
  {
    /// `Mesh/Gear i/Fine teeth = loaded`: the teeth the Solve positions load
    /// (geometry::loaded_teeth; pinion tooth k meshes with gear tooth -k).
    void resolve_loaded_teeth(GearContactInput &in)
    {
      if (in.mesh[0].fine_teeth != "loaded" && in.mesh[1].fine_teeth != "loaded")
        return;
      for (int i = 0; i < 2; ++i)
        if (in.mesh[i].fine_teeth == "loaded" && in.mesh[i].model != mesh::GearMeshParameters::Model::full_gear)
          throw InputError("Mesh/Gear " + std::to_string(i + 1) + "/Fine teeth", "loaded",
                           "auto or a list of tooth indices for Mesh/Model = sector (all its teeth are fine)");
      const std::vector<int> k = in.loaded_teeth();
      for (int i = 0; i < 2; ++i)
        if (in.mesh[i].fine_teeth == "loaded")
          in.mesh[i].fine_teeth = mesh::fine_teeth_list(k, i == 0 ? 1 : -1);
    }
  } // namespace

  GearContactInput parse_gear_contact_input(dealii::ParameterHandler &prm)
  {
    return parse_gear_contact_input(prm, nullptr);
  }

  GearContactInput parse_gear_contact_input(
    dealii::ParameterHandler &prm,
    const std::function<geometry::GeometryInput(const geometry::GeometryInput &)> &section)
  {
    GearContactInput in;
    const auto gi = section ? section(geometry::parse_geometry_parameters(prm)) :
                              geometry::parse_geometry_parameters(prm);
    const auto pm = geometry::parse_material_parameters(prm);
    for (int i = 0; i < 2; ++i)
      in.mesh[i] = mesh::parse_mesh_parameters(prm, i + 1);
    in.fe      = fem::parse_fe_parameters(prm);
    in.solve   = parse_solve_parameters(prm);
    using Relief = geometry::TipRelief::Kind;
    if (internal_pair_requested(prm))
      {
        for (int i = 0; i < 2; ++i)
          if (in.mesh[i].fine_teeth == "loaded")
            throw InputError("Mesh/Gear " + std::to_string(i + 1) + "/Fine teeth", "loaded",
                             "auto or a list of tooth indices for Pair/Type = internal");
        const RingInput ring = parse_ring_parameters(prm, gi.gear2, in.mesh[1]);
        in.ring_mesh         = ring.mesh;
        const auto ring_profile = geometry::InternalToothProfile::generate(ring.gear);
        auto make = [&](const geometry::GearParameters &pinion) {
          return std::make_unique<geometry::InternalGearPair>(geometry::ToothProfile::generate(pinion), ring_profile,
                                                              gi.pair.center_distance, ring.face_width);
        };
        in.internal_pair = make(gi.gear1);
        contact::check_contact_mesh(in.mesh[0]);
        (void)mesh::gear_domain(in.internal_pair->pinion(), in.mesh[0]);
        (void)mesh::ring_domain(ring_profile, in.ring_mesh);
        in.contact = contact::parse_contact_parameters(prm, pm.gear1.youngs_modulus, pm.gear2.youngs_modulus);
        if (gi.gear1.relief.kind != Relief::none)
          {
            if (!in.contact.micro_geometry_as_gap)
              throw InputError("Contact/Micro-geometry", "geometry",
                               "gap (Pair/Type = internal takes the pinion's tip relief as a gap)");
            geometry::GearParameters plain = gi.gear1;
            plain.relief                   = geometry::TipRelief();
            in.unmodified_internal_pair    = make(plain);
          }
      }
    else
      {
        in.pair = std::make_unique<geometry::GearPair>(geometry::build_pair(gi));
        resolve_loaded_teeth(in);
        for (int i = 0; i < 2; ++i)
          {
            contact::check_contact_mesh(in.mesh[i]);
            (void)mesh::gear_domain(in.pair->gear(i + 1), in.mesh[i]); // outline checks, no gmsh
          }
        in.contact = contact::parse_contact_parameters(prm, pm.gear1.youngs_modulus, pm.gear2.youngs_modulus);
        if (in.contact.micro_geometry_as_gap &&
            (gi.gear1.relief.kind != Relief::none || gi.gear2.relief.kind != Relief::none))
          {
            geometry::GeometryInput plain = gi;
            plain.gear1.relief = plain.gear2.relief = geometry::TipRelief();
            in.unmodified_pair = std::make_unique<geometry::GearPair>(geometry::build_pair(plain));
          }
      }
    for (int i = 0; i < 2; ++i)
      in.material[i] = fem::elasticity(i == 0 ? pm.gear1 : pm.gear2, in.meshing().face_width(i + 1), pm.plane_strain);
    in.friction = parse_friction_law(prm);
    (void)in.positions(); // checks the position list
    check_small_strain(in.meshing(), pm, in.solve.torques);
    in.contact.friction = in.friction_coefficients(in.solve.torques).front();
    return in;
  }

  std::vector<std::string> input_warnings(const GearContactInput &in)
  {
    std::vector<std::string> w;
    if (!in.pair)
      return w; // the flank-height rule is stated for external pairs
    const auto &pair = *in.pair;
    for (int i = 1; i <= 2; ++i)
      {
        const auto &g        = pair.gear(i);
        const double r_sap   = i == 1 ? pair.point("A").r1 : pair.point("E").r2;
        const double r_form  = g.radii().form;
        const double h       = mesh::contact_size(in.mesh[i - 1], g.parameters().rack.module);
        if (r_form > 0 && h > r_sap - r_form)
          {
            std::ostringstream s;
            s.precision(3);
            s << "gear " << i << ": Mesh/h_contact " << h * 1e3 << " mm is larger than the flank height "
              << (r_sap - r_form) * 1e3 << " mm between its start of active profile (r " << r_sap * 1e3
              << " mm) and its form circle (r_Ff " << r_form * 1e3
              << " mm): the contact of the tooth entering mesh can leak into its fillet and inflate its root "
                 "stress there; refine h_contact below that height for root stresses near the start of contact";
            w.push_back(s.str());
          }
      }
    return w;
  }

  std::vector<int> GearContactInput::loaded_teeth(const std::vector<double> &extra) const
  {
    std::vector<double> roll = extra;
    for (const auto &p : positions())
      roll.push_back(p.second);
    return geometry::loaded_teeth(*pair, roll);
  }

  std::vector<std::pair<std::string, double>> GearContactInput::positions() const
  {
    std::vector<std::pair<std::string, double>> out;
    const auto &s    = solve;
    const auto *pair = &meshing();
    switch (s.positions)
      {
        case SolveParameters::Positions::cycle:
          {
            const double start = s.start_at_A ? pair->point("A").roll_angle : s.start;
            for (const double phi : contact::cycle_positions(*pair, s.n_positions, s.pitches, start))
              out.emplace_back("", phi);
            break;
          }
        case SolveParameters::Positions::named:
          for (const auto &n : s.names)
            out.emplace_back(n, pair->point(n).roll_angle);
          break;
        case SolveParameters::Positions::list:
          for (const double phi : s.roll_angles)
            out.emplace_back("", phi);
          break;
      }
    // Name the cycle positions that coincide with a point of the line of action.
    for (auto &[name, phi] : out)
      if (name.empty())
        for (const char *n : {"A", "B", "C", "D", "E"})
          if (std::abs(phi - pair->point(n).roll_angle) < 1e-9)
            name = n;
    return out;
  }

  const geometry::MeshingPair &GearContactInput::meshing() const
  {
    if (internal_pair)
      return *internal_pair;
    return *pair;
  }

  void GearContactInput::require_external(const std::string &what) const
  {
    if (internal_pair)
      throw InputError("Pair/Type", "internal", "external (" + what + " covers external pairs only)");
  }

  std::unique_ptr<contact::GearContactModel> GearContactInput::model() const
  {
    if (internal_pair)
      return std::make_unique<contact::GearContactModel>(*internal_pair, mesh[0], ring_mesh, material, fe, contact,
                                                         unmodified_internal_pair.get());
    return std::make_unique<contact::GearContactModel>(*pair, mesh, material, fe, contact, unmodified_pair.get());
  }

  std::string model_key(const GearContactInput &in, bool gap_route)
  {
    std::ostringstream s;
    s.precision(17);
    const geometry::MeshingPair &meshed = in.internal_pair ?
      static_cast<const geometry::MeshingPair &>(in.unmodified_internal_pair ? *in.unmodified_internal_pair :
                                                                                *in.internal_pair) :
      (in.unmodified_pair ? *in.unmodified_pair : *in.pair);
    s << "pair " << meshed.center_distance() << '\n';
    for (int i = 1; i <= 2; ++i)
      {
        s << "gear " << i << ' ' << meshed.teeth(i) << ' ' << meshed.face_width(i) << '\n';
        const auto *ip = dynamic_cast<const geometry::InternalGearPair *>(&meshed);
        const auto samples =
          !ip ? static_cast<const geometry::GearPair &>(meshed).gear(i).sample(meshed.module() / 50) :
          i == 1 ? ip->pinion().sample(meshed.module() / 50) : ip->ring().sample(meshed.module() / 50);
        for (const auto &q : samples)
          s << q.p.x() << ' ' << q.p.y() << '\n';
        if (ip && i == 2)
          {
            const auto &r = in.ring_mesh;
            s << "ring " << r.rim_thickness << ' ' << r.backup_ratio << ' ' << r.bolts << ' ' << r.bolt_phase << ' '
              << r.bolt_width << '\n';
          }
        const auto &m = in.mesh[i - 1];
        s << "mesh " << static_cast<int>(m.model) << ' ' << m.sector_teeth << ' ' << m.h_contact << ' ' << m.h_fillet
          << ' ' << m.h_coast << ' ' << m.h_corner << ' ' << m.h_body << ' ' << m.h_tooth << ' ' << m.growth << ' '
          << m.bore_radius << ' ' << m.rim_thickness << ' ' << m.fine_teeth << ' ' << m.refinements << ' '
          << m.spline_samples << '\n';
        if (m.tiled)
          s << "tiled teeth\n"; // a different mesh of the same sizes (no line: meshed whole)
        // Teeth turned by their pitch deviations (Deviations/Model = geometry); none: no line.
        if (!m.tooth_angles.empty())
          {
            s << "tooth angles";
            for (const double d : m.tooth_angles)
              s << ' ' << d;
            s << '\n';
          }
        const auto &e = in.material[i - 1];
        s << "material " << e.youngs_modulus << ' ' << e.poisson_ratio << ' ' << e.thickness << ' '
          << static_cast<int>(e.model) << '\n';
      }
    s << "fe " << in.fe.degree << ' ' << in.fe.refinements << ' ' << static_cast<int>(in.fe.solver) << ' '
      << in.fe.umfpack_max_dofs << ' ' << static_cast<int>(in.fe.interior) << '\n';
    const auto &c = in.contact;
    s << "contact " << static_cast<int>(c.method) << ' ' << c.penalty_factor << ' ' << c.search_distance << ' '
      << c.tolerance << ' ' << c.max_active_set_iterations << ' ' << c.max_geometry_iterations << ' '
      << c.max_load_cuts << ' ' << c.slave << ' ' << c.per_zone_slaves << ' ' << static_cast<int>(c.gap) << ' '
      << (c.micro_geometry_as_gap || gap_route) << '\n';
    // Friction enters the key only when present, so that frictionless keys are unchanged.
    const auto &f = in.friction;
    if (c.friction > 0 || f.law != analytical::friction::Law::constant)
      s << "friction " << c.friction << ' ' << c.friction_tolerance << ' ' << static_cast<int>(f.law) << ' ' << f.mu
        << ' ' << f.pinion_speed << ' ' << f.eta_oil << ' ' << f.Ra1 << ' ' << f.Ra2 << ' ' << f.X_L << '\n';
    return io::content_hash(s.str());
  }

  std::vector<double> GearContactInput::friction_coefficients(const std::vector<double> &torques) const
  {
    const double b = std::min(material[0].thickness, material[1].thickness);
    std::vector<double> mu;
    for (const double T : torques)
      mu.push_back(analytical::friction::coefficient(
        friction, analytical::friction::pitch_point(meshing(), T, friction.pinion_speed, b)));
    return mu;
  }
} // namespace gearfem::solve
