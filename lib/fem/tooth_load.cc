// Flank-load cases on a meshed gear body (ISO 6336-3 tip loading).
#include "fem/tooth_load.h"
#include "base/progress.h"
#include "base/units.h"

#include "base/errors.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gearfem::fem
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    using units::pi;
  } // namespace

  std::pair<mesh::Vec2, mesh::Vec2> flank_point_and_normal(const geometry::ToothProfile &tooth,
                                                           int tooth_index, bool drive_side,
                                                           double r)
  {
    const auto side = drive_side ? geometry::Side::drive : geometry::Side::coast;
    const double angle = 2.0 * pi * tooth_index / tooth.teeth();
    const double c = std::cos(angle), s = std::sin(angle);
    auto rot = [&](const mesh::Vec2 &v) { return mesh::Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y()); };
    for (const int i : tooth.flank_segments(side))
      {
        const auto &sg = tooth.segments()[i];
        const double ra = sg.curve->point(sg.t0).norm(), rb = sg.curve->point(sg.t1).norm();
        const double lo = std::min(ra, rb), hi = std::max(ra, rb);
        if (r < lo - 1e-12 || r > hi + 1e-12)
          continue;
        // A radius within 1e-12 m outside the piece is its end (the default load radius is
        // the radius of the flank's last point).
        const double t = geometry::parameter_at_radius(*sg.curve, sg.t0, sg.t1, std::clamp(r, lo, hi));
        // The outline runs counter-clockwise from t0 to t1: outward normal = direction of
        // travel rotated by -90 deg.
        mesh::Vec2 d = sg.curve->d1(t) * (sg.t1 >= sg.t0 ? 1.0 : -1.0);
        const mesh::Vec2 n(d.y(), -d.x());
        return {rot(sg.curve->point(t)), rot(n.normalized())};
      }
    throw InputError("load radius", to_string_g(r * 1e3) + " mm",
                     "within the flank, up to the tip radius " +
                       to_string_g(tooth.radii().tip * 1e3) + " mm");
  }

  FlankLoadResult solve_flank_load(const geometry::ToothProfile &tooth,
                                   const mesh::GearMeshParameters &mp, const Elasticity &material,
                                   const FeOptions &fe_in, const FlankLoad &load,
                                   std::unique_ptr<ElasticBody> *body_out,
                                   dealii::Vector<double> *u_out)
  {
    FlankLoadResult res;
    require_greater("Loading/Normal force", load.normal_force, 0.0, "N");
    require_greater("Loading/Patch length", load.patch_length, 0.0, "m");
    const int z   = tooth.teeth();
    const int k   = ((load.tooth % z) + z) % z;
    double r_top  = 0;
    for (const int i : tooth.flank_segments(load.drive_side ? geometry::Side::drive : geometry::Side::coast))
      for (double t : {tooth.segments()[i].t0, tooth.segments()[i].t1})
        r_top = std::max(r_top, tooth.segments()[i].curve->point(t).norm());
    const double r_load = load.load_radius > 0 ? load.load_radius : r_top;
    const auto [x_load, n_load] = flank_point_and_normal(tooth, k, load.drive_side, r_load);
    (void)x_load;

    auto t0 = Clock::now();
    // Mesh vertices at the patch edge, so that the patch is a union of whole faces.
    mesh::GearMeshParameters mp_split = mp;
    mp_split.flank_split_radii.push_back(r_load - load.patch_length);
    const mesh::MeshData m = mesh::mesh_gear(tooth, mp_split);
    res.t_mesh = since(t0);

    t0 = Clock::now();
    FeOptions fe    = fe_in;
    fe.refinements  = fe_in.refinements + mp.refinements;
    auto body       = std::make_unique<ElasticBody>(m, material, fe);
    res.t_setup     = since(t0);
    body->constrain(mesh::boundary::bore);
    if (mp.model == mesh::GearMeshParameters::Model::sector)
      {
        body->constrain(mesh::boundary::cut_cw);
        body->constrain(mesh::boundary::cut_ccw);
      }
    body->assemble_and_factorize();
    res.t_assemble  = body->assemble_seconds();
    res.t_factorize = body->factorize_seconds();
    res.solver      = body->solver_used();

    const auto flank_code = load.drive_side ? mesh::boundary::flank_drive : mesh::boundary::flank_coast;
    const double r_lo     = r_load - load.patch_length;
    Tensor2 t_dir;
    t_dir[0] = -n_load.x();
    t_dir[1] = -n_load.y();
    auto f = body->traction_load([&](const Point2 &) { return t_dir; },
                                 {dealii::types::boundary_id(mesh::boundary::tooth_id(k, flank_code))},
                                 [&](const Point2 &x) {
                                   const double r = x.norm();
                                   return r >= r_lo - 1e-12 && r <= r_load + 1e-12;
                                 });
    const double f_norm = body->resultant(f).norm();
    if (!(f_norm > 0))
      throw InputError("Loading/Patch length", to_string_g(load.patch_length * 1e3) + " mm",
                       "a patch that contains flank quadrature points",
                       "refine h_contact or enlarge the patch");
    f *= load.normal_force / f_norm;
    res.applied_resultant = body->resultant(f);

    t0 = Clock::now();
    const auto u = body->solve(f);
    res.t_solve  = since(t0);
    res.applied_moment  = body->moment(f);
    res.reaction_moment = body->moment(body->reactions(u, f));

    const auto tension_fillet = load.drive_side ? mesh::boundary::fillet_drive : mesh::boundary::fillet_coast;
    const auto other_fillet   = load.drive_side ? mesh::boundary::fillet_coast : mesh::boundary::fillet_drive;
    res.fillet_profile = body->boundary_stress(u, mesh::boundary::tooth_id(k, tension_fillet));
    res.fillet_peak    = body->peak_principal_stress(u, mesh::boundary::tooth_id(k, tension_fillet));
    res.opposite_peak  = body->peak_principal_stress(u, mesh::boundary::tooth_id(k, other_fillet));
    res.n_cells        = body->triangulation().n_active_cells();
    res.n_dofs         = body->n_dofs();
    if (u_out)
      *u_out = u;
    if (body_out)
      *body_out = std::move(body);
    return res;
  }
} // namespace gearfem::fem
