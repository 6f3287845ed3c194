// `gearfem solve case.prm`: loaded static contact of the pair over the mesh positions and
// torques of the `Solve` section. Writes sweep.csv, pairs.csv, pressure.csv,
// line_of_action.csv, results.h5 (layout in docs/output-format.md), VTU/PVD files of the
// deformed pair and the PNG plots (scripts/plot_solve.py).
#include "analytical/iso6336.h"
#include "base/errors.h"
#include "base/progress.h"
#include "base/table.h"
#include "commands/command.h"
#include "commands/hdf5_tables.h"
#include "contact/parameters.h"
#include "fem/output.h"

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace gearfem::commands
{
  namespace
  {
    const double pi = 3.14159265358979323846;

    int point_code(const std::string &n)
    {
      const std::string names = "ABCDE";
      const auto p            = n.size() == 1 ? names.find(n[0]) : std::string::npos;
      return p == std::string::npos ? 0 : int(p) + 1;
    }

    Table make_table(const std::vector<std::pair<std::string, std::string>> &cols)
    {
      Table t;
      for (const auto &[n, u] : cols)
        t.add_column(n, u);
      return t;
    }

    struct Tables
    {
      Table sweep = make_table({{"torque", "N m"}, {"position", "-"}, {"roll angle", "deg"},
                                {"point (0 none; 1 A; 2 B; 3 C; 4 D; 5 E)", "-"}, {"STE", "um"},
                                {"STE angle", "urad"}, {"F_n", "N"}, {"k_secant", "N/m"},
                                {"k_tangent", "N/m"}, {"k_secant per width", "N/(mm um)"},
                                {"k_tangent per width", "N/(mm um)"}, {"pairs in contact", "-"},
                                {"max load share", "-"}, {"T1 contact moment", "N m"},
                                {"T1 reaction", "N m"}, {"T2 z1/(T1 z2)", "-"}, {"p_max", "MPa"},
                                {"p_max edge", "MPa"},
                                {"root stress pinion", "MPa"}, {"root stress gear", "MPa"},
                                {"active nodes", "-"}, {"geometry iterations", "-"},
                                {"active-set iterations", "-"}, {"load cuts", "-"},
                                {"complementarity", "-"}, {"max penetration", "um"}, {"time", "s"}});
      Table pairs = make_table({{"torque", "N m"}, {"position", "-"}, {"roll angle", "deg"},
                                {"pinion tooth", "-"}, {"gear tooth", "-"}, {"F_n", "N"},
                                {"load share", "-"}, {"active nodes", "-"}, {"p_max", "MPa"},
                                {"p_Hertz", "MPa"}, {"half width", "mm"}, {"a_Hertz", "mm"},
                                {"resolved", "-"}, {"edge contact", "-"}, {"slave body", "-"},
                                {"radius pinion", "mm"},
                                {"root stress pinion", "MPa"}, {"root radius pinion", "mm"},
                                {"root stress gear", "MPa"}, {"root radius gear", "mm"}});
      Table pressure = make_table({{"torque", "N m"}, {"position", "-"}, {"roll angle", "deg"},
                                   {"pinion tooth", "-"}, {"s", "mm"}, {"radius", "mm"}, {"p", "MPa"}});
      Table loa = make_table({{"point (1 A; 2 B; 3 C; 4 D; 5 E)", "-"}, {"roll angle", "deg"}});

      void add(const contact::PositionResult &r, const std::string &name, int index, double z_ratio)
      {
        const double deg = 180 / pi;
        const auto &s = r.solution;
        double share = 0;
        for (const auto &p : r.pairs)
          share = std::max(share, p.share);
        sweep.add_row({r.torque, double(index), r.phi1 * deg, double(point_code(name)), r.ste * 1e6,
                       r.rotation * 1e6, r.normal_force, r.k_secant, r.k_tangent, width(r.k_secant),
                       width(r.k_tangent), double(r.n_pairs), share, r.torque_contact, r.torque_reaction,
                       r.torque_gear / (r.torque * z_ratio), r.p_max / 1e6, r.p_max_edge / 1e6,
                       r.max_root_stress_pinion / 1e6,
                       r.max_root_stress_gear / 1e6, double(s.n_active), double(s.geometry_iterations),
                       double(s.active_set_iterations), double(s.load_cuts), s.complementarity,
                       s.max_penetration * 1e6, r.t_total});
        for (const auto &p : r.pairs)
          {
            pairs.add_row({r.torque, double(index), r.phi1 * deg, double(p.pinion_tooth), double(p.gear_tooth),
                           p.force, p.share, double(p.active_nodes), p.p_max / 1e6, p.p_hertz / 1e6,
                           p.half_width * 1e3, p.a_hertz * 1e3, double(p.resolved), double(p.edge),
                           double(p.slave_body),
                           p.radius_pinion * 1e3, p.root_stress_pinion / 1e6, p.root_radius_pinion * 1e3,
                           p.root_stress_gear / 1e6, p.root_radius_gear * 1e3});
            for (const auto &q : p.profile)
              pressure.add_row({r.torque, double(index), r.phi1 * deg, double(p.pinion_tooth), q[0] * 1e3,
                                q[1] * 1e3, q[2] / 1e6});
          }
      }
      double face_width = 1;
      double width(double k) const { return k / (face_width * 1e3) * 1e-6; } // N/m -> N/(mm um)
    };

    void declare(dealii::ParameterHandler &prm) { contact::declare_gear_contact_input(prm); }

    void write_outputs(const Tables &t, const contact::GearContactInput &in, const RunContext &ctx,
                       const std::map<double, std::vector<std::pair<double, std::string>>> &pvd)
    {
      t.sweep.write_csv(ctx.output_dir / "sweep.csv");
      t.pairs.write_csv(ctx.output_dir / "pairs.csv");
      t.pressure.write_csv(ctx.output_dir / "pressure.csv");
      t.loa.write_csv(ctx.output_dir / "line_of_action.csv");
      write_hdf5_tables({{"sweep", t.sweep}, {"pairs", t.pairs}, {"pressure", t.pressure},
                         {"line_of_action", t.loa}},
                        ctx.output_dir / "results.h5",
                        {{"format", "gearfem-solve-results"}, {"format_version", "1"},
                         {"program", "gearfem solve"},
                         {"geometry_hash", geometry::geometry_fingerprint(*in.pair)},
                         {"method", contact::to_string(in.contact.method)},
                         {"input", ctx.input_file.filename().string()}});
      for (const auto &[T, records] : pvd)
        if (!records.empty())
          {
            std::ostringstream n;
            n << "pair_T" << T << ".pvd";
            fem::write_pvd(ctx.output_dir / n.str(), records);
          }
    }

    void run(dealii::ParameterHandler &prm, const RunContext &ctx)
    {
      std::ostream &out = *ctx.out;
      const contact::GearContactInput in = contact::parse_gear_contact_input(prm);
      const auto positions = in.positions();
      const auto &pair     = *in.pair;
      const auto &sp       = in.solve;
      out << "solve: z " << pair.gear(1).teeth() << "/" << pair.gear(2).teeth() << ", a "
          << pair.center_distance() * 1e3 << " mm, contact ratio " << pair.contact_ratio() << ", "
          << positions.size() << " positions x " << sp.torques.size() << " torques, method "
          << contact::to_string(in.contact.method) << ", slave body " << in.contact.slave << ", "
          << (in.material[0].model == fem::PlaneModel::plane_stress ? "plane stress" : "plane strain")
          << "\n";
      if (ctx.validate_only)
        return;

      auto model = in.model();
      out << "model: " << model->n_dofs() << " DoFs (" << model->body(1).n_dofs() << " + "
          << model->body(2).n_dofs() << "), " << model->body(1).triangulation().n_active_cells() << " + "
          << model->body(2).triangulation().n_active_cells() << " cells, mesh " << std::setprecision(3)
          << model->mesh_seconds() << " s, set-up (mesh, assemble, factorise) " << model->setup_seconds()
          << " s" << std::endl;

      Tables t;
      t.face_width = std::min(in.material[0].thickness, in.material[1].thickness);
      for (const char *n : {"A", "B", "C", "D", "E"})
        t.loa.add_row({double(point_code(n)), pair.point(n).roll_angle * 180 / pi});
      const double z_ratio = double(pair.gear(2).teeth()) / pair.gear(1).teeth();
      std::map<double, std::vector<std::pair<double, std::string>>> pvd;
      // Positions written as VTU under `VTU = named`: every position of a `named` run, else
      // the positions nearest to B, C and D.
      std::set<std::size_t> vtu_named;
      for (std::size_t i = 0; i < positions.size(); ++i)
        if (sp.positions == contact::SolveParameters::Positions::named)
          vtu_named.insert(i);
      if (sp.positions != contact::SolveParameters::Positions::named)
        for (const char *n : {"B", "C", "D"})
          {
            std::size_t best = 0;
            for (std::size_t i = 1; i < positions.size(); ++i)
              if (std::abs(positions[i].second - pair.point(n).roll_angle) <
                  std::abs(positions[best].second - pair.point(n).roll_angle))
                best = i;
            vtu_named.insert(best);
          }
      Progress progress(&out, positions.size() * sp.torques.size(), "position");
      std::size_t done = 0;
      std::map<double, int> unresolved;
      std::string failure;
      for (const double T : sp.torques)
        {
          contact::PositionResult prev;
          bool have_prev = false;
          for (std::size_t i = 0; i < positions.size() && failure.empty(); ++i)
            {
              const auto &[name, phi] = positions[i];
              const bool keep = sp.vtu == contact::SolveParameters::Vtu::all ||
                                (sp.vtu == contact::SolveParameters::Vtu::named && vtu_named.count(i));
              contact::PositionResult r;
              try
                {
                  r = model->solve(phi, T, have_prev ? &prev : nullptr, keep);
                }
              catch (const SolverError &e)
                {
                  failure = e.what();
                  break;
                }
              t.add(r, name, int(i), z_ratio);
              for (const auto &p : r.pairs)
                unresolved[T] += p.share > 0.05 && !p.resolved && !p.edge;
              if (keep)
                {
                  std::ostringstream n;
                  n << "pair_T" << T << "_" << std::setw(3) << std::setfill('0') << i << ".vtu";
                  model->write_vtu(r, ctx.output_dir / n.str(), sp.vtu_scale);
                  pvd[T].emplace_back(phi * 180 / pi, n.str());
                  r.u[0].reinit(0), r.u[1].reinit(0);
                }
              std::ostringstream d;
              d << "T " << T << " N m, roll " << std::fixed << std::setprecision(3) << phi * 180 / pi
                << " deg" << (name.empty() ? "" : " (" + name + ")") << ", STE " << std::setprecision(3)
                << r.ste * 1e6 << " um, pairs " << r.n_pairs << ", " << std::setprecision(2) << r.t_total << " s";
              progress.step(++done, d.str());
              prev      = std::move(r);
              have_prev = true;
            }
          if (!failure.empty())
            break;
        }
      write_outputs(t, in, ctx, pvd);
      if (sp.plots && t.sweep.n_rows() > 0)
        run_plot_script("plot_solve.py", {ctx.output_dir.string()}, &out);
      if (!failure.empty())
        throw SolverError(failure + "\n  the " + std::to_string(t.sweep.n_rows()) +
                          " completed positions are saved in " + ctx.output_dir.string());

      // Summary per torque, with ISO 6336-1 c_gamma_alpha b for comparison.
      analytical::iso6336::StiffnessInput si;
      si.z1 = pair.gear(1).teeth(), si.z2 = pair.gear(2).teeth();
      si.x1 = pair.gear(1).parameters().profile_shift, si.x2 = pair.gear(2).parameters().profile_shift;
      si.alpha_n   = pair.gear(1).parameters().rack.pressure_angle;
      si.module    = pair.gear(1).parameters().rack.module;
      si.h_fP1     = pair.gear(1).parameters().rack.dedendum;
      si.h_fP2     = pair.gear(2).parameters().rack.dedendum;
      si.eps_alpha = pair.contact_ratio();
      double c_gamma = 0;
      try
        {
          c_gamma = analytical::iso6336::mesh_stiffness(si).c_gamma_alpha;
        }
      catch (const InputError &)
        {}
      out << "\n| T1 [N m] | mean STE [um] | STE p-p [um] | mean k_secant [N/(mm um)] | ISO 6336-1 "
             "c_gamma_alpha [N/(mm um)] | ratio | max p [MPa] | max root stress pinion/gear [MPa] | "
             "unresolved pair-positions (pairs x positions) |\n|---|---|---|---|---|---|---|---|---|\n";
      const auto T_col = t.sweep.column("torque"), ste = t.sweep.column("STE"),
                 k = t.sweep.column("k_secant per width"), p = t.sweep.column("p_max"),
                 sp1 = t.sweep.column("root stress pinion"), sp2 = t.sweep.column("root stress gear");
      for (const double T : sp.torques)
        {
          double sum = 0, lo = 1e300, hi = -1e300, ks = 0, pm = 0, s1 = 0, s2 = 0;
          int n = 0;
          for (std::size_t i = 0; i < T_col.size(); ++i)
            if (T_col[i] == T)
              {
                sum += ste[i], ks += k[i], ++n;
                lo = std::min(lo, ste[i]), hi = std::max(hi, ste[i]);
                pm = std::max(pm, p[i]), s1 = std::max(s1, sp1[i]), s2 = std::max(s2, sp2[i]);
              }
          if (n == 0)
            continue;
          out << std::setprecision(4) << "| " << T << " | " << sum / n << " | " << hi - lo << " | " << ks / n
              << " | " << c_gamma << " | " << (c_gamma > 0 ? ks / n / c_gamma : 0.0) << " | " << pm << " | "
              << s1 << " / " << s2 << " | " << unresolved[T] << " |\n";
        }
      int n_unresolved = 0;
      for (const auto &[T, n] : unresolved)
        n_unresolved += n;
      if (n_unresolved > 0)
        out << "warning: " << n_unresolved
            << " loaded tooth-pair positions (each loaded pair at each position, all torques) have fewer "
               "than 5 contact nodes across the patch: their peak pressure is unresolved (refine "
               "Mesh/h_contact; column \"resolved\" of pairs.csv); STE, stiffness and root "
               "stress are not affected\n";
    }
  } // namespace

  Command solve_command()
  {
    Command c;
    c.name        = "solve";
    c.summary     = "loaded static contact over the mesh cycle: STE, mesh stiffness, load sharing, pressure, root stress";
    c.description = "Meshes both gears, factorises them once, and solves frictionless contact (Lagrange\n"
                    "multipliers or penalty) at each position of the `Solve` section for each torque,\n"
                    "with the pinion rotation found by torque targeting.\n"
                    "Writes sweep.csv, pairs.csv, pressure.csv, line_of_action.csv, results.h5\n"
                    "(docs/output-format.md), pair_T<T>_<i>.vtu + pair_T<T>.pvd, and ste.png,\n"
                    "stiffness.png, load_sharing.png, pressure.png, root_stress.png.\n"
                    "Sample runs:\n"
                    "  gearfem solve inputs/demo.prm\n"
                    "  gearfem solve inputs/parker_ste.prm --output-dir results/parker\n";
    c.declare = declare;
    c.run     = run;
    return c;
  }
} // namespace gearfem::commands
