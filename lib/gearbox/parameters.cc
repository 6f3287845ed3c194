#include "gearbox/parameters.h"

#include "geometry/limits.h"
#include "base/units.h"

#include "geometry/parameters.h"
#include "rating/parameters.h"
#include "base/errors.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::gearbox
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;

  namespace
  {
    constexpr double deg = units::pi / 180.0;

    void declare_sn(dealii::ParameterHandler &prm, const std::string &mode, const char *sigma,
                    const char *N, const char *B, const char *group)
    {
      prm.declare_entry(mode + " S-N model", "semi-log", Selection("semi-log|iso"),
                        "semi-log: Siasos 2010 eq. 8.4-4, N = N_ref 10^((sigma - sigma_n)/B), no damage "
                        "below sigma_n; iso: ISO 6336-2/-3 life factor (Z_NT/Y_NT) from the material group.");
      prm.declare_entry(mode + " endurance stress", sigma, Double(0),
                        "sigma_n (semi-log) or sigma_lim (iso). Units: MPa.");
      prm.declare_entry(mode + " reference cycles", N, Double(1),
                        "N_ref, the cycles at sigma_n (semi-log). Units: cycles.");
      prm.declare_entry(mode + " slope", B, Double(),
                        "B of sigma = A + B log10 N (semi-log), < 0. Units: MPa per decade.");
      prm.declare_entry(mode + " ISO material group", group, Selection("Eh|NT"),
                        "ISO 6336 life-factor curve (iso): Eh case hardened, NT nitrided.");
    }

    void declare_stage(dealii::ParameterHandler &prm, int k)
    {
      const bool s2 = k == 2;
      prm.enter_subsection("Stage " + std::to_string(k));
      prm.declare_entry("Type", "planetary", Selection("planetary|parallel"),
                        "planetary: sun, planets, ring, carrier; parallel: one external pair, gear 1 "
                        "(the 'Sun' entries) drives gear 2 (the 'Planet' entries).");
      prm.declare_entry("Fixed member", "ring", Selection("ring|carrier"),
                        "Planetary layout: ring fixed, carrier in, sun out (Siasos 2010), or carrier "
                        "fixed (star), ring in, sun out.");
      prm.declare_entry("Output member", "sun", Anything(),
                        "The member that feeds the next stage: sun (planetary) or gear 2 (parallel).");
      geometry::declare_teeth_entry(prm, "Sun teeth", s2 ? 27 : 16, "Z_S (gear 1 of a parallel stage)");
      geometry::declare_teeth_entry(prm, "Planet teeth", s2 ? 44 : 28, "Z_P (gear 2 of a parallel stage)");
      geometry::declare_teeth_entry(prm, "Ring teeth", s2 ? 117 : 74, "Z_R (planetary only)");
      prm.declare_entry("Sun profile shift", "0.7", Double(-2, 2), "x_S. Units: multiples of the module.");
      prm.declare_entry("Planet profile shift", "0.6", Double(-2, 2), "x_P. Units: multiples of the module.");
      prm.declare_entry("Ring profile shift", "-0.9", Double(-2, 2),
                        "x_R; positive moves the tool towards the centre (Siasos 2010 eq. 2.1.2-4). Units: "
                        "multiples of the module.");
      geometry::declare_module_entry(prm, "Module", s2 ? 3.5 : 6);
      geometry::declare_pressure_angle_entry(prm);
      geometry::declare_face_width_entry(prm, "Face width", s2 ? 50 : 110);
      geometry::declare_addendum_entry(prm, "Addendum coefficient", "h_k/m_n (not stated by Siasos 2010)");
      prm.declare_entry("Tip shortening coefficient", "0", Double(0), "K/m_n (eq. 2.1.1-9). Units: none.");
      prm.declare_entry("Number of planets", "3", Integer(0), "N. Units: none.");
      prm.declare_entry("Load sharing factor", "0", Double(0),
                        "K_gamma; 0 takes Siasos 2010 table 7.2-1 (1.00 for 2-3 planets). Units: none.");
      prm.declare_entry("Sun bore diameter", "40", Double(0), "Holding diameter for K_B; 0: solid. Units: mm.");
      prm.declare_entry("Planet bore diameter", s2 ? "100" : "120", Double(0), "The same for the planet. Units: mm.");
      prm.declare_entry("Ring outer diameter", s2 ? "488" : "572", Double(0),
                        "Holding diameter of the ring for K_B; 0: K_B = 1. Units: mm.");
      prm.declare_entry("Coaxiality tolerance", "0.01", Double(0),
                        "Allowed |a_sun-planet - a_planet-ring|. Units: mm.");
      prm.declare_entry("Material name", s2 ? "42MnV7 nitrided" : "37Cr4 nitro-case-hardened", Anything(),
                        "For the report.");
      prm.declare_entry("Young's modulus", "206", Double(0), "E of every member. Units: GPa. Allowed: 0.1 to 1500.");
      prm.declare_entry("Poisson ratio", "0.3", Double(0, 0.5), "nu. Units: none.");
      prm.declare_entry("Roughness Ra", "0.5", Double(0), "Ra of the flanks. Units: um.");
      declare_sn(prm, "Contact", s2 ? "930" : "1285", "1e8", "-10", s2 ? "NT" : "Eh");
      declare_sn(prm, "Bending", s2 ? "580" : "740", "3e6", "-9", s2 ? "NT" : "Eh");
      prm.declare_entry("Reference contact stresses", "", List(Double(0)),
                        "Stress source = table: sigma_H of the sun-planet and planet-ring meshes (one "
                        "value for a parallel stage) at the reference torque. Units: MPa.");
      prm.declare_entry("Reference bending stresses", "", List(Double(0)),
                        "Stress source = table: sigma_F of pinion and gear of each mesh, in mesh order "
                        "(0 for the ring). Units: MPa.");
      prm.leave_subsection();
    }

    fatigue::SNCurve parse_sn(dealii::ParameterHandler &prm, const std::string &mode)
    {
      const double sigma = params::get_double(prm, mode + " endurance stress") * 1e6;
      if (prm.get(mode + " S-N model") == "iso")
        return fatigue::iso_curve(mode == "Contact" ? "contact" : "bending", prm.get(mode + " ISO material group"),
                                  sigma);
      fatigue::SNCurve c;
      c.sigma_n = sigma;
      c.N_ref = params::get_double(prm, mode + " reference cycles");
      c.B = params::get_double(prm, mode + " slope") * 1e6;
      return c;
    }

    void parse_stage(dealii::ParameterHandler &prm, int k, GearboxStudy &st)
    {
      prm.enter_subsection("Stage " + std::to_string(k));
      StageInput s;
      s.name = "Stage " + std::to_string(k);
      s.type = prm.get("Type") == "parallel" ? StageType::parallel : StageType::planetary;
      s.fixed = prm.get("Fixed member") == "carrier" ? Fixed::carrier : Fixed::ring;
      s.output = prm.get("Output member");
      if (s.type == StageType::parallel && s.output == "sun")
        s.output = "gear 2"; // the default names the planetary output
      s.z_sun = params::get_integer(prm, "Sun teeth");
      s.z_planet = params::get_integer(prm, "Planet teeth");
      s.z_ring = params::get_integer(prm, "Ring teeth");
      s.x_sun = params::get_double(prm, "Sun profile shift");
      s.x_planet = params::get_double(prm, "Planet profile shift");
      s.x_ring = params::get_double(prm, "Ring profile shift");
      s.module = params::get_double(prm, "Module") * 1e-3;
      s.pressure_angle = params::get_double(prm, "Pressure angle") * deg;
      s.face_width = params::get_double(prm, "Face width") * 1e-3;
      s.addendum = params::get_double(prm, "Addendum coefficient");
      s.tip_shortening = params::get_double(prm, "Tip shortening coefficient");
      s.planets = params::get_integer(prm, "Number of planets");
      s.K_gamma = params::get_double(prm, "Load sharing factor");
      s.bore_sun = params::get_double(prm, "Sun bore diameter") * 1e-3;
      s.bore_planet = params::get_double(prm, "Planet bore diameter") * 1e-3;
      s.ring_outer = params::get_double(prm, "Ring outer diameter") * 1e-3;
      s.coaxiality_tolerance = params::get_double(prm, "Coaxiality tolerance") * 1e-3;
      StageMaterial m;
      m.name = prm.get("Material name");
      m.E = params::get_double(prm, "Young's modulus") * 1e9;
      geometry::limits::check_youngs_modulus(s.name + "/Young's modulus", m.E);
      m.nu = params::get_double(prm, "Poisson ratio");
      m.Ra = params::get_double(prm, "Roughness Ra") * 1e-6;
      m.contact = parse_sn(prm, "Contact");
      m.bending = parse_sn(prm, "Bending");
      const std::vector<double> H = params::get_doubles(prm, "Reference contact stresses");
      const std::vector<double> F = params::get_doubles(prm, "Reference bending stresses");
      prm.leave_subsection();
      st.input.stages.push_back(s);
      st.input.materials.push_back(m);
      if (st.source != StressSource::table)
        return;
      const std::size_t meshes = s.type == StageType::parallel ? 1 : 2;
      if (H.size() != meshes || F.size() != 2 * meshes)
        throw InputError(s.name + "/Reference contact stresses, Reference bending stresses",
                         std::to_string(H.size()) + " and " + std::to_string(F.size()) + " values",
                         std::to_string(meshes) + " and " + std::to_string(2 * meshes) + " values",
                         "Gearbox/Stress source = table needs them");
      std::vector<MeshStress> ref;
      for (std::size_t j = 0; j < meshes; ++j)
        ref.push_back({H[j] * 1e6, F[2 * j] * 1e6, F[2 * j + 1] * 1e6});
      st.reference.push_back(ref);
    }
  } // namespace

  void declare_gearbox_parameters(dealii::ParameterHandler &prm)
  {
    rating::declare_rating_parameters(prm);
    prm.enter_subsection("Gearbox");
    prm.declare_entry("Input speed", "61", Double(0), "Speed of the gearbox input shaft. Units: rpm.");
    prm.declare_entry("Number of stages", "2", Integer(0), "Stages used, from `Stage 1`. Units: none. Allowed: 1-4.");
    prm.declare_entry("Stress source", "AGMA", Selection("AGMA|ISO|table|FE"),
                      "AGMA: AGMA 2101-D04/908-B89 from the geometry; ISO: ISO 6336-2 (the larger of "
                      "sigma_H1, sigma_H2 of the mesh) and ISO 6336-3 method B (sigma_F) from the geometry; table: the stresses given per stage "
                      "at the reference torque, sigma_H scaled with sqrt(M), sigma_F with M; FE: every mesh "
                      "solved by `gearfem solve` sector models (section `FE stresses`), sigma_H as "
                      "Hertz from the FE load share and sigma_F as the fillet sigma_1, maxima over the mesh "
                      "cycle; the planet-ring mesh as a pinion in a ring, whose ring is then rated in bending.");
    prm.declare_entry("Reference torque", "45000", Double(0), "Input torque of the table stresses. Units: N m.");
    prm.leave_subsection();
    for (int k = 1; k <= max_stages; ++k)
      declare_stage(prm, k);
    prm.enter_subsection("Spectrum");
    prm.declare_entry("Torques", "45000, 42500, 40000, 37500, 35000, 32500, 30000, 27500, 25000, 22500, 20000, "
                                 "17500, 15000, 10000, 5000",
                      List(Double()), "Torque bins at the gearbox input (Siasos 2010 table 9.2-1). Units: N m.");
    prm.declare_entry("Revolutions", "315, 315, 315, 125, 22100, 379000, 299000, 4.16e6, 36.6e6, 46.4e6, 40.5e6, "
                                     "32.1e6, 41.0e6, 52.0e6, 30.3e6",
                      List(Double()), "Input-shaft revolutions per bin over the spectrum duration. Units: rev.");
    prm.declare_entry("Hours", "", List(Double()),
                      "Alternative to Revolutions: hours per bin at the input speed. Units: h.");
    prm.declare_entry("Duration", "10", Double(), "Time the spectrum represents. Units: years.");
    prm.leave_subsection();
    prm.enter_subsection("Lubricant");
    prm.declare_entry("Oil type", "mineral", Selection("mineral|PAO|PAG|MIL-L-7808K|MIL-L-23699E"),
                      "For the pressure-viscosity constants (AGMA 925, Siasos 2010 eq. 4.4-48).");
    prm.declare_entry("Extreme pressure", "true", Bool(), "EP additives (theta_S of eq. 4.4-59).");
    prm.declare_entry("Kinematic viscosity at 40 C", "220", Double(0), "nu40. Units: mm^2/s. Allowed: 2 to 1e5.");
    prm.declare_entry("Dynamic viscosity at 40 C", "194.2414", Double(0),
                      "eta40. Units: mPa s. Allowed: 0.5 to 1e5, > eta100.");
    prm.declare_entry("Dynamic viscosity at 100 C", "15.98296", Double(0), "eta100. Units: mPa s. Allowed: 0.5 to 1e5.");
    prm.declare_entry("Oil temperature", "70", Double(), "theta_oil (not given by Siasos 2010). Units: C.");
    prm.declare_entry("Sump factor", "1.0", Double(), "k_sump: 1.0 oil bath, 1.2 spray. Units: none.");
    prm.declare_entry("Points along the path", "25", Integer(), "Scuffing points from A to E (25-50).");
    prm.leave_subsection();
  }

  GearboxStudy parse_gearbox_parameters(dealii::ParameterHandler &prm)
  {
    GearboxStudy st;
    const rating::RatingInput ri = rating::parse_rating_parameters(prm);
    AgmaFactors &f = st.input.agma;
    f.K_o = ri.K_o, f.K_v = ri.K_v, f.K_s = ri.K_s, f.Z_R = ri.Z_R, f.enclosure = ri.enclosure, f.tool = ri.tool;
    f.K_A = ri.K_A, f.K_v_iso = ri.K_v_iso, f.K_Hbeta = ri.K_Hbeta;
    prm.enter_subsection("Gearbox");
    st.input.input_speed = params::get_double(prm, "Input speed");
    const int n = params::get_integer(prm, "Number of stages");
    const std::string source = prm.get("Stress source");
    st.source = source == "table" ? StressSource::table :
                source == "FE"    ? StressSource::fe :
                source == "ISO"   ? StressSource::iso :
                                    StressSource::agma;
    st.reference_torque = params::get_double(prm, "Reference torque");
    prm.leave_subsection();
    require_range("Gearbox/Number of stages", n, 1, max_stages);
    for (int k = 1; k <= n; ++k)
      parse_stage(prm, k, st);
    prm.enter_subsection("Spectrum");
    fatigue::Spectrum &s = st.input.spectrum;
    s.torques = params::get_doubles(prm, "Torques");
    s.revolutions = params::get_doubles(prm, "Revolutions");
    const std::vector<double> hours = params::get_doubles(prm, "Hours");
    s.duration_years = params::get_double(prm, "Duration");
    prm.leave_subsection();
    if (!hours.empty())
      s.revolutions = fatigue::revolutions_from_hours(hours, st.input.input_speed);
    prm.enter_subsection("Lubricant");
    scuffing::Lubricant &o = st.input.oil;
    o.type = prm.get("Oil type");
    o.extreme_pressure = params::get_bool(prm, "Extreme pressure");
    o.nu40 = params::get_double(prm, "Kinematic viscosity at 40 C");
    o.eta40 = params::get_double(prm, "Dynamic viscosity at 40 C") * 1e-3;
    o.eta100 = params::get_double(prm, "Dynamic viscosity at 100 C") * 1e-3;
    st.input.conditions.theta_oil = params::get_double(prm, "Oil temperature");
    st.input.conditions.k_sump = params::get_double(prm, "Sump factor");
    st.input.conditions.points = params::get_integer(prm, "Points along the path");
    prm.leave_subsection();
    // Every check of the library, before anything is computed or written.
    s.check();
    scuffing::check(st.input.conditions, st.input.oil);
    build_train(st.input);
    return st;
  }
} // namespace gearfem::gearbox
