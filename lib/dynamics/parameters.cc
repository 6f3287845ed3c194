#include "dynamics/parameters.h"

#include "base/errors.h"
#include "params/checked.h"
#include "base/table.h"
#include "base/units.h"
#include "geometry/parameters.h"
#include "io/solve_results.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>

namespace gearfem::dynamics
{
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;

  namespace
  {

    /// The STE curve of the STE law from a CSV file: either two columns (position [deg],
    /// STE [um]) or the sweep.csv of `gearfem solve`, whose rows at the case's input torque
    /// give STE(theta) and, from F_n / STE, the mean mesh stiffness kbar.
    void read_ste(DynamicsCase &c, const std::string &file, const std::vector<std::vector<double>> &rows,
                  const std::vector<std::string> &headers)
    {
      using namespace gearfem::units;
      const std::string entry = "Dynamics/Mesh force/STE file";
      auto column = [&](const std::string &h) {
        const auto it = std::find(headers.begin(), headers.end(), h);
        return it == headers.end() ? -1 : int(it - headers.begin());
      };
      const int ct = column(io::sweep_column::torque), ca = column(io::sweep_column::roll_angle),
                cs = column(io::sweep_column::ste), cf = column(io::sweep_column::normal_force);
      const bool fe = ct >= 0 && ca >= 0 && cs >= 0 && cf >= 0;
      std::string torques;
      double F = 0, d = 0;
      for (const auto &row : rows)
        {
          if (!fe)
            {
              if (row.size() < 2)
                throw InputError(entry, file, ">= 2 columns: position [deg], STE [um]");
              c.ste_theta.push_back(row[0] * deg);
              c.ste_values.push_back(row[1] * um);
              continue;
            }
          if (row.size() != headers.size())
            throw InputError(entry, file, std::to_string(headers.size()) + " columns in every row");
          if (std::abs(row[ct] - c.input_torque) > 1e-9 * std::max(1.0, c.input_torque))
            {
              if (torques.find(to_string_g(row[ct]) + " ") == std::string::npos)
                torques += to_string_g(row[ct]) + " ";
              continue;
            }
          c.ste_theta.push_back(row[ca] * deg);
          c.ste_values.push_back(row[cs] * um);
          F += row[cf], d += row[cs] * um;
        }
      if (fe && c.ste_theta.size() < 2)
        throw InputError(entry, file, "a sweep at Dynamics/Operating/Input torque = " + to_string_g(c.input_torque) +
                                        " N m (the file has torques " + (torques.empty() ? "none" : torques) + "N m)");
      if (fe)
        c.ste_stiffness = F / d; // mean F_n over mean STE: the FE mean mesh stiffness [N/m]
    }
  } // namespace

  void declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Dynamics");
    prm.declare_entry("Model", "torsional", Selection("DTE|torsional|Kahraman-Singh"),
                      "DTE: 1-DOF relative model with a speed source; torsional: 2-DOF model "
                      "(Gkimisis 2019, 4.1-4.2); Kahraman-Singh: the dimensionless 1-DOF form "
                      "(Kahraman & Singh 1990).");
    prm.declare_entry("Analysis", "response", Selection("response|sweep|both"),
                      "Time response at the pinion speed, up/down speed sweep, or both.");

    prm.enter_subsection("Pair");
    geometry::declare_teeth_entry(prm, "Pinion teeth", 20, "z1");
    geometry::declare_teeth_entry(prm, "Gear teeth", 40, "z2");
    geometry::declare_module_entry(prm, "Module", 2.5);
    geometry::declare_pressure_angle_entry(prm);
    geometry::declare_addendum_entry(prm, "Addendum coefficient", "h_a/m of the standard rack of both gears");
    geometry::declare_face_width_entry(prm, "Face width", 30);
    prm.declare_entry("Pinion thickness coefficient", "0.5", Double(0.3, 0.6),
                      "C_f: tooth thickness at the reference circle / (pi m) [-]; 0.5 is "
                      "backlash-free (Gkimisis 2019 uses 0.49).");
    prm.declare_entry("Gear thickness coefficient", "0.5", Double(0.3, 0.6), "As above, gear [-].");
    prm.declare_entry("Centre distance change", "0", Double(-10, 10),
                      "Operating centre distance minus m (z1 + z2)/2. Units: mm.");
    prm.declare_entry("Backlash", "-1", Double(),
                      "Normal backlash along the line of action; < 0: from the pair (Gkimisis 2019 "
                      "eq. 2.52). Units: um.");
    prm.declare_entry("Density", "7850", Double(0), "Units: kg/m^3.");
    prm.declare_entry("Young modulus", "206", Double(1), "E (analytical table law). Units: GPa. Allowed: 0.1 to 1500.");
    prm.declare_entry("Poisson ratio", "0.3", Double(0, 0.5), "nu (analytical table law) [-].");
    prm.declare_entry("Pinion inertia", "0", Double(0),
                      "I1; 0: solid cylinder of the pitch diameter. Units: kg m^2.");
    prm.declare_entry("Gear inertia", "0", Double(0), "I2; 0: as above. Units: kg m^2.");
    prm.leave_subsection();

