#include "gearbox/stages.h"
#include "geometry/limits.h"
#include "base/units.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::gearbox
{
  namespace
  {
    using units::pi;
    constexpr double dedendum = 1.25; ///< h_f/m_n of the generating rack (AGMA 908 tool h_ao)

    /// Rim thickness factor of one member: m_B = t_B/h_t (AGMA 2101-D04, Siasos 2010 sec. 4.2.1).
    void rim_factor(const std::string &entry, double t_B, double h_t, double hold, double &mB,
                    double &KB)
    {
      if (hold <= 0.0)
        {
          mB = 0.0, KB = 1.0;
          return;
        }
      if (!(t_B > 0.0))
        throw InputError(entry, to_string_g(hold * 1e3) + " mm",
                         "a holding diameter that leaves a rim (rim thickness " +
                           to_string_g(t_B * 1e3) + " mm)");
      mB = t_B / h_t;
      KB = agma::K_B(mB);
    }
    /// ISO 6336-3 method B factors of an external member loaded at radius r_e: the critical
    /// section from the rack-fillet closed form (eqs. 25-33), the involute's half tooth angle
    /// at the base circle psi_b = (pi/2 + 2 x tan a)/z + inv a.
    iso6336::RootFactors iso_root(int z, double x, double m, double alpha, double r_e, const agma::Tool &tool)
    {
      const iso6336::RackFilletClosedForm c =
        iso6336::rack_fillet_closed_form(z, m, alpha, x, tool.h_ao, tool.rho_ao);
      iso6336::CriticalSection cs;
      cs.s_Fn = c.s_Fn, cs.y = c.y, cs.rho_F = c.rho_F;
      const double inv = std::tan(alpha) - alpha;
      const iso6336::InvoluteFlank fl{0.5 * m * z * std::cos(alpha), (pi / 2 + 2 * x * std::tan(alpha)) / z + inv};
      return iso6336::root_factors(cs, fl, r_e, m, alpha);
    }

    /// The input entry prefix of a member: "Sun", "Planet" or "Ring" (parallel: gear 1 is
    /// entered as the sun, gear 2 as the planet).
    std::string member_entry(const std::string &member)
    {
      if (member == "sun" || member == "gear 1")
        return "Sun";
      if (member == "planet" || member == "gear 2")
        return "Planet";
      return "Ring";
    }
  } // namespace

  double K_gamma_table(int N)
  {
    static const double t[] = {1.00, 1.00, 1.15, 1.19, 1.23, 1.27, 1.30, 1.33};
    if (N < 2 || N > 9)
      throw InputError("Number of planets (for K_gamma of Siasos 2010 table 7.2-1)", std::to_string(N),
                       "[2, 9], or give the load-sharing factor");
    return t[N - 2];
  }

  MeshGeometry mesh_geometry(const std::string &name, const std::string &pinion,
                             const std::string &gear, bool internal, int z1, int z2, double x1,
                             double x2, const StageInput &s, double hold1, double hold2,
                             const AgmaFactors &f)
  {
    MeshGeometry g;
    g.name = name, g.pinion = pinion, g.gear = gear, g.internal = internal;
    g.z1 = z1, g.z2 = z2, g.x1 = x1, g.x2 = x2;
    const double m = s.module, ha = s.addendum * m, K = s.tip_shortening * m, hf = dedendum * m;
    g.module = m, g.alpha = s.pressure_angle, g.b = s.face_width;
    const double ro1 = 0.5 * m * z1, ro2 = 0.5 * m * z2;
    g.r_w1 = ro1 + x1 * m;
    g.r_a1 = ro1 + ha + x1 * m - K;
    g.r_f1 = ro1 - hf + x1 * m;
    const double sgn = internal ? -1.0 : 1.0;
    g.r_w2 = ro2 + sgn * x2 * m;
    g.r_a2 = ro2 + sgn * (ha + x2 * m - K);
    g.r_f2 = ro2 - sgn * (hf - x2 * m);
    g.a = internal ? g.r_w2 - g.r_w1 : g.r_w1 + g.r_w2;
    const double u = double(z2) / z1;
    g.d_w1 = 2.0 * g.a / (u + sgn);
    const std::string stage = s.name + "/";
    // A pointed tooth (the flanks meet below the tip circle: no tip land) has no AGMA 908
    // geometry factor and is not a gear: refused against its member's profile shift. Tip land
    // of an external tooth at r_a: s_a = 2 r_a (pi/(2z) + 2 x tan(alpha)/z + inv(alpha) - inv(alpha_a)).
    const auto inv = [](double a) { return std::tan(a) - a; };
    for (int i = 0; i < 2; ++i)
      {
        const bool ext = i == 0 || !internal;
        const int z = i == 0 ? z1 : z2;
        const double x = i == 0 ? x1 : x2, ra = i == 0 ? g.r_a1 : g.r_a2, rb = 0.5 * m * z * std::cos(g.alpha);
        if (!ext || !(ra > rb))
          continue;
        const double sa = 2 * ra * (units::pi / (2 * z) + 2 * x * std::tan(g.alpha) / z + inv(g.alpha) -
                                    inv(std::acos(rb / ra)));
        if (!(sa > 0))
          throw InputError(stage + member_entry(i == 0 ? pinion : gear) + " profile shift", to_string_g(x),
                           "a value that leaves a tip land (the tooth of " + std::to_string(z) + " teeth is pointed)",
                           "the flanks meet below the tip circle (tip land " + to_string_g(sa * 1e3) + " mm)");
      }
    // A line of action that does not exist, or starts below the pinion's base circle
    // (involute interference, the real check on the generated geometry), is reported
    // against the gear's profile shift of this stage.
    const std::string entry = stage + member_entry(gear) + " profile shift";
    try
      {
        g.loa = internal ? agma::line_of_action_internal(z1, z2, m, g.alpha, g.r_a1, g.r_a2, g.a) :
                           agma::line_of_action(z1, z2, m, g.alpha, g.r_a1, g.r_a2, g.a);
      }
    catch (const InputError &e)
      {
        throw InputError(entry, to_string_g(x2), "a value that gives a valid " + name + " mesh", e.what());
      }
    if (!internal && !(g.loa.C1 > 0.0))
      throw InputError(entry, to_string_g(x2), "a value with contact start C1 > 0 on the line of action",
                       "involute interference: the " + gear + " tip starts contact below the base circle of the " +
                         pinion);
    if (!(g.loa.contact_ratio >= 1.0))
      throw InputError(stage + name + " contact ratio", to_string_g(g.loa.contact_ratio), ">= 1");
    g.Z_I = internal ? agma::geometry_factor_I_internal(g.loa) : agma::geometry_factor_I(g.loa);
    g.K_Hma = agma::K_Hma(g.b, f.enclosure);
    g.K_Hpf = agma::K_Hpf(g.b, g.d_w1);
    g.K_H = 1.0 + g.K_Hma + g.K_Hpf;
    g.Z_E = agma::Z_E(f.E1, f.nu1, f.E2, f.nu2);
    const double h_t = ha + hf - K;
    rim_factor(stage + pinion + " holding diameter", g.r_f1 - 0.5 * hold1, h_t, hold1, g.m_B1, g.K_B1);
    rim_factor(stage + gear + " holding diameter", internal ? 0.5 * hold2 - g.r_f2 : g.r_f2 - 0.5 * hold2,
               h_t, hold2, g.m_B2, g.K_B2);
    // Bending: Y_J at the HPSTC of each external member; the ring is not rated (Siasos 2010
    // sec. 7.2: Y_J covers external teeth, and the internal root is wider).
    const agma::LineOfAction &l = g.loa;
    g.J1 = agma::geometry_factor_J(z1, x1, l.C4 / l.Rb1, g.alpha, l.phi_r, f.tool);
    g.Y_J1 = g.J1.Y_J;
    if (!internal)
      {
        g.J2 = agma::geometry_factor_J(z2, x2, (l.C6 - l.C2) / l.Rb2, g.alpha, l.phi_r, f.tool);
        g.Y_J2 = g.J2.Y_J;
      }
    // ISO 6336-2 with the standard's sign convention for the internal gear: with z2 < 0 the
    // M1 term tan(alpha_a2) - (eps - 1) 2 pi/z2 is rho2/r_b2 at the inner single-contact point.
    iso6336::ContactInput ci;
    ci.z1 = z1, ci.z2 = internal ? -z2 : z2;
    ci.alpha_t = g.alpha, ci.alpha_wt = l.phi_r;
    ci.d1 = m * z1;
    ci.da1 = 2 * g.r_a1, ci.da2 = sgn * 2 * g.r_a2;
    ci.db1 = m * z1 * std::cos(g.alpha), ci.db2 = sgn * m * z2 * std::cos(g.alpha);
    ci.b = g.b, ci.Ft = 1.0;
    ci.E1 = f.E1, ci.nu1 = f.nu1, ci.E2 = f.E2, ci.nu2 = f.nu2;
    ci.eps_alpha = l.contact_ratio;
    g.iso = iso6336::contact_stress(ci);
    if (internal)
      g.iso.Z_D = 1.0;
    // ISO 6336-3: outer point of single contact, the pinion's HPSTC (C4) and the gear's point
    // opposite the LPSTC (C6 - C2); the line of action is in unit module.
    g.F1_iso = iso_root(z1, x1, m, g.alpha, m * std::hypot(l.Rb1, l.C4), f.tool);
    if (!internal)
      g.F2_iso = iso_root(z2, x2, m, g.alpha, m * std::hypot(l.Rb2, l.C6 - l.C2), f.tool);
    const double bh = std::max(3.0, g.b / (ha + hf)), NF = bh * bh / (1 + bh + bh * bh);
    g.K_Fbeta = std::pow(f.K_Hbeta, NF);
    return g;
  }

  MeshStress mesh_stress(const MeshGeometry &g, double Ft, const AgmaFactors &f)
  {
    require_greater("mesh tangential load", Ft, 0.0, "N");
    MeshStress r;
    const double W = Ft * f.K_o * f.K_v * f.K_s * g.K_H;
    r.sigma_H = g.Z_E * std::sqrt(W / (g.d_w1 * g.b) * f.Z_R / g.Z_I);
    r.sigma_F1 = W * g.K_B1 / (g.b * g.module * g.Y_J1);
    r.sigma_F2 = g.Y_J2 > 0.0 ? W * g.K_B2 / (g.b * g.module * g.Y_J2) : 0.0;
    const double Ft_iso = Ft * g.r_w1 / (0.5 * g.module * g.z1);
    const double H0 = g.iso.sigma_H0 * std::sqrt(Ft_iso * f.K_A * f.K_v_iso * f.K_Hbeta);
    r.sigma_H1_iso = g.iso.Z_B * H0, r.sigma_H2_iso = g.iso.Z_D * H0;
    const double F0 = Ft_iso / (g.b * g.module) * f.K_A * f.K_v_iso * g.K_Fbeta;
    r.sigma_F1_iso = F0 * g.F1_iso.Y_F * g.F1_iso.Y_S;
    r.sigma_F2_iso = F0 * g.F2_iso.Y_F * g.F2_iso.Y_S;
    return r;
  }

  double Stage::tangential_load(double M_in) const
  {
    if (in.type == StageType::parallel)
      return M_in / (meshes[0].pinion == "gear 1" ? meshes[0].r_w1 : meshes[0].r_w2);
    return K_gamma * M_in * torque_ratio / (in.planets * sun_working_radius);
  }

  namespace
  {
    void check_common(const StageInput &s)
    {
      const std::string p = s.name + "/";
      namespace limits = geometry::limits;
      limits::check_module(p + "Module", s.module);
      limits::check_face_width(p + "Face width", s.face_width);
      limits::check_pressure_angle(p + "Pressure angle", s.pressure_angle);
      limits::check_addendum(p + "Addendum coefficient", s.addendum);
      require_range(p + "Tip shortening coefficient", s.tip_shortening, 0.0, 0.5);
      // A parallel stage's gear 1 and gear 2 are the `Sun teeth` and `Planet teeth` entries.
      limits::check_teeth(p + "Sun teeth", s.z_sun);
      limits::check_teeth(p + "Planet teeth", s.z_planet);
    }

    Stage build_parallel(const StageInput &s, const AgmaFactors &f)
    {
      if (s.output != "gear 2")
        throw InputError(s.name + "/Output member", s.output, "gear 2",
                         "a parallel stage is driven by gear 1 and feeds the next stage from gear 2");
      Stage st;
      st.in = s;
      const bool swap = s.z_planet < s.z_sun; // reducer form: the pinion has fewer teeth
      st.meshes.push_back(swap ? mesh_geometry("pair", "gear 2", "gear 1", false, s.z_planet, s.z_sun,
                                               s.x_planet, s.x_sun, s, s.bore_planet, s.bore_sun, f) :
                                 mesh_geometry("pair", "gear 1", "gear 2", false, s.z_sun, s.z_planet,
                                               s.x_sun, s.x_planet, s, s.bore_sun, s.bore_planet, f));
      st.ratio = st.torque_ratio = double(s.z_planet) / s.z_sun;
      st.cycles_sun = 1.0;
      st.cycles_planet = double(s.z_sun) / s.z_planet;
      return st;
    }

    void check_planetary(const StageInput &s)
    {
      const std::string p = s.name + "/";
      geometry::limits::check_teeth(p + "Ring teeth", s.z_ring);
      if (s.planets < 2)
        throw InputError(p + "Number of planets", std::to_string(s.planets), ">= 2");
      if ((s.z_sun + s.z_ring) % s.planets != 0)
        throw InputError(p + "Number of planets", std::to_string(s.planets),
                         "a divisor of Z_S + Z_R = " + std::to_string(s.z_sun + s.z_ring),
                         "equal spacing (Siasos 2010 eq. 7.2-13) needs (Z_S + Z_R)/N to be an integer");
      if (s.z_ring < s.z_planet + 10)
        throw InputError(p + "Ring teeth", std::to_string(s.z_ring),
                         ">= planet teeth + 10 = " + std::to_string(s.z_planet + 10),
                         "internal tip interference (Siasos 2010 eq. 2.2.2-2)");
      const std::string fixed = s.fixed == Fixed::ring ? "ring" : "carrier";
      if (s.output != "sun")
        throw InputError(p + "Output member", s.output, "sun",
                         s.output == fixed ? "the " + fixed + " is fixed, so it cannot feed the next stage" :
                                             "only the sun-output layouts are implemented");
      if (s.K_gamma != 0.0)
        require_range(p + "Load sharing factor", s.K_gamma, 1.0, 2.0);
    }

    Stage build_planetary(const StageInput &s, const AgmaFactors &f)
    {
      check_planetary(s);
      const std::string p = s.name + "/";
      Stage st;
      st.in = s;
      const bool swap = s.z_planet < s.z_sun;
      st.meshes.push_back(swap ? mesh_geometry("sun-planet", "planet", "sun", false, s.z_planet, s.z_sun,
                                               s.x_planet, s.x_sun, s, s.bore_planet, s.bore_sun, f) :
                                 mesh_geometry("sun-planet", "sun", "planet", false, s.z_sun, s.z_planet,
                                               s.x_sun, s.x_planet, s, s.bore_sun, s.bore_planet, f));
      st.meshes.push_back(mesh_geometry("planet-ring", "planet", "ring", true, s.z_planet, s.z_ring,
                                        s.x_planet, s.x_ring, s, s.bore_planet, s.ring_outer, f));
      const MeshGeometry &sp = st.meshes[0], &pr = st.meshes[1];
      if (std::abs(sp.a - pr.a) > s.coaxiality_tolerance)
        throw InputError(p + "Ring profile shift", to_string_g(s.x_ring),
                         "a value that makes the meshes coaxial (|a_SP - a_PR| <= " +
                           to_string_g(s.coaxiality_tolerance * 1e3) + " mm)",
                         "a_SP = " + to_string_g(sp.a * 1e3) + " mm, a_PR = " + to_string_g(pr.a * 1e3) + " mm");
      const double r_aP = swap ? sp.r_a1 : sp.r_a2, gap = 2.0 * sp.a * std::sin(pi / s.planets);
      if (!(2.0 * r_aP < gap))
        throw InputError(p + "Number of planets", std::to_string(s.planets),
                         "planet tip diameter " + to_string_g(2e3 * r_aP) + " mm < 2 a sin(pi/N) = " +
                           to_string_g(gap * 1e3) + " mm",
                         "neighbouring planets touch");
      st.sun_working_radius = swap ? sp.r_w2 : sp.r_w1;
      st.K_gamma = s.K_gamma > 0.0 ? s.K_gamma : K_gamma_table(s.planets);
      const double ZS = s.z_sun, ZP = s.z_planet, ZR = s.z_ring;
      if (s.fixed == Fixed::ring)
        {
          // Carrier in (speed 1), sun out (Siasos 2010 eqs. 7.2-1, -5, -6, -7).
          st.ratio = ZS / (ZS + ZR);
          st.n_sun_rel = 1.0 / st.ratio - 1.0;
          st.n_ring_rel = -1.0;
        }
      else
        {
          // Star: carrier fixed, ring in (speed 1), sun out, reversed.
          st.ratio = -ZS / ZR;
          st.n_sun_rel = -ZR / ZS;
          st.n_ring_rel = 1.0;
        }
      st.n_planet_rel = -st.n_sun_rel * ZS / ZP;
      st.torque_ratio = std::abs(st.ratio);
      // Table 8.2-1: each sun and ring tooth meets N planets per relative revolution.
      st.cycles_sun = std::abs(st.n_sun_rel) * s.planets;
      st.cycles_ring = std::abs(st.n_ring_rel) * s.planets;
      st.cycles_planet = std::abs(st.n_planet_rel);
      return st;
    }
  } // namespace

  Stage build_stage(const StageInput &s, const AgmaFactors &f)
  {
    check_common(s);
    return s.type == StageType::parallel ? build_parallel(s, f) : build_planetary(s, f);
  }

  std::vector<double> Train::speeds() const
  {
    std::vector<double> n{input_speed};
    for (const Stage &s : stages)
      n.push_back(n.back() / s.ratio);
    return n;
  }

  std::vector<double> Train::torques(double M) const
  {
    std::vector<double> t{M};
    for (const Stage &s : stages)
      t.push_back(t.back() * s.torque_ratio);
    return t;
  }

  double Train::input_revolutions(std::size_t k) const
  {
    double r = 1.0;
    for (std::size_t j = 0; j < k && j < stages.size(); ++j)
      r /= std::abs(stages[j].ratio);
    return r;
  }

  Train build_train(const std::vector<StageInput> &stages, double input_speed, const AgmaFactors &f)
  {
    if (stages.empty())
      throw InputError("Gearbox/Stages", "(none)", "one or more stages");
    require_greater("Gearbox/Input speed", input_speed, 0.0, "rpm");
    Train t;
    t.input_speed = input_speed;
    for (const StageInput &s : stages)
      t.stages.push_back(build_stage(s, f));
    return t;
  }
} // namespace gearfem::gearbox
