#include "rating/internal.h"

#include "analytical/from_geometry.h"
#include "base/errors.h"
#include "base/units.h"
#include "geometry/limits.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace gearfem::rating
{
  namespace
  {
    using units::pi;
    constexpr double deg = pi / 180.0;
    double inv(double a) { return std::tan(a) - a; }
  } // namespace

  // ------------------------------------------------------------------ ISO 6336-3 pieces

  namespace iso6336
  {
    double Y_B_external(double s_R, double h_t)
    {
      require_greater("tooth depth h_t", h_t, 0.0, "m");
      const double r = s_R / h_t;
      if (!(r > 0.5))
        throw InputError("rim thickness ratio s_R/h_t", to_string_g(r), "> 0.5 (ISO 6336-3 clause 8)");
      return r >= 1.2 ? 1.0 : 1.6 * std::log(2.242 / r);
    }

    double Y_B_internal(double s_R, double m_n)
    {
      require_greater("module m_n", m_n, 0.0, "m");
      const double r = s_R / m_n;
      if (!(r > 1.75))
        throw InputError("rim thickness ratio s_R/m_n of an internal gear", to_string_g(r),
                         "> 1.75 (ISO 6336-3 clause 8)");
      return r >= 3.5 ? 1.0 : 1.15 * std::log(8.324 / r);
    }

    InternalSection internal_gear_section(int z2, double m, double an, double x2, double h_fP, double rho_fP,
                                          double s_pr)
    {
      require_greater("internal gear teeth", z2, 4);
      require_greater("module", m, 0.0, "m");
      require_greater("cutter tip radius coefficient rho_a0*", rho_fP, 0.0);
      InternalSection s;
      const double zn = -double(z2);
      s.E = pi / 4.0 - h_fP * std::tan(an) + s_pr / m / std::cos(an) - (1.0 - std::sin(an)) * rho_fP / std::cos(an);
      s.G = rho_fP - h_fP + x2;
      s.H = 2.0 / zn * (pi / 2.0 - s.E) - pi / 6.0;
      // theta = 2G/zn tan(theta) - H, iterated from pi/6 as the standard prescribes (a
      // contraction: |2G/(zn cos^2 theta)| << 1; Newton on the whole of (-pi/2, pi/2) can
      // reach the other two roots of the equation, near -pi/2 and +pi/2).
      double th = pi / 6.0;
      bool converged = false;
      for (int it = 0; it < 200 && !converged; ++it)
        {
          const double next = 2.0 * s.G / zn * std::tan(th) - s.H;
          converged = std::abs(next - th) < 1e-15;
          th = next;
          if (!(std::abs(th) < 0.5 * pi))
            break;
        }
      if (!converged)
        throw SolverError("ISO 6336-3 theta equation (internal gear, " + std::to_string(z2) +
                          " teeth): the iteration from pi/6 does not converge");
      s.theta = th;
      const double d = s.G / std::cos(s.theta) - rho_fP; // offset of the section point, module units
      s.s_Fn = m * (zn * std::sin(pi / 6.0 - s.theta) + d);
      s.y = -m * (0.5 * zn * std::cos(pi / 6.0 - s.theta) + d * std::sin(pi / 3.0));
      s.rho_F = rho_fP * m;
      if (!(s.s_Fn > 0.0 && s.y > 0.0))
        throw InputError("internal gear basic rack (h_fP*, rho_fP*, x2)",
                         to_string_g(h_fP) + ", " + to_string_g(rho_fP) + ", " + to_string_g(x2),
                         "a ring tooth with a root chord", "ISO 6336-3 closed form gives s_Fn = " + mm_text(s.s_Fn));
      return s;
    }

    RootFactors internal_root_factors(double s_Fn, double y, double rho_F, const InvoluteFlank &fl, double r_e,
                                      double m, double an)
    {
      if (!(r_e > fl.rb))
        throw InputError("ISO 6336-3 load radius (internal gear)", mm_text(r_e), "> base radius " + mm_text(fl.rb));
      const double a_en = std::acos(fl.rb / r_e);
      const double gamma_e = fl.psi_b + inv(a_en);
      RootFactors f;
      f.alpha_Fen = a_en + gamma_e;
      f.s_Fn = s_Fn;
      f.rho_F = rho_F;
      f.h_Fe = y - fl.rb / std::cos(f.alpha_Fen);
      if (!(f.h_Fe > 0.0))
        throw SolverError("ISO 6336-3 (internal gear): the load line meets the tooth axis beyond the critical "
                          "section (h_Fe = " + mm_text(f.h_Fe) + ")");
      const double sm = s_Fn / m, hm = f.h_Fe / m;
      f.Y_F = 6.0 * hm * std::cos(f.alpha_Fen) / (sm * sm * std::cos(an));
      f.L = s_Fn / f.h_Fe;
      f.q_s = s_Fn / (2.0 * rho_F);
      f.Y_S = (1.2 + 0.13 * f.L) * std::pow(f.q_s, 1.0 / (1.21 + 2.3 / f.L));
      return f;
    }
  } // namespace iso6336

  // ------------------------------------------------------------------ the rating

  namespace
  {

    const geometry::ProfileSegment &drive_segment(const geometry::InternalToothProfile &ring,
                                                  geometry::SegmentType type)
    {
      for (const geometry::ProfileSegment &s : ring.segments())
        if (s.type == type && s.side == geometry::Side::drive)
          return s;
      throw InputError(ring.parameters().name + "/Cutter tip radius coefficient",
                       to_string_g(ring.parameters().cutter.tip_radius), "> 0",
                       std::string("the ring outline has no drive ") + geometry::to_string(type));
    }

    /// The drive (x > 0) side of ring tooth 0 as a PlaneCurve: the fillet (t in [0, 1], from
    /// the root), followed by the involute flank (t in [1, 2], to the tip) when with_flank.
    /// flip: y -> -y (the tooth then points to +y with its root below, the frame of the
    /// external constructions).
    analytical::PlaneCurve ring_side(const geometry::InternalToothProfile &ring, bool with_flank, bool flip)
    {
      std::vector<const geometry::ProfileSegment *> parts{&drive_segment(ring, geometry::SegmentType::fillet)};
      if (with_flank)
        parts.push_back(&drive_segment(ring, geometry::SegmentType::flank));
      // Piece k runs from its root end to its tip end as t goes from k to k + 1.
      const auto eval = [parts](double t, int n) {
        const int k = std::clamp(int(std::floor(t)), 0, int(parts.size()) - 1);
        const geometry::ProfileSegment &s = *parts[k];
        const double a = s.t0, b = s.t1; // fillet: root -> form; flank: form -> tip
        const double u = a + (t - k) * (b - a), du = b - a;
        return n == 0 ? geometry::Vec2(s.curve->point(u)) : n == 1 ? geometry::Vec2(du * s.curve->d1(u)) : geometry::Vec2(du * du * s.curve->d2(u));
      };
      const double sy = flip ? -1.0 : 1.0;
      analytical::PlaneCurve p;
      p.x = [eval](double t, int n) { return eval(t, n).x(); };
      p.y = [eval, sy](double t, int n) { return sy * eval(t, n).y(); };
      p.t0 = 0.0, p.t1 = double(parts.size());
      return p;
    }

    /// Everything both standards start from (SI).
    struct Context
    {
      const geometry::ToothProfile &p1;
      const geometry::InternalToothProfile &p2;
      const geometry::InternalMesh &mesh;
      const InternalRatingInput &in;
      const RatingInput &r;
      int z1, z2;
      double m, alpha, b, d1, x1, x2, ht1, ht2, rf2, r2;
      std::vector<double> per_torque(const std::function<double(double)> &f) const
      {
        std::vector<double> v;
        for (double T : r.torques)
          v.push_back(f(T));
        return v;
      }
    };

    void check_input(const Context &c)
    {
      const RatingInput &r = c.r;
      if (r.torques.empty())
        throw InputError("Rating/Pinion torques", "(empty)", "one or more values > 0 N m");
      for (double T : r.torques)
        require_greater("Rating/Pinion torques", T, 0.0, "N m");
      for (auto f : {std::pair<const char *, double>{"AGMA overload factor", r.K_o}, {"AGMA dynamic factor", r.K_v},
                     {"AGMA size factor", r.K_s}, {"AGMA surface condition factor", r.Z_R},
                     {"Application factor", r.K_A}, {"ISO dynamic factor", r.K_v_iso},
                     {"ISO face load factor", r.K_Hbeta}})
        require_greater(std::string("Rating/") + f.first, f.second, 0.0);
      if (r.K_H < 0.0)
        throw InputError("Rating/AGMA load distribution factor", to_string_g(r.K_H), "0 (computed) or >= 1");
      if (r.K_B != 1.0)
        throw InputError("Rating/AGMA rim thickness factor", to_string_g(r.K_B), "1",
                         "an internal pair's K_B comes from the pinion and ring rim thicknesses");
      if (r.accuracy_grade != 0)
        throw InputError("Rating/ISO accuracy grade", std::to_string(r.accuracy_grade), "0",
                         "internal pairs are rated with K_Halpha = K_Falpha = 1");
      const geometry::InternalMeshInput &mi = c.mesh.in;
      const std::string R = c.p2.parameters().name + "/";
      if (mi.z1 != c.z1)
        throw InputError("Internal mesh/Pinion teeth", std::to_string(mi.z1), std::to_string(c.z1) + " (the pinion's)");
      if (mi.z2 != c.z2)
        throw InputError("Internal mesh/Ring teeth", std::to_string(mi.z2), std::to_string(c.z2) + " (the ring's)");
      for (double v : {mi.module, c.p2.parameters().module})
        if (std::abs(v - c.m) > 1e-12 * c.m)
          throw InputError(R + "Module", mm_text(v), mm_text(c.m) + " (the pinion's)");
      const double sR1 = c.in.pinion_rim_thickness, sR2 = c.in.ring_rim_thickness;
      if (sR1 != 0.0 && !(sR1 > 0.5 * c.ht1))
        throw InputError("Rating/Pinion rim thickness", mm_text(sR1), "0 (solid) or > 0.5 h_t = " + mm_text(0.5 * c.ht1),
                         "ISO 6336-3 Y_B (s_R/h_t > 0.5) and AGMA 2101-D04 K_B (m_B >= 0.5)");
      const double lo2 = std::max(1.75 * c.m, 0.5 * c.ht2);
      if (sR2 != 0.0 && !(sR2 > lo2))
        throw InputError("Rating/Ring rim thickness", mm_text(sR2), "0 (not given) or > " + mm_text(lo2),
                         "ISO 6336-3 Y_B of internal gears (s_R/m_n > 1.75) and AGMA 2101-D04 K_B (m_B >= 0.5)");
    }

    /// ISO 6336-1/-2 rows: load, factors and the contact stress.
    void add_iso_contact(const Context &c, RatingReport &rep, double KFb)
    {
      const RatingInput &in = c.r;
      RowBuilder B{rep, "ISO 6336", "internal rating"};
      const geometry::InternalMesh &mesh = c.mesh;
      iso6336::ContactInput ci;
      ci.z1 = c.z1, ci.z2 = -c.z2;
      ci.alpha_t = c.alpha, ci.alpha_wt = mesh.alpha_w;
      ci.d1 = c.d1;
      ci.da1 = 2 * mesh.in.tip_radius1, ci.da2 = -2 * mesh.in.tip_radius2;
      ci.db1 = 2 * mesh.rb1, ci.db2 = -2 * mesh.rb2;
      ci.b = c.b;
      ci.E1 = in.E1, ci.nu1 = in.nu1, ci.E2 = in.E2, ci.nu2 = in.nu2;
      ci.eps_alpha = mesh.contact_ratio;
      ci.K_A = in.K_A, ci.K_v = in.K_v_iso, ci.K_Hbeta = in.K_Hbeta;
      ci.Ft = 1.0;
      iso6336::ContactFactors f = iso6336::contact_stress(ci);
      f.Z_D = 1.0; // ISO 6336-2: Z_D = 1 for internal gears
      B.constant("reference diameter of the pinion", "d_1", "6336-1", "mm", c.d1 * 1e3);
      B.constant("gear ratio z2/z1 (internal gear: z2 < 0)", "u", "6336-1", "-", -double(c.z2) / c.z1);
      B.constant("working transverse pressure angle", "alpha_wt", "6336-2 (lib/geometry internal mesh)", "deg",
                 mesh.alpha_w / deg);
      B.add("nominal tangential load 2T/d_1", "F_t", "6336-1 eq. 1", "N",
            c.per_torque([&](double T) { return 2 * T / c.d1; }));
      B.constant("transverse contact ratio", "eps_alpha", "6336-1 (lib/geometry internal mesh)", "-",
                 mesh.contact_ratio);
      B.constant("application factor", "K_A", "6336-1 (input)", "-", in.K_A);
      B.constant("dynamic factor", "K_v", "6336-1 (input)", "-", in.K_v_iso);
      B.constant("face load factor (contact)", "K_Hbeta", "6336-1 (input)", "-", in.K_Hbeta);
      B.constant("face load factor (root) K_Hbeta^N_F", "K_Fbeta", "6336-1 eq. 41", "-", KFb);
      B.constant("transverse load factors (grade 0)", "K_Halpha", "6336-1 (K_Halpha = K_Falpha = 1)", "-", 1.0);
      B.constant("zone factor", "Z_H", "6336-2 eq. 10 (alpha_wt of the internal mesh)", "-", f.Z_H);
      B.constant("elasticity factor", "Z_E", "6336-2 eq. 11", "sqrt(MPa)", f.Z_E / 1e3);
      B.constant("contact ratio factor", "Z_eps", "6336-2 eq. 19", "-", f.Z_eps);
      B.constant("helix angle factor", "Z_beta", "6336-2 eq. 23", "-", f.Z_beta);
      B.constant("M1 with z2, d_a2, d_b2 < 0", "M_1", "6336-2 eq. 12", "-", f.M1);
      B.constant("single pair contact factor (pinion)", "Z_B", "6336-2 eqs. 12, 14", "-", f.Z_B);
      B.constant("single pair contact factor (internal gear)", "Z_D", "6336-2 (Z_D = 1 for internal gears)", "-",
                 f.Z_D);
      const double K = std::sqrt(in.K_A * in.K_v_iso * in.K_Hbeta);
      auto s0 = [&](double T) { return f.sigma_H0 * std::sqrt(2 * T / c.d1) / 1e6; };
      B.add("nominal contact stress ((u + 1)/u with u < 0)", "sigma_H0", "6336-2 eq. 2", "MPa", c.per_torque(s0));
      B.add("contact stress, pinion", "sigma_H1", "6336-2 eq. 1", "MPa",
            c.per_torque([&](double T) { return f.Z_B * s0(T) * K; }));
      B.add("contact stress, internal gear", "sigma_H2", "6336-2 eq. 1", "MPa",
            c.per_torque([&](double T) { return f.Z_D * s0(T) * K; }));
    }

    /// ISO 6336-3 method B rows of one member: section, factors, Y_B, stresses.
    void add_iso_root_member(const Context &c, RowBuilder &B, const std::string &s, const std::string &method,
                             const iso6336::RootFactors &rf, double Y_B, const std::string &yb_clause, double KFb)
    {
      const RatingInput &in = c.r;
      B.constant("critical section chord", "s_Fn" + s, method, "mm", rf.s_Fn * 1e3);
      B.constant("fillet radius at the critical section", "rho_F" + s, method, "mm", rf.rho_F * 1e3);
      B.constant("bending moment arm, outer single contact", "h_Fe" + s, "6336-3 6.2", "mm", rf.h_Fe * 1e3);
      B.constant("load direction angle", "alpha_Fen" + s, "6336-3 6.2", "deg", rf.alpha_Fen / deg);
      B.constant("form factor", "Y_F" + s, "6336-3 eq. 24", "-", rf.Y_F);
      B.constant("stress correction factor", "Y_S" + s, "6336-3 eq. 43", "-", rf.Y_S);
      B.constant("rim thickness factor", "Y_B" + s, yb_clause, "-", Y_B);
      const double Y = rf.Y_F * rf.Y_S * Y_B / (c.b * c.m);
      B.add("nominal root stress (method B)", "sigma_F0" + s, "6336-3 eq. 3", "MPa",
            c.per_torque([&](double T) { return 2 * T / c.d1 * Y / 1e6; }));
      B.add("root stress", "sigma_F" + s, "6336-3 eq. 2", "MPa", c.per_torque([&](double T) {
              return 2 * T / c.d1 * Y * in.K_A * in.K_v_iso * KFb / 1e6;
            }));
    }

    /// ISO 6336-3 rows of the pinion (30 deg) and of the ring (closed form, 60 deg; check on
    /// the generated ring fillet).
    void add_iso_root(const Context &c, RatingReport &rep, double KFb)
    {
      RowBuilder B{rep, "ISO 6336", "internal rating"};
      const geometry::InternalMesh &mesh = c.mesh;
      B.constant("helix angle factor", "Y_beta", "6336-3 eq. 48", "-", 1.0);
      // Pinion: the external machinery at its outer point of single contact D.
      const iso6336::CriticalSection cs1 = iso6336::critical_section(analytical::fillet_curve(c.p1));
      const analytical::InvoluteTooth t1 = analytical::involute_tooth(c.p1, 0.0, 5);
      const iso6336::RootFactors rf1 =
        iso6336::root_factors(cs1, {t1.rb, t1.psi_b}, mesh.point("D").r1, c.m, c.alpha);
      const double sR1 = c.in.pinion_rim_thickness, sR2 = c.in.ring_rim_thickness;
      const double YB1 = sR1 > 0 ? iso6336::Y_B_external(sR1, c.ht1) : 1.0;
      if (sR1 > 0)
        B.constant("rim thickness ratio", "s_R1/h_t1", "6336-3 clause 8", "-", sR1 / c.ht1);
      add_iso_root_member(c, B, "1", "6336-3 6.2 (30 deg tangent, generated fillet)", rf1, YB1,
                          "6336-3 clause 8 (external: 1.6 ln(2.242 h_t/s_R); 1 if solid)", KFb);
      // Ring: the closed form with z2 < 0 and the 60 deg tangent, load at its point B.
      const geometry::InternalGearParameters &g2 = c.p2.parameters();
      const double h_fP2 = (c.rf2 - c.r2) / c.m + c.x2, rho_a0 = g2.cutter.tip_radius;
      const iso6336::InternalSection sec = iso6336::internal_gear_section(c.z2, c.m, c.alpha, c.x2, h_fP2, rho_a0);
      const iso6336::InvoluteFlank fl2{mesh.rb2, (0.5 * pi + 2 * c.x2 * std::tan(c.alpha)) / c.z2 - inv(c.alpha)};
      const double r_e2 = mesh.point("B").r2;
      const iso6336::RootFactors rf2 = iso6336::internal_root_factors(sec.s_Fn, sec.y, sec.rho_F, fl2, r_e2, c.m, c.alpha);
      B.constant("basic-rack dedendum of the ring (r_f2 - r_2)/m + x_2", "h_fP2", "6336-3 6.2 (internal gear)", "-",
                 h_fP2);
      B.constant("cutter tip radius = ring root radius", "rho_fP2", "6336-3 6.2 (rho_a0 of the shaper)", "-", rho_a0);
      B.constant("theta of the closed form (z2 < 0, T = pi/6)", "theta2", "6336-3 6.2 (internal gear)", "deg",
                 sec.theta / deg);
      B.constant("diameter of the critical section points", "d_sFn2", "6336-3 6.2 (internal gear)", "mm",
                 2e3 * std::hypot(sec.y, 0.5 * sec.s_Fn));
      B.constant("load diameter, outer single contact (B)", "d_en2", "6336-3 6.2", "mm", 2e3 * r_e2);
      const double YB2 = sR2 > 0 ? iso6336::Y_B_internal(sR2, c.m) : 1.0;
      if (sR2 > 0)
        B.constant("rim thickness ratio", "s_R2/m_n", "6336-3 clause 8 (internal gear)", "-", sR2 / c.m);
      add_iso_root_member(c, B, "2", "6336-3 6.2 (internal gear: closed form, 60 deg tangent)", rf2, YB2,
                          "6336-3 clause 8 (internal: 1.15 ln(8.324 m_n/s_R); 1 if not given)", KFb);
      // The same construction on the exact generated ring fillet (check).
      const iso6336::CriticalSection cg = iso6336::critical_section(ring_side(c.p2, false, false), 60.0);
      const iso6336::RootFactors rg = iso6336::internal_root_factors(cg.s_Fn, cg.y, cg.rho_F, fl2, r_e2, c.m, c.alpha);
      const std::string gen = "6336-3 6.2 on the generated ring fillet (check)";
      B.constant("critical section chord, generated ring (60 deg)", "s_Fn2,gen", gen, "mm", rg.s_Fn * 1e3);
      B.constant("fillet radius there, generated ring", "rho_F2,gen", gen, "mm", rg.rho_F * 1e3);
      B.constant("bending moment arm, generated ring", "h_Fe2,gen", gen, "mm", rg.h_Fe * 1e3);
      B.constant("form factor, generated ring", "Y_F2,gen", gen, "-", rg.Y_F);
      B.constant("stress correction factor, generated ring", "Y_S2,gen", gen, "-", rg.Y_S);
    }

    /// AGMA 2101-D04 / 908-B89 rows.
    void add_agma(const Context &c, RatingReport &rep)
    {
      const RatingInput &in = c.r;
      RowBuilder B{rep, "AGMA", "internal rating"};
      const geometry::InternalMesh &mesh = c.mesh;
      const agma::LineOfAction l = agma::line_of_action_internal(c.z1, c.z2, c.m, c.alpha, mesh.in.tip_radius1,
                                                                 mesh.in.tip_radius2, mesh.a);
      const double dw1 = 2.0 * mesh.rw1, ZI = agma::geometry_factor_I_internal(l);
      const double ZE = agma::Z_E(in.E1, in.nu1, in.E2, in.nu2);
      const double Kma = agma::K_Hma(c.b, in.enclosure), Kpf = agma::K_Hpf(c.b, dw1);
      const double KH = in.K_H > 0.0 ? in.K_H : 1.0 + Kma + Kpf;
      const double sR1 = c.in.pinion_rim_thickness, sR2 = c.in.ring_rim_thickness;
      const double mB1 = sR1 / c.ht1, mB2 = sR2 / c.ht2;
      const double KB1 = sR1 > 0 ? agma::K_B(mB1) : 1.0, KB2 = sR2 > 0 ? agma::K_B(mB2) : 1.0;
      const double W = in.K_o * in.K_v * in.K_s * KH; // times F_t
      B.constant("operating pitch diameter 2 C_r/(m_G - 1)", "d_w1", "2101-D04 (Siasos 2010 sec. 4.3)", "mm", dw1 * 1e3);
      B.constant("net face width", "b", "2101-D04", "mm", c.b * 1e3);
      B.constant("pitch-line velocity (from Rating/Pinion speed)", "v_t", "2101-D04", "m/s",
                 in.speed * 2.0 * pi / 60.0 * 0.5 * dw1);
      B.add("transmitted tangential load 2T/d_w1", "F_t", "2101-D04", "N",
            c.per_torque([&](double T) { return 2 * T / dw1; }));
      B.constant("elastic coefficient", "Z_E", "2101-D04", "sqrt(MPa)", ZE / 1e3);
      B.constant("overload factor", "K_o", "2101-D04 (input)", "-", in.K_o);
      B.constant("dynamic factor", "K_v", "2101-D04 (input)", "-", in.K_v);
      B.constant("size factor", "K_s", "2101-D04 (input)", "-", in.K_s);
      B.constant(std::string("mesh alignment factor (") + agma::to_string(in.enclosure) + ")", "K_Hma",
                 "2101-D04 (Siasos 2010 eq. 4.1.6-4)", "-", Kma);
      B.constant("pinion proportion factor", "K_Hpf", "2101-D04 (Siasos 2010 eqs. 4.1.6-5..7)", "-", Kpf);
      B.constant("load distribution factor", "K_H", "2101-D04 (Siasos 2010 eq. 4.1.6-3)", "-", KH);
      B.constant("surface condition factor", "Z_R", "2101-D04 (input)", "-", in.Z_R);
      B.constant("contact start from T1, ring tip (unit module)", "C1", "908-B89 (Siasos 2010 sec. 4.3, internal)", "-",
                 l.C1);
      B.constant("LPSTC distance from T1 (unit module)", "C2", "908-B89 (Siasos 2010 eq. 4.3-17)", "-", l.C2);
      B.constant("HPSTC distance from T1 (unit module)", "C4", "908-B89 (Siasos 2010 eq. 4.3-15)", "-", l.C4);
      B.constant("transverse contact ratio", "m_p", "908-B89 (Siasos 2010 eq. 4.3-19)", "-", l.contact_ratio);
      B.constant("pitting geometry factor (internal)", "Z_I", "908-B89 (Siasos 2010 sec. 4.3, lower signs)", "-", ZI);
      B.add("contact stress", "sigma_H", "2101-D04 (Siasos 2010 eq. 4.1-1)", "MPa", c.per_torque([&](double T) {
              return ZE * std::sqrt(2 * T / dw1 * W / (dw1 * c.b) * in.Z_R / ZI) / 1e6;
            }));
      // Pinion: the 908 trochoid at its HPSTC C4, with the pinion's rack as the tool.
      agma::Tool tool = in.tool;
      const geometry::GearParameters &g1 = c.p1.parameters();
      tool.h_ao = g1.rack.dedendum, tool.rho_ao = g1.rack.root_radius;
      const agma::BendingGeometry J1 = agma::geometry_factor_J(c.z1, c.x1, l.C4 / l.Rb1, c.alpha, l.phi_r, tool);
      // Ring: 908's Lewis parabola on the generated ring outline, fillet and flank (the
      // parabola may touch the wide internal tooth on its involute; tooth turned to point up),
      // load at its HPSTC (roll C6 + C2), phi_nL = a_en + gamma_e (the half angle widens outwards).
      const double r_e2 = c.m * std::hypot(l.Rb2, l.C6 + l.C2), a_en2 = std::acos(mesh.rb2 / r_e2);
      agma::BendingGeometry J2;
      J2.tan_phi_nW = (l.C6 + l.C2) / l.Rb2;
      J2.phi_nL = a_en2 + c.p2.involute_thickness_at_radius(r_e2) / (2 * r_e2);
      J2.r_nL = mesh.rb2 / std::cos(J2.phi_nL) / c.m;
      const agma::LewisSection ls = agma::lewis_section(ring_side(c.p2, true, true), -J2.r_nL * c.m);
      J2.s_F = ls.s_F / c.m, J2.h_F = ls.h_F / c.m, J2.rho_F = ls.rho_F / c.m;
      agma::form_and_stress_factors(J2, c.alpha, l.phi_r);
      for (int i : {1, 2})
        {
          const std::string s = std::to_string(i);
          const agma::BendingGeometry &J = i == 1 ? J1 : J2;
          const std::string src = i == 1 ? "908-B89 trochoid (Siasos 2010 eqs. 4.3.2-8..46)" : "908-B89 Lewis parabola, generated ring";
          const double KB = i == 1 ? KB1 : KB2, sR = i == 1 ? sR1 : sR2, mB = i == 1 ? mB1 : mB2;
          B.constant("load angle at the HPSTC", "phi_nL" + s, src, "deg", J.phi_nL / deg);
          B.constant("critical section thickness", "s_F" + s, src, "mm", J.s_F * c.m * 1e3);
          B.constant("Lewis parabola height", "h_F" + s, src, "mm", J.h_F * c.m * 1e3);
          B.constant("minimum fillet radius", "rho_F" + s, src, "mm", J.rho_F * c.m * 1e3);
          B.constant("stress correction factor", "K_f" + s, "908-B89 (Siasos 2010 eq. 4.3.2-44)", "-", J.K_f);
          B.constant("tooth form factor", "Y" + s, "908-B89 (Siasos 2010 eq. 4.3.2-46)", "-", J.Y);
          B.constant("bending geometry factor", "Y_J" + s, "908-B89 (Siasos 2010 eq. 4.3.2-1)", "-", J.Y_J);
          if (sR > 0)
            B.constant("backup ratio t_R/h_t", "m_B" + s, "2101-D04 (Siasos 2010 sec. 4.2.1)", "-", mB);
          B.constant("rim thickness factor", "K_B" + s, "2101-D04 (1.6 ln(2.242/m_B); 1 if not given)", "-", KB);
          B.add("bending stress at the HPSTC", "sigma_F" + s, "2101-D04 (Siasos 2010 eq. 4.2-1)", "MPa",
                c.per_torque([&](double T) { return 2 * T / dw1 * W * KB / (c.b * c.m * J.Y_J) / 1e6; }));
        }
    }
  } // namespace

  RatingReport rate_internal(const geometry::ToothProfile &pinion, const geometry::InternalToothProfile &ring,
                             const geometry::InternalMesh &mesh, const InternalRatingInput &in)
  {
    const geometry::GearParameters &g1 = pinion.parameters();
    const geometry::InternalGearParameters &g2 = ring.parameters();
    Context c{pinion, ring, mesh, in, in.rating, g1.teeth, g2.teeth, g1.rack.module, g1.rack.pressure_angle,
              0, 0, g1.profile_shift, g2.profile_shift, 0, 0, ring.radii().root, ring.radii().reference};
    require_greater(g1.name + "/Face width", g1.face_width, 0.0, "m");
    if (in.ring_face_width < 0.0)
      throw InputError("Rating/Ring face width", mm_text(in.ring_face_width), ">= 0 (0: the pinion's)");
    c.b = in.ring_face_width > 0.0 ? std::min(g1.face_width, in.ring_face_width) : g1.face_width;
    c.d1 = c.m * c.z1;
    c.ht1 = pinion.radii().tip - pinion.radii().root;
    c.ht2 = ring.radii().root - ring.radii().tip;
    if (std::abs(g2.pressure_angle - c.alpha) > 1e-12)
      throw InputError(g2.name + "/Pressure angle", to_string_g(g2.pressure_angle / deg) + " deg",
                       to_string_g(c.alpha / deg) + " deg (the pinion's)");
    check_input(c);
    {
      // The small-strain bound of the contact models (plane strain E' = E/(1 - nu^2)).
      const RatingInput &r = in.rating;
      const double Es = 1.0 / ((1 - r.nu1 * r.nu1) / r.E1 + (1 - r.nu2 * r.nu2) / r.E2);
      for (const double T : r.torques)
        geometry::limits::check_small_strain("Rating/Pinion torques", T, mesh.rb1, c.b, Es,
                                             mesh.relative_curvature(mesh.point("C").g));
    }
    RatingReport rep;
    rep.torques = in.rating.torques;
    add_agma(c, rep);
    const double h = (g1.rack.addendum + g1.rack.dedendum) * c.m;
    const double bh = std::max(3.0, c.b / h), NF = bh * bh / (1 + bh + bh * bh);
    const double KFb = std::pow(in.rating.K_Hbeta, NF);
    add_iso_contact(c, rep, KFb);
    add_iso_root(c, rep, KFb);
    return rep;
  }
} // namespace gearfem::rating