    prm.enter_subsection("Mesh force");
    prm.declare_entry("Law", "piecewise constant",
                      Selection("piecewise constant|Fourier|STE|analytical table|table file|Ricker"),
                      "piecewise constant: k_single / k_double zones from the contact ratio; "
                      "Fourier: kbar (1 + sum a_n cos(n z1 theta) + b_n sin); STE: kbar (delta - "
                      "e(theta)); analytical table: Gkimisis 2019 torque table T(theta, delta) of the "
                      "Weber/Cornell model (lib/analytical) on the generated pair; table file: an "
                      "HDF5 mesh table T(theta, delta) or k(theta, F) (docs/mesh-tables.md, e.g. "
                      "mesh_torque.h5 of gearfem calibrate); Ricker: Gkimisis 2019 semi-analytical "
                      "pair stiffness with Ricker-wavelet load sharing (eqs. 3.18-3.46).");
    prm.declare_entry("Theta interpolation", "linear", Selection("linear|monotone cubic"),
                      "Table laws: bilinear, or monotone cubic (Fritsch-Carlson) in theta [-].");
    prm.declare_entry("Single-pair stiffness", "14", Double(0),
                      "c' per unit face width (ISO 6336-1 rule of thumb 14). Units: N/(mm um).");
    prm.declare_entry("Double-pair factor", "1.75", Double(1, 3),
                      "k_double / k_single [-]; 1.75 makes the mean equal to ISO c_gamma_alpha.");
    prm.declare_entry("Fourier cosine coefficients", "-0.1", List(Double()),
                      "a_n relative to kbar [-]; kbar = c'(0.75 eps + 0.25) b (ISO c_gamma_alpha).");
    prm.declare_entry("Fourier sine coefficients", "", List(Double()), "b_n relative to kbar [-].");
    prm.declare_entry("Reverse-flank mapping", "true", Bool(),
                      "Back contact at theta_r = thickness angle - theta (Gkimisis 2019, 4.11) [-].");
    prm.declare_entry("STE file", "", dealii::Patterns::Anything(),
                      "Law = STE: CSV with a header line, either two columns (mesh position [deg], "
                      "STE [um] over one mesh period) or the sweep.csv of gearfem solve (its rows at "
                      "the Input torque; kbar = mean F_n / mean STE of those rows).");
    prm.declare_entry("Table file", "", dealii::Patterns::Anything(),
                      "Law = table file: HDF5 mesh table (relative paths from the input file's "
                      "folder). Its period must be 2 pi/z1 and its base radius r_b1 of this pair.");
    prm.declare_entry("Table geometry hash", "", dealii::Patterns::Anything(),
                      "Law = table file: the geometry hash the table must carry (the FE run's "
                      "geometry fingerprint); empty: not checked (the hash is printed).");
    prm.declare_entry("Ricker widening", "2", Double(0),
                      "Law = Ricker: c_x, widening of the double-contact zone with the "
                      "compression (Gkimisis 2019 eq. 3.42, thesis: about 2). Units: deg/mm.");
    prm.declare_entry("Ricker second pair", "thesis", Selection("thesis|centred"),
                      "Law = Ricker: neighbour pair of eq. 3.36 switched at the pitch point "
                      "(eq. 3.45 as printed) or at the centre of AB (continuous force) [-].");
    prm.leave_subsection();

