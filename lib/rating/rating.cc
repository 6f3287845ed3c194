#include "rating/rating.h"

#include "geometry/limits.h"
#include "base/units.h"

#include "analytical/from_geometry.h"
#include "rating/iso6336.h"
#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/number.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::rating
{
  using namespace analytical; // the compliance models and the geometry bridge

  namespace
  {
    using units::pi;


    void check_factor(const std::string &name, double v)
    {
      require_greater("Rating/" + name, v, 0.0);
    }
  } // namespace

  void RatingReport::add(const std::string &what, const std::string &standard, const std::string &quantity,
                         const std::string &symbol, const std::string &clause, const std::string &unit,
                         std::vector<double> v)
  {
    for (double x : v)
      if (!std::isfinite(x))
        throw SolverError(what + ": " + standard + " " + symbol + " is not finite");
    rows.push_back({standard, quantity, symbol, clause, unit, std::move(v)});
  }

  const RatingRow &RatingReport::row(const std::string &standard, const std::string &symbol) const
  {
    for (const auto &r : rows)
      if (r.standard == standard && r.symbol == symbol)
        return r;
    throw InputError("rating report: no row " + standard + " " + symbol);
  }

  namespace
  {
    /// The pair quantities both standards start from (SI units).
    struct RatingContext
    {
      const geometry::GearPair &pair;
      const RatingInput &in;
      const geometry::ToothProfile &p1, &p2;
      const geometry::GearParameters &g1, &g2;
      int z1, z2;
      double m, alpha, b, a, u, dw1, d1, ra1, ra2, eps;

      RatingContext(const geometry::GearPair &pr, const RatingInput &input)
        : pair(pr), in(input), p1(pr.gear(1)), p2(pr.gear(2)), g1(p1.parameters()), g2(p2.parameters())
      {
        z1 = g1.teeth, z2 = g2.teeth;
        m = g1.rack.module, alpha = g1.rack.pressure_angle;
        b = std::min(g1.face_width, g2.face_width);
        require_greater("Gear 1/Face width", b, 0.0, "m");
        a = pair.center_distance(), u = double(z2) / z1;
        dw1 = 2.0 * a / (u + 1.0), d1 = m * z1;
        ra1 = p1.radii().tip, ra2 = p2.radii().tip;
        eps = pair.contact_ratio();
      }
      /// f(T) for every pinion torque T.
      template <typename F>
      std::vector<double> per_torque(F f) const
      {
        std::vector<double> v(in.torques.size());
        for (std::size_t i = 0; i < v.size(); ++i)
          v[i] = f(in.torques[i]);
        return v;
      }
    };

    void check_rating_input(const RatingInput &in)
    {
      if (in.torques.empty())
        throw InputError("Rating/Pinion torques", "(empty)", "one or more values > 0 N m");
      for (double T : in.torques)
        require_greater("Rating/Pinion torques", T, 0.0, "N m");
      for (auto f : {std::pair<const char *, double>{"K_o", in.K_o}, {"K_v", in.K_v}, {"K_s", in.K_s},
                     {"Z_R", in.Z_R}, {"K_B", in.K_B}, {"K_A", in.K_A}, {"ISO K_v", in.K_v_iso},
                     {"ISO K_Hbeta", in.K_Hbeta}})
        check_factor(f.first, f.second);
      if (in.K_H < 0.0)
        throw InputError("Rating/AGMA K_H", to_string_g(in.K_H), "0 (computed) or >= 1");
    }

    /// AGMA 2101-D04 / 908-B89 rows (Siasos 2010 chapter 4).
    void add_agma_rows(const RatingContext &c, RatingReport &rep)
    {
      const RatingInput &in = c.in;
      const geometry::GearPair &pair = c.pair;
      const geometry::GearParameters &g1 = c.g1, &g2 = c.g2;
      const int z1 = c.z1, z2 = c.z2;
      const double m = c.m, alpha = c.alpha, b = c.b, a = c.a, dw1 = c.dw1, ra1 = c.ra1, ra2 = c.ra2;
      auto per_torque = [&c](auto f) { return c.per_torque(f); };
      RowBuilder B{rep, "AGMA"};
      const agma::LineOfAction l = agma::line_of_action(z1, z2, m, alpha, ra1, ra2, a);
      const double ZI = agma::geometry_factor_I(l);
      const double ZE = agma::Z_E(in.E1, in.nu1, in.E2, in.nu2);
      const double Kma = agma::K_Hma(b, in.enclosure), Kpf = agma::K_Hpf(b, dw1);
      const double KH = in.K_H > 0.0 ? in.K_H : 1.0 + Kma + Kpf;
      agma::Tool tool = in.tool;
      B.constant("operating pitch diameter", "d_w1", "2101-D04 (Siasos 2010 eq. 4.1-1)", "mm", dw1 * 1e3);
      B.constant("net face width", "b", "2101-D04", "mm", b * 1e3);
      B.constant("pitch-line velocity (from Rating/Pinion speed)", "v_t", "2101-D04", "m/s",
                 in.speed * 2.0 * pi / 60.0 * 0.5 * dw1);
      B.add("transmitted tangential load 2T/d_w1", "F_t", "2101-D04", "N",
            per_torque([&](double T) { return 2 * T / dw1; }));
      B.constant("elastic coefficient", "Z_E", "2101-D04 (Siasos 2010 eq. 4.1-2)", "sqrt(MPa)", ZE / 1e3);
      B.constant("overload factor", "K_o", "2101-D04 (input)", "-", in.K_o);
      B.constant("dynamic factor", "K_v", "2101-D04 (input; Siasos 2010 sec. 4.1.4)", "-", in.K_v);
      B.constant("size factor", "K_s", "2101-D04 (input)", "-", in.K_s);
      B.constant(std::string("mesh alignment factor (") + agma::to_string(in.enclosure) + ")", "K_Hma",
                 "2101-D04 (Siasos 2010 eq. 4.1.6-4)", "-", Kma);
      B.constant("pinion proportion factor", "K_Hpf", "2101-D04 (Siasos 2010 eqs. 4.1.6-5..7)", "-", Kpf);
      B.constant(in.K_H > 0 ? "load distribution factor (input)" : "load distribution factor 1 + K_Hma + K_Hpf",
                 "K_H", "2101-D04 (Siasos 2010 eq. 4.1.6-3)", "-", KH);
      B.constant("surface condition factor", "Z_R", "2101-D04 (input)", "-", in.Z_R);
      B.constant("rim thickness factor", "K_B", "2101-D04 (input)", "-", in.K_B);
      B.constant("LPSTC distance from T1 (unit module)", "C2", "908-B89 (Siasos 2010 eq. 4.3-17)", "-", l.C2);
      B.constant("pitch point (unit module)", "C3", "908-B89 (Siasos 2010 eq. 4.3-14)", "-", l.C3);
      B.constant("HPSTC distance from T1 (unit module)", "C4", "908-B89 (Siasos 2010 eq. 4.3-15)", "-", l.C4);
      B.constant("transverse contact ratio", "m_p", "908-B89 (Siasos 2010 eq. 4.3-19)", "-", l.contact_ratio);
      B.constant("pitting geometry factor", "Z_I", "908-B89 (Siasos 2010 eq. 4.3.1-1)", "-", ZI);
      B.add("contact stress", "sigma_H", "2101-D04 (Siasos 2010 eq. 4.1-1)", "MPa", per_torque([&](double T) {
              const double Ft = 2 * T / dw1;
              return ZE * std::sqrt(Ft * in.K_o * in.K_v * in.K_s * KH / (dw1 * b) * in.Z_R / ZI) / 1e6;
            }));
      for (int i : {1, 2})
        {
          const geometry::GearParameters &g = i == 1 ? g1 : g2;
          const std::string s = std::to_string(i);
          tool.h_ao = g.rack.dedendum;
          tool.rho_ao = g.rack.root_radius;
          const double tanW = i == 1 ? l.C4 / l.Rb1 : (l.C6 - l.C2) / l.Rb2;
          const agma::BendingGeometry J = agma::geometry_factor_J(g.teeth, g.profile_shift, tanW, alpha, l.phi_r, tool);
          // The same construction on the generated fillet (cross-check).
          const agma::LewisSection ls = agma::lewis_section(fillet_curve(pair.gear(i)), J.r_nL * m);
          agma::BendingGeometry Jg = J;
          Jg.s_F = ls.s_F / m, Jg.h_F = ls.h_F / m, Jg.rho_F = ls.rho_F / m;
          agma::form_and_stress_factors(Jg, alpha, l.phi_r);
          B.constant("load angle at the HPSTC", "phi_nL" + s, "908-B89 (Siasos 2010 eq. 4.3.2-8)", "deg", J.phi_nL / pi * 180);
          B.constant("Newton iterations from alpha_n = pi/4", "iter" + s, "908-B89 (Siasos 2010 eq. 4.3.2-38)", "-", J.iterations);
          B.constant("critical section thickness", "s_F" + s, "908-B89 (Siasos 2010 eq. 4.3.2-35)", "mm", J.s_F * m * 1e3);
          B.constant("Lewis parabola height", "h_F" + s, "908-B89 (Siasos 2010 eq. 4.3.2-37)", "mm", J.h_F * m * 1e3);
          B.constant("minimum fillet radius", "rho_F" + s, "908-B89 (Siasos 2010 eq. 4.3.2-40)", "mm", J.rho_F * m * 1e3);
          B.constant("stress correction factor", "K_f" + s, "908-B89 (Siasos 2010 eq. 4.3.2-44)", "-", J.K_f);
          B.constant("tooth form factor", "Y" + s, "908-B89 (Siasos 2010 eq. 4.3.2-46)", "-", J.Y);
          B.constant("bending geometry factor", "Y_J" + s, "908-B89 (Siasos 2010 eq. 4.3.2-1)", "-", J.Y_J);
          B.constant("Y_J from the generated fillet (check)", "Y_J" + s + ",gen", "908-B89 on lib/geometry fillet", "-", Jg.Y_J);
          B.add("bending stress at the HPSTC", "sigma_F" + s, "2101-D04 (Siasos 2010 eq. 4.2-1)", "MPa",
                per_torque([&](double T) {
                  return 2 * T / dw1 * in.K_o * in.K_v * in.K_s * KH * in.K_B / (b * m * J.Y_J) / 1e6;
                }));
        }
    }

    /// ISO 6336-1/2/3 rows (method B).
    void add_iso6336_rows(const RatingContext &c, RatingReport &rep)
    {
      const RatingInput &in = c.in;
      const geometry::GearPair &pair = c.pair;
      const geometry::GearParameters &g1 = c.g1, &g2 = c.g2;
      const int z1 = c.z1, z2 = c.z2;
      const double m = c.m, alpha = c.alpha, b = c.b, d1 = c.d1, ra1 = c.ra1, ra2 = c.ra2, eps = c.eps;
      auto per_torque = [&c](auto f) { return c.per_torque(f); };
      RowBuilder B{rep, "ISO 6336"};
      const double db1 = 2 * pair.base_radius(1), db2 = 2 * pair.base_radius(2);
      iso6336::StiffnessInput si;
      si.z1 = z1;
      si.z2 = z2;
      si.x1 = g1.profile_shift;
      si.x2 = g2.profile_shift;
      si.alpha_n = alpha;
      si.module = m;
      si.h_fP1 = g1.rack.dedendum;
      si.h_fP2 = g2.rack.dedendum;
      si.eps_alpha = eps;
      const iso6336::Stiffness st = iso6336::mesh_stiffness(si);
      B.constant("reference diameter of the pinion", "d_1", "6336-1", "mm", d1 * 1e3);
      B.add("nominal tangential load 2T/d_1", "F_t", "6336-1 eq. 1", "N", per_torque([&](double T) { return 2 * T / d1; }));
      B.constant("transverse contact ratio", "eps_alpha", "6336-1 (lib/geometry)", "-", eps);
      B.constant("single stiffness (theoretical) 1/q'", "c'_th", "6336-1 eq. 71", "N/(mm um)", st.c_th);
      B.constant("single stiffness", "c'", "6336-1 eq. 69 (C_M 0.8, C_R, C_B)", "N/(mm um)", st.c_prime);
      B.constant("mesh stiffness", "c_gamma_alpha", "6336-1 eq. 75", "N/(mm um)", st.c_gamma_alpha);
      B.constant("application factor", "K_A", "6336-1 (input)", "-", in.K_A);
      B.constant("dynamic factor", "K_v", "6336-1 (input)", "-", in.K_v_iso);
      B.constant("face load factor (contact)", "K_Hbeta", "6336-1 (input)", "-", in.K_Hbeta);
      const double h = (g1.rack.addendum + g1.rack.dedendum) * m;
      const double bh = std::max(3.0, b / h);
      const double NF = bh * bh / (1 + bh + bh * bh);
      const double KFb = std::pow(in.K_Hbeta, NF);
      B.constant("face load factor (root) K_Hbeta^N_F", "K_Fbeta", "6336-1 eq. 41", "-", KFb);

      iso6336::ContactInput ci;
      ci.z1 = z1;
      ci.z2 = z2;
      ci.alpha_t = alpha;
      ci.alpha_wt = pair.working_pressure_angle();
      ci.d1 = d1;
      ci.da1 = 2 * ra1;
      ci.da2 = 2 * ra2;
      ci.db1 = db1;
      ci.db2 = db2;
      ci.b = b;
      ci.E1 = in.E1, ci.nu1 = in.nu1, ci.E2 = in.E2, ci.nu2 = in.nu2;
      ci.eps_alpha = eps;
      ci.K_A = in.K_A, ci.K_v = in.K_v_iso, ci.K_Hbeta = in.K_Hbeta;
      // Transverse load factor (method B, 6336-1 eq. 73-74) from the accuracy grade.
      const double Yeps = iso6336::Y_eps(eps);
      auto K_alpha = [&](double T, double Zeps, bool root) {
        if (in.accuracy_grade <= 0)
          return 1.0;
        const double dmm = std::max(d1, m * z2) * 1e3, mm = m * 1e3;
        const double fpt5 = 0.3 * (mm + 0.4 * std::sqrt(dmm)) + 4.0; // ISO 1328-1 grade 5 [um]
        const double fpb = fpt5 * std::pow(2.0, 0.5 * (in.accuracy_grade - 5));
        const double ya = in.case_hardened ? std::min(3.0, 0.075 * fpb) : 160.0 / (in.sigma_Hlim / 1e6) * fpb;
        const double FtH_b = 2 * T / d1 * in.K_A * in.K_v_iso * in.K_Hbeta / (b * 1e3); // N/mm
        double K = eps / 2 * (0.9 + 0.4 * st.c_gamma_alpha * (fpb - ya) / FtH_b);
        const double Kmax = root ? eps / (eps * Yeps) : eps / (eps * Zeps * Zeps);
        return std::max(1.0, std::min(K, Kmax));
      };
      const iso6336::ContactFactors cf0 = iso6336::contact_stress([&] { auto c = ci; c.Ft = 1.0; return c; }());
      B.constant("zone factor", "Z_H", "6336-2 eq. 10", "-", cf0.Z_H);
      B.constant("elasticity factor", "Z_E", "6336-2 eq. 11", "sqrt(MPa)", cf0.Z_E / 1e3);
      B.constant("contact ratio factor", "Z_eps", "6336-2 eq. 19", "-", cf0.Z_eps);
      B.constant("helix angle factor", "Z_beta", "6336-2 eq. 23", "-", cf0.Z_beta);
      B.constant("single pair contact factor (pinion)", "Z_B", "6336-2 eqs. 12, 14", "-", cf0.Z_B);
      B.constant("single pair contact factor (wheel)", "Z_D", "6336-2 eqs. 13, 15", "-", cf0.Z_D);
      B.add("transverse load factor", "K_Halpha", "6336-1 eq. 73 (grade " + std::to_string(in.accuracy_grade) + ")", "-",
            per_torque([&](double T) { return K_alpha(T, cf0.Z_eps, false); }));
      auto sigmaH = [&](double T, int which) {
        auto c = ci;
        c.Ft = 2 * T / d1;
        c.K_Halpha = K_alpha(T, cf0.Z_eps, false);
        const auto f = iso6336::contact_stress(c);
        return (which == 0 ? f.sigma_H0 : which == 1 ? f.sigma_H1 : f.sigma_H2) / 1e6;
      };
      B.add("nominal contact stress", "sigma_H0", "6336-2 eq. 2", "MPa", per_torque([&](double T) { return sigmaH(T, 0); }));
      B.add("contact stress, pinion", "sigma_H1", "6336-2 eq. 1", "MPa", per_torque([&](double T) { return sigmaH(T, 1); }));
      B.add("contact stress, wheel", "sigma_H2", "6336-2 eq. 1", "MPa", per_torque([&](double T) { return sigmaH(T, 2); }));

      B.constant("contact ratio factor (tip load)", "Y_eps", "6336-3 eq. 47", "-", Yeps);
      B.constant("helix angle factor", "Y_beta", "6336-3 eq. 48", "-", iso6336::Y_beta(0, 0));
      B.add("transverse load factor (root)", "K_Falpha", "6336-1 eq. 73", "-",
            per_torque([&](double T) { return K_alpha(T, cf0.Z_eps, true); }));
      for (int i : {1, 2})
        {
          const std::string s = std::to_string(i);
          const geometry::ToothProfile &p = pair.gear(i);
          const iso6336::CriticalSection cs = iso6336::critical_section(fillet_curve(p));
          const InvoluteTooth t = involute_tooth(p, 0.0, 5);
          const iso6336::InvoluteFlank fl{t.rb, t.psi_b};
          // Outer point of single contact: D on the pinion, B on the wheel.
          const double r_e = i == 1 ? pair.point("D").r1 : pair.point("B").r2;
          const iso6336::RootFactors rf = iso6336::root_factors(cs, fl, r_e, m, alpha);
          const iso6336::RootFactors ra = iso6336::root_factors(cs, fl, p.radii().tip, m, alpha);
          B.constant("critical section chord (30 deg tangent)", "s_Fn" + s, "6336-3 6.2 (generated fillet)", "mm", cs.s_Fn * 1e3);
          B.constant("fillet radius at the critical section", "rho_F" + s, "6336-3 6.2 (generated fillet)", "mm", cs.rho_F * 1e3);
          B.constant("bending moment arm, outer single contact", "h_Fe" + s, "6336-3 6.2", "mm", rf.h_Fe * 1e3);
          B.constant("load direction angle", "alpha_Fen" + s, "6336-3 6.2", "deg", rf.alpha_Fen / pi * 180);
          B.constant("form factor", "Y_F" + s, "6336-3 eq. 24", "-", rf.Y_F);
          B.constant("stress correction factor", "Y_S" + s, "6336-3 eq. 43", "-", rf.Y_S);
          B.constant("form factor, tip load", "Y_Fa" + s, "6336-3 eq. 24 (d_en = d_a)", "-", ra.Y_F);
          B.constant("stress correction factor, tip load", "Y_Sa" + s, "6336-3 eq. 43 (d_en = d_a)", "-", ra.Y_S);
          B.add("nominal root stress (method B)", "sigma_F0" + s, "6336-3 eq. 3", "MPa",
                per_torque([&](double T) { return 2 * T / d1 / (b * m) * rf.Y_F * rf.Y_S / 1e6; }));
          B.add("root stress", "sigma_F" + s, "6336-3 eq. 2", "MPa", per_torque([&](double T) {
                  return 2 * T / d1 / (b * m) * rf.Y_F * rf.Y_S * in.K_A * in.K_v_iso * KFb *
                         K_alpha(T, cf0.Z_eps, true) / 1e6;
                }));
          B.add("nominal root stress, tip load with Y_eps", "sigma_F0a" + s, "6336-3:1996 method C", "MPa",
                per_torque([&](double T) { return 2 * T / d1 / (b * m) * ra.Y_F * ra.Y_S * Yeps / 1e6; }));
        }
    }
  } // namespace

  RatingReport rate(const geometry::GearPair &pair, const RatingInput &in)
  {
    check_rating_input(in);
    const RatingContext c(pair, in);
    {
      // The small-strain bound of the contact models (plane strain E' = E / (1 - nu^2)).
      const double Es = 1.0 / ((1 - in.nu1 * in.nu1) / in.E1 + (1 - in.nu2 * in.nu2) / in.E2);
      for (const double T : in.torques)
        geometry::limits::check_small_strain("Rating/Pinion torques", T, pair.base_radius(1), c.b, Es,
                                             pair.equivalent_curvature(0.0));
    }
    RatingReport rep;
    rep.torques = in.torques;
    add_agma_rows(c, rep);
    add_iso6336_rows(c, rep);
    return rep;
  }

  void RatingReport::write_markdown(const std::filesystem::path &file, const std::string &title) const
  {
    std::ostringstream s;
    s << "# " << title << "\n\n"
      << "Every factor with its clause (standard clause; Siasos 2010: the equation "
         "numbers of its chapter 4), value and unit. One column per pinion torque.\n";
    std::string current;
    for (const auto &r : rows)
      {
        if (r.standard != current)
          {
            current = r.standard;
            s << "\n## " << current << "\n\n| quantity | symbol | clause | unit |";
            for (double T : torques)
              s << " T = " << T << " N m |";
            s << "\n|---|---|---|---|";
            for (std::size_t i = 0; i < torques.size(); ++i)
              s << "---|";
            s << "\n";
          }
        s << "| " << r.quantity << " | " << r.symbol << " | " << r.clause << " | " << r.unit << " |";
        for (double v : r.values)
          {
            require_finite_output(v, file.string(), "row '" + r.quantity + "'");
            s << " " << std::setprecision(6) << v << " |";
          }
        s << "\n";
      }
    write_file_atomically(file, s.str());
  }

  void RatingReport::write_csv(const std::filesystem::path &file) const
  {
    std::ostringstream s;
    auto q = [](const std::string &x) { return "\"" + x + "\""; };
    s << "standard,quantity,symbol,clause,unit";
    for (double T : torques)
      s << "," << q("T = " + to_string_g(T) + " [N m]");
    s << "\n";
    for (const auto &r : rows)
      {
        s << q(r.standard) << "," << q(r.quantity) << "," << q(r.symbol) << "," << q(r.clause) << ","
          << q(r.unit);
        for (double v : r.values)
          {
            require_finite_output(v, file.string(), "row '" + r.quantity + "'");
            s << "," << std::setprecision(10) << v;
          }
        s << "\n";
      }
    write_file_atomically(file, s.str());
  }
} // namespace gearfem::rating
