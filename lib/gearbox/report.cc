#include "gearbox/report.h"
#include "base/units.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::gearbox
{
  namespace
  {
    using units::pi;

    /// A finite number for an output file (throws otherwise: nothing non-finite is written).
    std::string num(double v, const std::string &file, const std::string &what, int precision = 6)
    {
      require_finite_output(v, file, what);
      std::ostringstream s;
      s << std::setprecision(precision) << v;
      return s.str();
    }
    /// A life: "no damage" (md) or "" (csv) when infinite.
    std::string life(double v, const std::string &file, bool csv)
    {
      return std::isinf(v) ? (csv ? "" : "no damage") : num(v, file, "life");
    }

    struct Row
    {
      std::string quantity, symbol, clause, unit;
      double value;
    };
    std::vector<Row> mesh_rows(const MeshGeometry &g, const Stage &st, const AgmaFactors &f)
    {
      const std::string p = g.pinion, q = g.gear;
      const std::string sign = g.internal ? " (internal: lower signs)" : "";
      std::vector<Row> r = {
        {"working radius of the " + p, "r_w1", "Siasos 2010 eq. 2.1.1-9", "mm", g.r_w1 * 1e3},
        {"working radius of the " + q, "r_w2", g.internal ? "Siasos 2010 eq. 2.1.2-4" : "Siasos 2010 eq. 2.1.1-9", "mm", g.r_w2 * 1e3},
        {"tip radius of the " + p, "r_a1", "Siasos 2010 eq. 2.1.1-9 (r_k)", "mm", g.r_a1 * 1e3},
        {"tip radius of the " + q, "r_a2", g.internal ? "Siasos 2010 sec. 2.1.2 (r_k)" : "Siasos 2010 eq. 2.1.1-9 (r_k)", "mm", g.r_a2 * 1e3},
        {"centre distance", "a", g.internal ? "Siasos 2010 eq. 2.2.2-1" : "Siasos 2010 eq. 2.2.1-1", "mm", g.a * 1e3},
        {"operating pitch diameter 2a/(u" + std::string(g.internal ? "-" : "+") + "1)", "d_w1", "2101-D04 (Siasos 2010 sec. 4.1)" + sign, "mm", g.d_w1 * 1e3},
        {"operating pressure angle", "phi_r", "908-B89 (Siasos 2010 eqs. 4.3-12..19)" + sign, "deg", g.loa.phi_r / units::deg},
        {"start of contact (unit module)", "C1", "908-B89 (Siasos 2010 eqs. 4.3-12..19)" + sign, "-", g.loa.C1},
        {"LPSTC (unit module)", "C2", "908-B89 (Siasos 2010 eq. 4.3-17)", "-", g.loa.C2},
        {"pitch point (unit module)", "C3", "908-B89 (Siasos 2010 eq. 4.3-14)" + sign, "-", g.loa.C3},
        {"HPSTC (unit module)", "C4", "908-B89 (Siasos 2010 eq. 4.3-15)", "-", g.loa.C4},
        {"end of contact (unit module)", "C5", "908-B89 (Siasos 2010 eqs. 4.3-12..19)", "-", g.loa.C5},
        {"T1T2 (unit module)", "C6", "908-B89 (Siasos 2010 eqs. 4.3-12..19)", "-", g.loa.C6},
        {"transverse contact ratio", "m_p", "908-B89 (Siasos 2010 eq. 4.3-19)", "-", g.loa.contact_ratio},
        {"pitting geometry factor", "Z_I", "908-B89 (Siasos 2010 eq. 4.3.1-1)" + sign, "-", g.Z_I},
        {"elastic coefficient", "Z_E", "2101-D04 (Siasos 2010 eq. 4.1-2)", "sqrt(MPa)", g.Z_E / 1e3},
        {"overload factor", "K_o", "2101-D04 (input)", "-", f.K_o},
        {"dynamic factor", "K_v", "2101-D04 (input)", "-", f.K_v},
        {"size factor", "K_s", "2101-D04 (input)", "-", f.K_s},
        {"surface condition factor", "Z_R", "2101-D04 (input)", "-", f.Z_R},
        {std::string("mesh alignment factor (") + agma::to_string(f.enclosure) + ")", "K_Hma", "2101-D04 (Siasos 2010 eq. 4.1.6-4)", "-", g.K_Hma},
        {"pinion proportion factor", "K_Hpf", "2101-D04 (Siasos 2010 eqs. 4.1.6-5..7)", "-", g.K_Hpf},
        {"load distribution factor 1 + K_Hma + K_Hpf", "K_H", "2101-D04 (Siasos 2010 eq. 4.1.6-3)", "-", g.K_H},
        {"backup ratio of the " + p, "m_B1", "2101-D04 (Siasos 2010 sec. 4.2.1; 0: solid)", "-", g.m_B1},
        {"rim thickness factor of the " + p, "K_B1", "2101-D04 (Siasos 2010 sec. 4.2.1)", "-", g.K_B1},
        {"backup ratio of the " + q, "m_B2", "2101-D04 (Siasos 2010 sec. 4.2.1; 0: solid)", "-", g.m_B2},
        {"rim thickness factor of the " + q, "K_B2", "2101-D04 (Siasos 2010 sec. 4.2.1)", "-", g.K_B2},
        {"bending geometry factor of the " + p, "Y_J1", "908-B89 (Siasos 2010 eq. 4.3.2-1)", "-", g.Y_J1},
        {"bending geometry factor of the " + q + (g.internal ? " (ring: not rated)" : ""), "Y_J2", "908-B89 (Siasos 2010 eq. 4.3.2-1)", "-", g.Y_J2},
        {"load-sharing factor", "K_gamma", "Siasos 2010 table 7.2-1 / input", "-", st.K_gamma},
        {"zone factor", "Z_H", "6336-2 eq. 10", "-", g.iso.Z_H},
        {"contact ratio factor", "Z_eps", "6336-2 eq. 19", "-", g.iso.Z_eps},
        {"single pair contact factor, pinion", "Z_B", "6336-2 eqs. 12, 14" + std::string(g.internal ? " (z2 < 0)" : ""), "-", g.iso.Z_B},
        {"single pair contact factor, gear", "Z_D", g.internal ? "6336-2 (internal gear: 1)" : "6336-2 eqs. 13, 15", "-", g.iso.Z_D},
        {"application factor", "K_A", "6336-1 (input)", "-", f.K_A},
        {"dynamic factor", "K_v,ISO", "6336-1 (input)", "-", f.K_v_iso},
        {"face load factor", "K_Hbeta", "6336-1 (input); K_Halpha = 1", "-", f.K_Hbeta},
        {"face load factor (root) K_Hbeta^N_F", "K_Fbeta", "6336-1 eq. 41; K_Falpha = 1, Y_beta = 1", "-", g.K_Fbeta},
      };
      const iso6336::RootFactors *F[2] = {&g.F1_iso, &g.F2_iso};
      for (int i = 0; i < (g.internal ? 1 : 2); ++i)
        {
          const std::string who = i == 0 ? p : q, s = std::to_string(i + 1);
          const std::string fillet = "6336-3 eqs. 25-33 (rack-generated fillet, closed form)";
          r.push_back({"critical section chord (30 deg tangent), " + who, "s_Fn" + s, fillet, "mm", F[i]->s_Fn * 1e3});
          r.push_back({"fillet radius at the critical section, " + who, "rho_F" + s, fillet, "mm", F[i]->rho_F * 1e3});
          r.push_back({"bending moment arm, outer single contact, " + who, "h_Fe" + s, "6336-3 6.2", "mm", F[i]->h_Fe * 1e3});
          r.push_back({"load direction angle, " + who, "alpha_Fen" + s, "6336-3 6.2", "deg", F[i]->alpha_Fen / units::deg});
          r.push_back({"form factor, " + who, "Y_F" + s, "6336-3 eq. 24 (method B)", "-", F[i]->Y_F});
          r.push_back({"stress correction factor, " + who, "Y_S" + s, "6336-3 eq. 43", "-", F[i]->Y_S});
        }
      return r;
    }
  } // namespace

  void write_markdown(const GearboxInput &in, const GearboxResult &r, const std::string &source,
                      const std::filesystem::path &file, const std::string &title, const std::string &appendix)
  {
    const std::string fs = file.string();
    std::ostringstream s;
    s << "# " << title << "\n\n"
      << "Siasos 2010 (NTUA) system-level procedure: kinematics (eqs. 7.2-1..9), AGMA 2101-D04 / "
         "908-B89 stresses of every mesh (internal meshes with the lower signs of sec. 4.3), load cycles (table "
         "8.2-1), Miner damage (eqs. 8.4-1..4) and AGMA 925-A03 scuffing (sec. 4.4, SI units). Stress source: "
      << source << ".\n\n## Train\n\n| stage | type | i = n_in/n_out | input speed (rpm) | output speed (rpm) | "
         "input torque at the first bin (N m) | K_gamma |\n|---|---|---|---|---|---|---|\n";
    const auto n = r.train.speeds();
    const auto M = r.train.torques(in.spectrum.torques[0]);
    for (std::size_t k = 0; k < r.train.stages.size(); ++k)
      {
        const Stage &st = r.train.stages[k];
        s << "| " << st.in.name << " | "
          << (st.in.type == StageType::parallel ? "parallel" : st.in.fixed == Fixed::ring ? "planetary, ring fixed" : "planetary, carrier fixed")
          << " | " << num(st.ratio, fs, "ratio") << " | " << num(n[k], fs, "speed") << " | " << num(n[k + 1], fs, "speed")
          << " | " << num(M[k], fs, "torque") << " | " << num(st.K_gamma, fs, "K_gamma") << " |\n";
      }
    s << "\nCycles per gearbox-input revolution (table 8.2-1): ";
    for (std::size_t k = 0; k < r.train.stages.size(); ++k)
      {
        const Stage &st = r.train.stages[k];
        const double q = r.train.input_revolutions(k);
        s << st.in.name << ": " << (st.in.type == StageType::parallel ? "gear 1 " : "sun ") << num(q * st.cycles_sun, fs, "cycles")
          << ", " << (st.in.type == StageType::parallel ? "gear 2 " : "planet ") << num(q * st.cycles_planet, fs, "cycles");
        if (st.in.type == StageType::planetary)
          s << ", ring " << num(q * st.cycles_ring, fs, "cycles");
        s << (k + 1 < r.train.stages.size() ? "; " : ".\n");
      }
    for (std::size_t k = 0; k < r.train.stages.size(); ++k)
      for (std::size_t j = 0; j < r.train.stages[k].meshes.size(); ++j)
        {
          const Stage &st = r.train.stages[k];
          const MeshGeometry &g = st.meshes[j];
          s << "\n## " << st.in.name << ", " << g.name << " mesh (pinion " << g.pinion << ", gear " << g.gear << ")\n\n"
            << "| quantity | symbol | clause | unit | value |\n|---|---|---|---|---|\n";
          for (const Row &row : mesh_rows(g, st, in.agma))
            s << "| " << row.quantity << " | " << row.symbol << " | " << row.clause << " | " << row.unit << " | "
              << num(row.value, fs, row.symbol) << " |\n";
          s << "\n| M_in (N m) | sigma_H (MPa) | sigma_F1 (MPa) | sigma_F2 (MPa) | ISO sigma_H1 / sigma_H2 (MPa) | "
               "ISO sigma_F1 / sigma_F2 (MPa) | theta_fl,max (K) | theta_B,max (C) | h_c,min (um) | lambda_min | "
               "P_scuffing | risk |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
          for (std::size_t b = 0; b < in.spectrum.torques.size(); ++b)
            {
              const MeshStress &m = r.stress[k][j][b];
              const scuffing::Result &c = r.scuff[k][j][b];
              s << "| " << num(in.spectrum.torques[b], fs, "torque") << " | " << num(m.sigma_H / 1e6, fs, "sigma_H") << " | "
                << num(m.sigma_F1 / 1e6, fs, "sigma_F1") << " | " << num(m.sigma_F2 / 1e6, fs, "sigma_F2") << " | "
                << num(m.sigma_H1_iso / 1e6, fs, "ISO sigma_H1") << " / " << num(m.sigma_H2_iso / 1e6, fs, "ISO sigma_H2") << " | "
                << num(m.sigma_F1_iso / 1e6, fs, "ISO sigma_F1") << " / "
                << (g.internal ? std::string("-") : num(m.sigma_F2_iso / 1e6, fs, "ISO sigma_F2")) << " | "
                << num(c.theta_fl_max, fs, "theta_fl") << " | " << num(c.theta_B_max, fs, "theta_B") << " | "
                << num(c.h_c_min * 1e6, fs, "h_c") << " | " << num(c.lambda_min, fs, "lambda") << " | "
                << num(c.P, fs, "P", 3) << " | " << c.risk << " |\n";
            }
        }
    s << appendix;
    s << "\n## Fatigue life (Miner, eqs. 8.4-1..4; spectrum of " << num(in.spectrum.duration_years, fs, "years")
      << " years)\n\n| stage | member | mode | load | cycles per input rev | D | life (spectra) | life (years) |\n"
         "|---|---|---|---|---|---|---|---|\n";
    for (const MemberLife &m : r.lives)
      s << "| " << m.stage << " | " << m.member << " | " << m.mode << " | " << m.detail << " | "
        << num(m.cycles_per_revolution, fs, "cycles") << " | " << num(m.damage.D, fs, "D") << " | "
        << life(m.damage.life_spectra, fs, false) << " | " << life(m.life_years, fs, false) << " |\n";
    if (r.first_failure >= 0)
      {
        const MemberLife &m = r.lives[r.first_failure];
        s << "\n**First failure:** " << m.stage << " " << m.member << " (" << m.mode << "), after "
          << num(m.damage.life_spectra, fs, "life") << " spectra = " << num(m.life_years, fs, "life") << " years.\n";
      }
    else
      s << "\n**No member is damaged** by this spectrum.\n";
    s << "\nScuffing: oil temperature " << num(in.conditions.theta_oil, fs, "theta_oil") << " C, k_sump "
      << num(in.conditions.k_sump, fs, "k_sump") << ", theta_S "
      << num(scuffing::scuffing_temperature(in.oil), fs, "theta_S") << " C; mesh speeds relative to the carrier.\n";
    write_file_atomically(file, s.str());
  }

  void write_csv(const GearboxInput &in, const GearboxResult &r, const std::filesystem::path &dir)
  {
    const std::string f1 = (dir / "gearbox.csv").string(), f2 = (dir / "gearbox_life.csv").string(),
                      f3 = (dir / "scuffing_path.csv").string();
    std::ostringstream a, l, p;
    a << "stage,mesh,input torque [N m],F_t [N],sigma_H [MPa],sigma_F1 [MPa],sigma_F2 [MPa],ISO sigma_H1 [MPa],"
         "ISO sigma_H2 [MPa],theta_fl_max [K],theta_B_max [C],h_c_min [um],lambda_min [-],P_scuffing [-],ISO sigma_F1 [MPa],ISO sigma_F2 [MPa]\n";
    // The worst scuffing bin (highest theta_B) for the path file.
    std::size_t wk = 0, wj = 0, wb = 0;
    for (std::size_t k = 0; k < r.train.stages.size(); ++k)
      {
        const Stage &st = r.train.stages[k];
        for (std::size_t j = 0; j < st.meshes.size(); ++j)
          for (std::size_t b = 0; b < in.spectrum.torques.size(); ++b)
            {
              const MeshStress &m = r.stress[k][j][b];
              const scuffing::Result &c = r.scuff[k][j][b];
              if (c.theta_B_max > r.scuff[wk][wj][wb].theta_B_max)
                wk = k, wj = j, wb = b;
              a << st.in.name << "," << st.meshes[j].name << "," << num(in.spectrum.torques[b], f1, "torque") << ","
                << num(st.tangential_load(r.train.torques(in.spectrum.torques[b])[k]), f1, "F_t", 10) << ","
                << num(m.sigma_H / 1e6, f1, "sigma_H", 10) << "," << num(m.sigma_F1 / 1e6, f1, "sigma_F1", 10) << ","
                << num(m.sigma_F2 / 1e6, f1, "sigma_F2", 10) << "," << num(m.sigma_H1_iso / 1e6, f1, "ISO sigma_H1", 10) << ","
                << num(m.sigma_H2_iso / 1e6, f1, "ISO sigma_H2", 10) << "," << num(c.theta_fl_max, f1, "theta_fl") << ","
                << num(c.theta_B_max, f1, "theta_B") << "," << num(c.h_c_min * 1e6, f1, "h_c") << ","
                << num(c.lambda_min, f1, "lambda") << "," << num(c.P, f1, "P") << ","
                << num(m.sigma_F1_iso / 1e6, f1, "ISO sigma_F1", 10) << "," << num(m.sigma_F2_iso / 1e6, f1, "ISO sigma_F2", 10)
                << "\n";
            }
      }
    l << "stage,member,mode,load,cycles per input revolution [-],damage D [-],life [spectra] (empty: no damage),"
         "life [years] (empty: no damage)\n";
    for (const MemberLife &m : r.lives)
      l << m.stage << "," << m.member << "," << m.mode << ",\"" << m.detail << "\"," << num(m.cycles_per_revolution, f2, "cycles", 10)
        << "," << num(m.damage.D, f2, "D", 10) << "," << life(m.damage.life_spectra, f2, true) << ","
        << life(m.life_years, f2, true) << "\n";
    const scuffing::Result &w = r.scuff[wk][wj][wb];
    p << "# worst scuffing bin: " << r.train.stages[wk].in.name << " " << r.train.stages[wk].meshes[wj].name
      << ", input torque " << num(in.spectrum.torques[wb], f3, "torque") << " N m\n"
      << "roll angle [deg],rho1 [mm],rho2 [mm],X_Gamma [-],v_r1 [m/s],v_r2 [m/s],b_H [mm],theta_fl [K],h_c [um],"
         "lambda [-],theta_B [C]\n";
    for (const scuffing::PathPoint &q : w.path)
      p << num(q.roll / units::deg, f3, "roll") << "," << num(q.rho1 * 1e3, f3, "rho1") << "," << num(q.rho2 * 1e3, f3, "rho2")
        << "," << num(q.X, f3, "X") << "," << num(q.v1, f3, "v1") << "," << num(q.v2, f3, "v2") << ","
        << num(q.b_H * 1e3, f3, "b_H") << "," << num(q.theta_fl, f3, "theta_fl") << "," << num(q.h_c * 1e6, f3, "h_c")
        << "," << num(q.lambda, f3, "lambda") << "," << num(q.theta_B, f3, "theta_B") << "\n";
    write_file_atomically(dir / "gearbox.csv", a.str());
    write_file_atomically(dir / "gearbox_life.csv", l.str());
    write_file_atomically(dir / "scuffing_path.csv", p.str());
  }

  void write_sn_csv(const GearboxInput &in, const GearboxResult &r, const std::filesystem::path &file)
  {
    const std::string f = file.string();
    std::ostringstream s;
    s << "stage,member,mode,load,bin [-],input torque [N m],stress [MPa],cycles per spectrum [-],"
         "cycles to failure [-] (empty: no damage),n/N [-],curve (0 semi-log; 1 ISO) [-],sigma_n [MPa],N_ref [-],"
         "B [MPa/decade],N_static [-],Y_static [-]\n";
    for (const MemberLife &m : r.lives)
      {
        const StageMaterial &mat = in.materials.at(m.stage_index);
        const fatigue::SNCurve &c = m.mode == "contact" ? mat.contact : mat.bending;
        for (std::size_t l = 0; l < m.stress.size(); ++l)
          for (std::size_t b = 0; b < m.stress[l].size(); ++b)
            {
              const double sigma = m.stress[l][b], n = m.cycles[l][b], N = fatigue::cycles_to_failure(c, sigma);
              const std::string load = m.stress.size() > 1 ? m.detail + " #" + std::to_string(l + 1) : m.detail;
              s << m.stage << "," << m.member << "," << m.mode << ",\"" << load << "\"," << b + 1 << ","
                << num(in.spectrum.torques[b], f, "torque") << "," << num(sigma / 1e6, f, "stress", 10) << ","
                << num(n, f, "cycles", 10) << "," << (std::isinf(N) ? "" : num(N, f, "N", 10)) << ","
                << num(std::isinf(N) ? 0.0 : n / N, f, "n/N", 10) << ","
                << (c.kind == fatigue::SNCurve::Kind::iso ? 1 : 0) << "," << num(c.sigma_n / 1e6, f, "sigma_n") << ","
                << num(c.N_ref, f, "N_ref") << "," << num(c.B / 1e6, f, "B") << "," << num(c.N_static, f, "N_static")
                << "," << num(c.Y_static, f, "Y_static") << "\n";
            }
      }
    write_file_atomically(file, s.str());
  }

  GearboxTables gearbox_tables(const GearboxInput &in, const GearboxResult &r)
  {
    GearboxTables t;
    for (const auto &[n, u] : std::vector<std::pair<const char *, const char *>>{
           {"input torque", "N m"}, {"F_t", "N"}, {"sigma_H", "MPa"}, {"sigma_F1", "MPa"}, {"sigma_F2", "MPa"},
           {"ISO sigma_H1", "MPa"}, {"ISO sigma_H2", "MPa"}, {"theta_fl_max", "K"}, {"theta_B_max", "C"},
           {"h_c_min", "um"}, {"lambda_min", "-"}, {"P_scuffing", "-"}, {"ISO sigma_F1", "MPa"},
           {"ISO sigma_F2", "MPa"}})
      t.meshes.add_column(n, u);
    for (std::size_t k = 0; k < r.train.stages.size(); ++k)
      {
        const Stage &st = r.train.stages[k];
        for (std::size_t j = 0; j < st.meshes.size(); ++j)
          for (std::size_t b = 0; b < in.spectrum.torques.size(); ++b)
            {
              const MeshStress &m       = r.stress[k][j][b];
              const scuffing::Result &c = r.scuff[k][j][b];
              const double T            = in.spectrum.torques[b];
              t.meshes.add_row({T, st.tangential_load(r.train.torques(T)[k]), m.sigma_H / 1e6, m.sigma_F1 / 1e6,
                                m.sigma_F2 / 1e6, m.sigma_H1_iso / 1e6, m.sigma_H2_iso / 1e6, c.theta_fl_max,
                                c.theta_B_max, c.h_c_min * 1e6, c.lambda_min, c.P, m.sigma_F1_iso / 1e6,
                                m.sigma_F2_iso / 1e6});
              t.mesh_stage.push_back(st.in.name);
              t.mesh_name.push_back(st.meshes[j].name);
            }
      }
    t.lives.add_column("cycles per input revolution", "-");
    t.lives.add_column("damage D", "-");
    t.lives.add_column("damaged", "-");
    t.lives.add_column("life", "spectra");
    t.lives.add_column("life", "years");
    for (const MemberLife &m : r.lives)
      {
        const bool damaged = m.damage.D > 0.0 && std::isfinite(m.damage.life_spectra);
        t.lives.add_row({m.cycles_per_revolution, m.damage.D, damaged ? 1.0 : 0.0,
                         damaged ? m.damage.life_spectra : 0.0,
                         damaged && std::isfinite(m.life_years) ? m.life_years : 0.0});
        t.life_stage.push_back(m.stage);
        t.life_member.push_back(m.member);
        t.life_mode.push_back(m.mode);
        t.life_load.push_back(m.detail);
      }
    return t;
  }
} // namespace gearfem::gearbox