    prm.enter_subsection("Operating");
    prm.declare_entry("Input torque", "100", Double(0), "T_in on the pinion. Units: N m.");
    prm.declare_entry("Output torque", "-1", Double(),
                      "T_out on the gear; < 0: balanced, T_in r_b2 / r_b1. Units: N m.");
    prm.declare_entry("Pinion speed", "1528", Double(0), "Units: rpm.");
    prm.declare_entry("Torque ramp time", "0", Double(0), "Linear start-up ramp. Units: ms.");
    prm.declare_entry("Speed source", "false", Bool(), "Impose the pinion speed (2-DOF model) [-].");
    prm.declare_entry("Damping ratio", "0.02", Double(),
                      "zeta: c = 2 zeta sqrt(kbar m_eq) [-]. Allowed: 0 to 1; > 0 with a speed sweep (an "
                      "undamped sweep never settles).");
    prm.declare_entry("Damping only in contact", "false", Bool(), "[-]");
    prm.declare_entry("Tooth mass", "false", Bool(),
                      "Add the equivalent tooth inertia of the NTUA tooth-mass thesis (eqs. 3.1-3.6: m_eq "
                      "along the path of contact of the generated pair, J_t = sum m_eq r^2 over the pairs "
                      "in contact) [-].");
    prm.declare_entry("Tooth mass weighting", "linear", Selection("linear|quadratic"),
                      "linear: (delta/delta0) as in the NTUA tooth-mass thesis, with delta(y) = delta_f + "
                      "(y/Y) delta_b below the load height Y and delta0 above; quadratic: (delta/delta0)^2 "
                      "(kinetic-energy equivalence) [-].");
    prm.declare_entry("Tooth inertia", "constant", Selection("constant|position dependent"),
                      "With Tooth mass: the mean of J_t over a mesh period added to the inertias, or "
                      "J_t(theta) in the equations of motion with the 1/2 J'(theta) theta'^2 terms "
                      "(torsional model only) [-].");
    prm.declare_entry("Start from rest deflection", "false", Bool(),
                      "true: delta(0) = 0 (zero initial conditions); false: static deflection [-].");
    prm.leave_subsection();

    prm.enter_subsection("Kahraman-Singh");
    prm.declare_entry("Damping ratio", "0.05", Double(),
                      "zeta [-]. Allowed: 0 to 1; > 0 with a speed sweep (an undamped sweep never settles).");
    prm.declare_entry("Mean force", "0.1", Double(0), "F_m [-].");
    prm.declare_entry("Cosine coefficients", "-0.2, -0.1, -0.05", List(Double()), "k(t) = 1 + sum a_n cos(n W t) [-].");
    prm.declare_entry("Frequency", "0.9", Double(0), "Omega of the time response [-].");
    prm.leave_subsection();

    prm.enter_subsection("Integrator");
    prm.declare_entry("Method", "RK4", Selection("RK4|DOPRI5|SDIRK3"), "Stepper.");
    prm.declare_entry("Steps per period", "128", Integer(), "Fixed-step methods: steps per mesh period [-]. Allowed: 1 to 1e6.");
    prm.declare_entry("Relative tolerance", "1e-8", Double(), "DOPRI5 [-]. Allowed: 1e-14 to 1e-2.");
    prm.declare_entry("Absolute tolerance", "1e-14", Double(),
                      "DOPRI5; state units (m, m/s, rad; dimensionless in Kahraman-Singh mode). Allowed: > 0 "
                      "and <= 1e-3 (looser steps let the contact events chatter).");
    prm.declare_entry("Event location", "true", Bool(), "Locate contact and stiffness events [-].");
    prm.declare_entry("Event tolerance", "1e-12", Double(),
                      "Units: s (dimensionless in KS mode). Allowed: > 0 and <= 1e-3.");
    prm.declare_entry("Wall time limit", "3600", Double(),
                      "Cap of the whole run (response or sweep): beyond it the run ends with a solver failure "
                      "(exit 3) naming this entry. Units: s. Allowed: 0 (none) to 1e7.");
    prm.leave_subsection();

