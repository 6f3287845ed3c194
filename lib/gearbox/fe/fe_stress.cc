#include "gearbox/fe/fe_stress.h"
#include "base/units.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"
#include "base/progress.h"
#include "base/table.h"
#include "solve/input.h"
#include "io/journal.h"
#include "solve/run.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::gearbox::fe
{
  namespace
  {
    using units::pi;

    std::string mm_12(double x)
    {
      std::ostringstream s;
      s << std::setprecision(12) << x * 1e3;
      return s.str();
    }

    std::string num(double x)
    {
      std::ostringstream s;
      s << std::setprecision(12) << x;
      return s.str();
    }

    /// The meshes solved: (stage, mesh) of every mesh of each selected stage.
    std::vector<std::pair<std::size_t, std::size_t>> selected(const gb::Train &t, const FeStressOptions &o)
    {
      std::vector<std::pair<std::size_t, std::size_t>> r;
      for (std::size_t k = 0; k < t.stages.size(); ++k)
        if (o.stages.empty() || std::find(o.stages.begin(), o.stages.end(), int(k + 1)) != o.stages.end())
          for (std::size_t j = 0; j < t.stages[k].meshes.size(); ++j)
            r.emplace_back(k, j);
      return r;
    }

    double max_of(const std::vector<double> &v, const std::vector<double> &T, double T0, const std::vector<double> *keep)
    {
      double m = 0.0;
      for (std::size_t i = 0; i < v.size(); ++i)
        if (std::abs(T[i] - T0) <= 1e-9 * T0 && (!keep || (*keep)[i] == 0.0))
          m = std::max(m, v[i]);
      return m;
    }
  } // namespace

  void validate(const FeStressOptions &o, std::size_t n_stages)
  {
    const std::string p = "FE stresses/";
    for (int k : o.stages)
      require_range(p + "Stages", k, 1, double(n_stages));
    require_range(p + "Sector teeth", o.sector_teeth, 3, 7);
    require_range(p + "h_contact", o.h_contact * 1e3, 0.0, 5.0, "mm");
    require_range(p + "h_fillet", o.h_fillet * 1e3, 0.0, 5.0, "mm");
    require_range(p + "h_body", o.h_body * 1e3, 0.0, 50.0, "mm");
    require_range(p + "Positions", o.positions, 4, 200);
    require_range(p + "Torque points", o.torque_points, 0, 50);
  }

  std::string contact_case(const gb::MeshGeometry &g, const gb::StageInput &s, const gb::StageMaterial &m,
                           const rating::agma::Tool &tool, const FeStressOptions &o,
                           const std::vector<double> &pinion_torques)
  {
    const double h_contact = o.h_contact > 0 ? o.h_contact : g.module / 30.0;
    const double h_fillet = o.h_fillet > 0 ? o.h_fillet : g.module / 14.0;
    const double h_body = o.h_body > 0 ? o.h_body : g.module;
    std::ostringstream c;
    c << "subsection Rack\n  set Module = " << mm_12(g.module) << "\n  set Pressure angle = " << num(g.alpha / units::deg)
      << "\n  set Addendum coefficient = " << num(s.addendum) << "\n  set Dedendum coefficient = " << num(tool.h_ao)
      << "\n  set Root radius coefficient = " << num(tool.rho_ao) << "\nend\n";
    const int z[2] = {g.z1, g.z2};
    const double x[2] = {g.x1, g.x2};
    for (int i = 0; i < 2; ++i)
      c << "subsection Gear " << i + 1 << "\n  set Number of teeth = " << z[i]
        << "\n  set Profile shift coefficient = " << num(x[i]) << "\n  set Tip shortening coefficient = "
        << num(s.tip_shortening) << "\n  set Face width = " << mm_12(g.b) << "\nend\n";
    if (g.internal)
      c << internal_case(g, s, tool);
    else
      c << "subsection Pair\n  set Centre distance = " << mm_12(g.a) << "\nend\n";
    c << "subsection Material\n  set Plane model = plane strain\n";
    for (int i = 1; i <= 2; ++i)
      c << "  subsection Gear " << i << "\n    set Young's modulus = " << num(m.E / 1e9)
        << "\n    set Poisson ratio = " << num(m.nu) << "\n  end\n";
    c << "end\n";
    c << "subsection Mesh\n  set Model = sector\n  set Sector teeth = " << o.sector_teeth
      << "\n  set h_contact = " << mm_12(h_contact) << "\n  set h_fillet = " << mm_12(h_fillet)
      << "\n  set h_body = " << mm_12(h_body) << "\nend\n";
    c << "subsection Solve\n  set Positions = cycle\n  set Number of positions = " << o.positions
      << "\n  set Pitches = 1\n  set Start = A\n  set Torques = ";
    for (std::size_t i = 0; i < pinion_torques.size(); ++i)
      c << (i ? ", " : "") << num(pinion_torques[i]);
    c << "\n  set VTU = none\n  set Plots = false\nend\n";
    return c.str();
  }

  std::string internal_case(const gb::MeshGeometry &g, const gb::StageInput &s, const rating::agma::Tool &tool)
  {
    geometry::InternalGearParameters ring;
    ring.name = "Gear 2", ring.teeth = g.z2, ring.module = g.module, ring.pressure_angle = g.alpha;
    ring.profile_shift = g.x2, ring.addendum = s.addendum, ring.tip_shortening = s.tip_shortening;
    ring.cutter.teeth = g.z1, ring.cutter.addendum = tool.h_ao, ring.cutter.tip_radius = tool.rho_ao;
    const double r_f2 = geometry::InternalToothProfile::generate(ring).radii().root;
    std::ostringstream c;
    c << "subsection Pair\n  set Type = internal\n  set Centre distance = 0\nend\n";
    c << "subsection Ring\n  set Cutter teeth = " << ring.cutter.teeth << "\n  set Cutter addendum coefficient = "
      << num(ring.cutter.addendum) << "\n  set Cutter tip radius coefficient = " << num(ring.cutter.tip_radius);
    const double rim = 0.5 * s.ring_outer - r_f2;
    if (!(rim > 0))
      c << "\n  set Backup ratio = 1.2";
    c << "\nend\n";
    if (rim > 0)
      c << "subsection Mesh\n  subsection Gear 2\n    set Rim thickness = " << mm_12(rim) << "\n  end\nend\n";
    return c.str();
  }

  double fe_pinion_torque(const gb::Train &t, std::size_t k, std::size_t j, double M, const gb::AgmaFactors &f)
  {
    const gb::Stage &st = t.stages[k];
    const gb::MeshGeometry &g = st.meshes[j];
    return st.tangential_load(t.torques(M)[k]) * g.r_w1 * f.K_o * f.K_v * f.K_s * g.K_H;
  }

  std::vector<double> solve_torques(const gearbox::fatigue::Spectrum &s, int points)
  {
    std::vector<double> T = s.torques;
    std::sort(T.begin(), T.end());
    T.erase(std::unique(T.begin(), T.end()), T.end());
    if (points == 0 || T.size() <= 1)
      return T;
    if (points == 1)
      return {T.back()};
    std::vector<double> r;
    for (int i = 0; i < points; ++i)
      r.push_back(T.front() + (T.back() - T.front()) * i / (points - 1));
    return r;
  }

  double interpolate(const std::vector<double> &x, const std::vector<double> &y, double x0, double e)
  {
    auto ratio = [&](std::size_t i) { return y[i] / std::pow(x[i], e); };
    if (x.size() == 1 || x0 <= x.front())
      return ratio(0) * std::pow(x0, e);
    if (x0 >= x.back())
      return ratio(x.size() - 1) * std::pow(x0, e);
    const std::size_t i = std::upper_bound(x.begin(), x.end(), x0) - x.begin();
    const double w = (x0 - x[i - 1]) / (x[i] - x[i - 1]);
    return ((1 - w) * ratio(i - 1) + w * ratio(i)) * std::pow(x0, e);
  }

  MeshFeStress solve_mesh(const gb::GearboxInput &in, const gb::Train &t, std::size_t k, std::size_t j,
                          const std::vector<double> &M, const FeStressOptions &o)
  {
    const auto start = std::chrono::steady_clock::now();
    MeshFeStress r;
    r.stage = k, r.mesh = j;
    const gb::MeshGeometry &g = t.stages[k].meshes[j];
    r.name = t.stages[k].in.name + " " + g.name;
    r.input_torques = M;
    for (double m : M)
      r.pinion_torques.push_back(fe_pinion_torque(t, k, j, m, in.agma));
    const std::string text = contact_case(g, in.stages[k], in.materials[k], in.agma.tool, o, r.pinion_torques);
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    const solve::GearContactInput ci = solve::parse_gear_contact_input(prm);
    auto model = ci.model();
    r.dofs = model->n_dofs();
    r.dir = o.output_dir / ("stage" + std::to_string(k + 1) + "_" + g.name);
    std::filesystem::create_directories(r.dir);
    write_file_atomically(r.dir / "case.prm", "# gearfem solve case of " + r.name + " (gearfem gearbox, FE stresses)\n" + text);
    solve::SolveRunOptions so;
    so.output_dir = r.dir;
    so.input_hash = io::content_hash(text);
    so.input_name = "case.prm";
    so.out = o.out;
    const solve::SolveRunResult run = solve::run_solve(*model, ci, so);
    r.failure = run.failure;
    const Table &sw = run.results.sweep, &pr = run.results.pairs;
    const auto sT = sw.column("torque"), pT = pr.column("torque");
    const auto edge = pr.column("edge contact");
    for (double T : r.pinion_torques)
      {
        r.sigma_H.push_back(max_of(pr.column("p_Hertz"), pT, T, &edge) * 1e6);
        r.p_max.push_back(max_of(pr.column("p_max"), pT, T, &edge) * 1e6);
        r.sigma_F1.push_back(max_of(sw.column("root stress pinion"), sT, T, nullptr) * 1e6);
        r.sigma_F2.push_back(max_of(sw.column("root stress gear"), sT, T, nullptr) * 1e6);
      }
    // A torque without a flank-to-flank pair or a fillet stress would enter the damage sum
    // as "no damage": refuse it like a solver failure.
    for (std::size_t i = 0; i < r.pinion_torques.size() && r.failure.empty(); ++i)
      if (!(r.sigma_H[i] > 0 && r.sigma_F1[i] > 0 && r.sigma_F2[i] > 0))
        r.failure = "no flank-to-flank contact or no root stress over the mesh cycle at the pinion torque " +
                    to_string_g(r.pinion_torques[i]) + " N m (refine FE stresses/h_contact or add Positions)";
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

  FeStressResult fe_stress_table(const gb::GearboxInput &in, const gb::Train &t, const gb::StressTable &base,
                                 const FeStressOptions &o)
  {
    validate(o, t.stages.size());
    FeStressResult r;
    r.stress = base;
    const auto meshes = selected(t, o);
    const std::vector<double> M = solve_torques(in.spectrum, o.torque_points);
    Progress progress(o.out, meshes.size(), "FE mesh");
    for (std::size_t i = 0; i < meshes.size(); ++i)
      {
        const auto [k, j] = meshes[i];
        if (o.out)
          *o.out << "FE mesh " << i + 1 << "/" << meshes.size() << ": " << t.stages[k].in.name << " "
                 << t.stages[k].meshes[j].name << " at " << M.size() << " torques" << std::endl;
        MeshFeStress m = solve_mesh(in, t, k, j, M, o);
        const bool failed = !m.failure.empty();
        if (failed)
          r.failure = m.name + ": " + m.failure;
        else
          for (std::size_t b = 0; b < in.spectrum.torques.size(); ++b)
            {
              const double T = in.spectrum.torques[b];
              gb::MeshStress &s = r.stress[k][j][b];
              s.sigma_H = interpolate(M, m.sigma_H, T, 0.5);
              s.sigma_F1 = interpolate(M, m.sigma_F1, T, 1.0);
              s.sigma_F2 = interpolate(M, m.sigma_F2, T, 1.0);
            }
        r.meshes.push_back(std::move(m));
        progress.step(i + 1, r.meshes.back().name);
        if (failed)
          break;
      }
    return r;
  }

  void write_fe_stresses(const FeStressResult &r, const std::filesystem::path &file)
  {
    Table t;
    for (const auto &[n, u] : std::vector<std::pair<std::string, std::string>>{
           {"stage", "-"}, {"mesh (0 sun-planet or pair)", "-"}, {"input torque", "N m"},
           {"FE pinion torque", "N m"}, {"sigma_H FE Hertz", "MPa"}, {"p_max FE nodal", "MPa"},
           {"sigma_F1 FE", "MPa"}, {"sigma_F2 FE", "MPa"}, {"DoFs", "-"}})
      t.add_column(n, u);
    for (const MeshFeStress &m : r.meshes)
      for (std::size_t i = 0; i < m.sigma_H.size(); ++i)
        {
          const std::vector<double> row = {double(m.stage + 1), double(m.mesh), m.input_torques[i],
                                           m.pinion_torques[i], m.sigma_H[i] / 1e6, m.p_max[i] / 1e6,
                                           m.sigma_F1[i] / 1e6, m.sigma_F2[i] / 1e6, double(m.dofs)};
          for (double v : row)
            require_finite_output(v, file.string(), "FE stresses");
          t.add_row(row);
        }
    t.write_csv(file);
  }

  std::string fe_markdown(const FeStressResult &r, const FeStressOptions &o)
  {
    std::ostringstream s;
    s << std::setprecision(5);
    s << "\n## FE stresses\n\n"
      << "Meshes solved with the `gearfem solve` chain (solve::run_solve) on " << o.sector_teeth
      << "-tooth sector models (plane strain, Lagrange contact), " << o.positions
      << " positions over one mesh cycle from A, at the pinion torque F_t r_w1 K_o K_v K_s K_H (the AGMA "
         "load W). sigma_H: the largest Hertz pressure over the cycle from the FE load share of each "
         "flank-to-flank pair on the local involute radii (p_Hertz); sigma_F: the largest fillet sigma_1 "
         "of each member over the cycle (a ring's: its tension-side fillet; planet-ring meshes at the "
         "zero-backlash centre distance, the ring cut by a shaper with the planet's tooth count). Between the solved torques sigma_H/sqrt(T) and sigma_F/T are "
         "interpolated linearly in T (constant beyond). Files: fe_stresses.csv and each mesh's solve "
         "results folder.\n\n"
      << "| mesh | input torque [N m] | FE pinion torque [N m] | sigma_H (Hertz, FE share) [MPa] | "
         "p_max nodal [MPa] | sigma_F1 [MPa] | sigma_F2 [MPa] | DoFs |\n|---|---|---|---|---|---|---|---|\n";
    for (const MeshFeStress &m : r.meshes)
      for (std::size_t i = 0; i < m.sigma_H.size(); ++i)
        s << "| " << m.name << " | " << m.input_torques[i] << " | " << m.pinion_torques[i] << " | "
          << m.sigma_H[i] / 1e6 << " | " << m.p_max[i] / 1e6 << " | " << m.sigma_F1[i] / 1e6 << " | "
          << m.sigma_F2[i] / 1e6 << " | " << m.dofs << " |\n";
    if (!r.failure.empty())
      s << "\nSolver failure: " << r.failure << "\n";
    return s.str();
  }
} // namespace gearfem::gearbox::fe