    prm.enter_subsection("Analysis");
    prm.declare_entry("Periods per speed", "300", Integer(), "Transient + record, at most [-]. Allowed: 1 to 100000 (settles any damping ratio >= 1e-4).");
    prm.declare_entry("Recorded periods", "32", Integer(), "Steady-state record [-]. Allowed: 1 to Periods per speed; Recorded periods x Samples per period <= 1e7.");
    prm.declare_entry("Samples per period", "64", Integer(), "Output samples per mesh period [-]. Allowed: 4 to 10000.");
    prm.declare_entry("Steady-state tolerance", "1e-5", Double(),
                      "Poincare-sample change relative to the response scale [-].");
    prm.declare_entry("Sweep minimum speed", "500", Double(),
                      "Pinion speed. Units: rpm (Omega [-] in Kahraman-Singh mode).");
    prm.declare_entry("Sweep maximum speed", "10000", Double(), "Units: rpm (Omega [-] in KS mode).");
    prm.declare_entry("Number of speeds", "100", Integer(), "Per direction [-]. Allowed: 2 to 100000.");
    prm.declare_entry("Threads", "2", Integer(), "Threads for the up/down sweeps [-]. Allowed: 1 to 1024.");
    prm.declare_entry("Portrait speeds", "", List(Double(0)),
                      "Extra time responses at these pinion speeds, each from the static state: "
                      "phase portrait, Poincare section and spectrum per speed (portrait_<k>_*.csv, "
                      "portraits.png). Units: rpm (Omega [-] in Kahraman-Singh mode).");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  DynamicsCase parse_parameters(dealii::ParameterHandler &prm, const std::string &input_dir)
  {
    using namespace gearfem::units;
    DynamicsCase c;
    prm.enter_subsection("Dynamics");
    const std::string model = prm.get("Model");
    c.model = model == "DTE" ? ModelKind::dte :
              (model == "torsional" ? ModelKind::torsional : ModelKind::kahraman_singh);
    const std::string analysis = prm.get("Analysis");
    c.run_response = analysis != "sweep";
    c.run_sweep = analysis != "response";

    prm.enter_subsection("Pair");
    c.z1 = params::get_integer(prm, "Pinion teeth");
    c.z2 = params::get_integer(prm, "Gear teeth");
    c.module = params::get_double(prm, "Module") * mm;
    c.alpha = params::get_double(prm, "Pressure angle") * deg;
    c.addendum = params::get_double(prm, "Addendum coefficient");
    c.face_width = params::get_double(prm, "Face width") * mm;
    c.thickness1 = params::get_double(prm, "Pinion thickness coefficient");
    c.thickness2 = params::get_double(prm, "Gear thickness coefficient");
    c.delta_a = params::get_double(prm, "Centre distance change") * mm;
    const double b = params::get_double(prm, "Backlash");
    c.backlash = b < 0 ? -1.0 : b * um;
    c.density = params::get_double(prm, "Density");
    c.youngs_modulus = params::get_double(prm, "Young modulus") * GPa;
    c.poisson_ratio = params::get_double(prm, "Poisson ratio");
    c.inertia1 = params::get_double(prm, "Pinion inertia");
    c.inertia2 = params::get_double(prm, "Gear inertia");
    prm.leave_subsection();

    prm.enter_subsection("Mesh force");
    const std::string law = prm.get("Law");
    c.law = law == "Fourier" ? LawKind::fourier :
            law == "STE"     ? LawKind::ste :
            (law == "analytical table" || law == "table file" || law == "Ricker") ?
                               LawKind::external :
                               LawKind::piecewise_constant;
    c.external_source = law == "table file" ? ExternalSource::table_file :
                        law == "Ricker"     ? ExternalSource::ricker :
                                              ExternalSource::analytical_table;
    c.theta_interpolation = prm.get("Theta interpolation") == "linear" ?
                              ThetaInterpolation::linear :
                              ThetaInterpolation::monotone_cubic;
    c.single_pair_stiffness = params::get_double(prm, "Single-pair stiffness") * N_per_mm_um;
    c.double_pair_factor = params::get_double(prm, "Double-pair factor");
    c.fourier_cos = params::get_doubles(prm, "Fourier cosine coefficients");
    c.fourier_sin = params::get_doubles(prm, "Fourier sine coefficients");
    c.reverse_mapping = params::get_bool(prm, "Reverse-flank mapping");
    const std::string ste = prm.get("STE file");
    std::vector<std::vector<double>> ste_rows;
    std::vector<std::string> ste_headers;
    std::filesystem::path ste_path(ste);
    if (c.law == LawKind::ste)
      {
        if (ste_path.is_relative() && !input_dir.empty())
          ste_path = std::filesystem::path(input_dir) / ste_path;
        if (ste.empty() || !std::filesystem::is_regular_file(ste_path))
          throw InputError("Dynamics/Mesh force/STE file", ste.empty() ? "(empty)" : ste_path.string(),
                           "an existing CSV file: position [deg], STE [um], or sweep.csv of gearfem solve");
        try
          {
            ste_rows = read_csv_numbers(ste_path, &ste_headers);
          }
        catch (const std::exception &e)
          {
            throw InputError("Dynamics/Mesh force/STE file", ste_path.string(),
                             "a CSV file of numbers with one header line", e.what());
          }
      }
    const std::string table = prm.get("Table file");
    c.table_hash = prm.get("Table geometry hash");
    if (c.law == LawKind::external && c.external_source == ExternalSource::table_file)
      {
        std::filesystem::path f(table);
        if (f.is_relative() && !input_dir.empty())
          f = std::filesystem::path(input_dir) / f;
        if (table.empty() || !std::filesystem::is_regular_file(f))
          throw InputError("Dynamics/Mesh force/Table file", table.empty() ? "(empty)" : f.string(),
                           "an existing HDF5 mesh-table file (docs/mesh-tables.md; gearfem "
                           "calibrate writes mesh_torque.h5 and mesh_stiffness.h5)");
        c.table_file = f.string();
      }
    c.ricker_widening = params::get_double(prm, "Ricker widening") * deg / mm;
    c.ricker_centred = prm.get("Ricker second pair") == "centred";
    prm.leave_subsection();

    prm.enter_subsection("Operating");
    c.input_torque = params::get_double(prm, "Input torque");
    c.output_torque = params::get_double(prm, "Output torque");
    c.speed = params::get_double(prm, "Pinion speed") * rpm;
    c.ramp_time = params::get_double(prm, "Torque ramp time") * 1e-3;
    c.speed_source = params::get_bool(prm, "Speed source");
    c.zeta = params::get_double(prm, "Damping ratio");
    c.damping_only_in_contact = params::get_bool(prm, "Damping only in contact");
    c.tooth_mass = params::get_bool(prm, "Tooth mass");
    c.tooth_mass_energy_weighting = prm.get("Tooth mass weighting") == "quadratic";
    c.tooth_inertia_position_dependent = prm.get("Tooth inertia") == "position dependent";
    c.start_at_rest_deflection = params::get_bool(prm, "Start from rest deflection");
    prm.leave_subsection();

    if (c.law == LawKind::ste)
      read_ste(c, ste_path.string(), ste_rows, ste_headers);

    prm.enter_subsection("Kahraman-Singh");
    c.ks_zeta = params::get_double(prm, "Damping ratio");
    c.ks_force = params::get_double(prm, "Mean force");
    c.ks_cos = params::get_doubles(prm, "Cosine coefficients");
    c.ks_frequency = params::get_double(prm, "Frequency");
    prm.leave_subsection();

    prm.enter_subsection("Integrator");
    c.integrator.method = method_from_string(prm.get("Method"));
    c.integrator.adaptive = true;
    c.response.steps_per_period = params::get_integer(prm, "Steps per period");
    c.integrator.rtol = params::get_double(prm, "Relative tolerance");
    c.integrator.atol = params::get_double(prm, "Absolute tolerance");
    c.integrator.locate_events = params::get_bool(prm, "Event location");
    c.integrator.event_tolerance = params::get_double(prm, "Event tolerance");
    c.integrator.wall_limit = params::get_double(prm, "Wall time limit");
    if (c.integrator.method != Method::dopri5)
      require_greater("Dynamics/Integrator/Steps per period", c.response.steps_per_period, 0.0);
    c.integrator.step = c.model == ModelKind::kahraman_singh ? 1e-2 : 1e-6; // first trial step
    prm.leave_subsection();

    prm.enter_subsection("Analysis");
    c.response.max_periods = params::get_integer(prm, "Periods per speed");
    c.response.record_periods = params::get_integer(prm, "Recorded periods");
    c.response.samples_per_period = params::get_integer(prm, "Samples per period");
    c.response.steady_tolerance = params::get_double(prm, "Steady-state tolerance");
    const double f = c.model == ModelKind::kahraman_singh ? 1.0 : rpm;
    c.sweep_min = params::get_double(prm, "Sweep minimum speed") * f;
    c.sweep_max = params::get_double(prm, "Sweep maximum speed") * f;
    c.sweep_points = params::get_integer(prm, "Number of speeds");
    c.threads = params::get_integer(prm, "Threads");
    for (const double w : params::get_doubles(prm, "Portrait speeds"))
      {
        if (!(w > 0))
          throw InputError("Dynamics/Analysis/Portrait speeds", to_string_g(w), "> 0");
        c.portrait_speeds.push_back(w * f);
      }
    prm.leave_subsection();
    prm.leave_subsection();
    c.check();
    return c;
  }
} // namespace gearfem::dynamics
