// ParameterHandler bindings of the tip-relief problem (see relief_parameters.h).
#include "optimise/relief_parameters.h"

#include "optimise/parameters.h"

#include "base/errors.h"
#include "solve/input.h"
#include "params/checked.h"
#include "post/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>

namespace gearfem::optimise
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  void declare_relief_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Tip relief");
    prm.declare_entry("Kind", "linear", Selection("linear|parabolic"),
                      "Shape of the relief from its start to the tip (as Gear i/Tip relief). Units: none.");
    prm.declare_entry("Variables", "same on both gears", Selection("same on both gears|per gear"),
                      "same on both gears: 2 variables (C_a, L); per gear: 4 (C_a1, L1, C_a2, L2). Units: none.");
    prm.declare_entry("Minimum amount", "0", Double(),
                      "Lower bound of C_a (0 = no relief is a candidate). Units: um. Allowed: 0 to 1000.");
    prm.declare_entry("Maximum amount", "30", Double(),
                      "Upper bound of C_a. Units: um. Allowed: above the minimum, up to 1000.");
    prm.declare_entry("Minimum length", "0.5", Double(),
                      "Lower bound of L, along the line of action from the tip. Units: mm. Allowed: > 0.");
    prm.declare_entry("Maximum length", "8", Double(),
                      "Upper bound of L; the relief must start above the form circle. Units: mm. "
                      "Allowed: above the minimum.");
    prm.declare_entry("Start point", "", Anything(),
                      "C_a [um], L [mm] (and C_a2, L2 per gear), comma-separated, inside the box; empty = "
                      "the middle of the box. Units: um and mm.");
    prm.declare_entry("Objective", "peak-to-peak", Selection("peak-to-peak|first harmonic"),
                      "Measure of the STE cycle at each torque of Solve/Torques: its peak-to-peak, or the "
                      "amplitude of its first mesh harmonic. Units: none.");
    prm.declare_entry("Torque aggregate", "maximum", Selection("maximum|weighted mean"),
                      "How the measures at the torques of Solve/Torques combine into the objective. Units: none.");
    prm.declare_entry("Torque weights", "", Anything(),
                      "Weights of the weighted mean, one per torque of Solve/Torques; empty = equal. "
                      "Units: none. Allowed: >= 0, not all 0.");
    prm.declare_entry("Grid points", "0", Integer(),
                      "Also evaluate a full-factorial grid of this many values per variable over the box on "
                      "the same model (a Harris-map grid, the check of the optimum); 0 = none. Units: none. "
                      "Allowed: 0, 2 to 50.");
    prm.declare_entry("Single-torque optima", "false", Bool(),
                      "Also optimise at each torque of Solve/Torques alone (same method, start and budget, on "
                      "the same model): the single-load optima the robust optimum is compared with. Units: none. "
                      "Allowed: false, or true with 2 or more Solve/Torques.");
    prm.declare_entry("Check torques", "", Anything(),
                      "After the optimisation, evaluate no relief, the optimum, the single-load optima and the "
                      "grid's best at each of these torques on the same model (robust.csv, relief_robust.png); "
                      "comma-separated, empty = none. Units: N m. Allowed: up to 50 torques, each > 0 and "
                      "within the small-strain limit of Solve/Torques.");
    prm.declare_entry("Condensed cycle", "auto", Selection("auto|off"),
                      "auto: evaluate the designs on a condensed cycle of the model (gearfem condense), built once "
                      "over the positions for the torques and check torques: milliseconds per design instead of "
                      "a sweep, within 0.1 % of the full FE (docs/model-choice.md); a design the cycle cannot "
                      "serve falls back to the full sweep (summary). off: a full FE sweep per design. Units: none.");
    prm.leave_subsection();
  }

  namespace
  {
    void read_problem(dealii::ParameterHandler &prm, ReliefProblem &p)
    {
      prm.enter_subsection("Optimise");
      prm.enter_subsection("Tip relief");
      p.kind       = prm.get("Kind") == "parabolic" ? geometry::TipRelief::Kind::parabolic : geometry::TipRelief::Kind::linear;
      p.per_gear   = prm.get("Variables") == "per gear";
      p.amount_min = params::get_double(prm, "Minimum amount") * 1e-6;
      p.amount_max = params::get_double(prm, "Maximum amount") * 1e-6;
      p.length_min = params::get_double(prm, "Minimum length") * 1e-3;
      p.length_max = params::get_double(prm, "Maximum length") * 1e-3;
      p.start      = params::get_doubles(prm, "Start point");
      for (std::size_t i = 0; i < p.start.size(); ++i)
        p.start[i] *= i % 2 == 0 ? 1e-6 : 1e-3;
      p.measure     = prm.get("Objective") == "first harmonic" ? ReliefMeasure::first_harmonic : ReliefMeasure::peak_to_peak;
      p.aggregate   = prm.get("Torque aggregate") == "weighted mean" ? TorqueAggregate::weighted_mean : TorqueAggregate::maximum;
      p.weights     = params::get_doubles(prm, "Torque weights");
      p.grid_points = params::get_integer(prm, "Grid points");
      p.single_torque_optima = params::get_bool(prm, "Single-torque optima");
      p.check_torques        = params::get_torques(prm, "Check torques", "Optimise/Tip relief/Check torques", true);
      prm.leave_subsection();
      prm.leave_subsection();
    }

    bool read_condensed(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Optimise");
      prm.enter_subsection("Tip relief");
      const bool c = prm.get("Condensed cycle") == "auto";
      prm.leave_subsection();
      prm.leave_subsection();
      return c;
    }

    /// The shared Optimiser reader, with this problem's restrictions: exactly one method,
    /// and Bound unused (the box is the problem's), so its value is not checked.
    OptimiserSettings read_optimiser(dealii::ParameterHandler &prm)
    {
      const OptimiserSection section = read_optimiser_section(prm);
      if (section.methods.size() != 1)
        throw InputError("Optimiser/Methods", section.methods_text.empty() ? "(empty)" : section.methods_text,
                         "one of " + method_names(),
                         "Problem = tip relief runs one method (bobyqa or cobyla suit its FE objective)");
      OptimiserSettings o = section.settings;
      o.bound             = OptimiserSettings().bound;
      o.check();
      return o;
    }

    /// Check torques within the small-strain limit that `gearfem solve` applies to
    /// Solve/Torques (contact/parameters.cc): the same check, run on a copy of the case
    /// with these torques, its error re-named to the Check torques entry.
    void check_torques_strain(dealii::ParameterHandler &prm, const std::vector<double> &torques)
    {
      if (torques.empty())
        return;
      std::string list;
      for (const double t : torques)
        list += (list.empty() ? "" : ", ") + to_string_g(t);
      prm.enter_subsection("Solve");
      const std::string saved = prm.get("Torques");
      prm.set("Torques", list);
      prm.leave_subsection();
      std::string error;
      try
        {
          (void)solve::parse_gear_contact_input(prm);
        }
      catch (const InputError &e)
        {
          error = e.what();
        }
      prm.enter_subsection("Solve");
      prm.set("Torques", saved);
      prm.leave_subsection();
      if (!error.empty())
        throw InputError("Optimise/Tip relief/Check torques", list + " N m",
                         "torques > 0 N m within the small-strain limit of the pair", error);
    }
  } // namespace

  ReliefStudy parse_relief_study(dealii::ParameterHandler &prm)
  {
    ReliefStudy s;
    read_problem(prm, s.problem);
    s.condensed = read_condensed(prm);
    s.optimiser = read_optimiser(prm);
    s.geometry  = geometry::parse_geometry_parameters(prm);
    auto input  = std::make_shared<solve::GearContactInput>(solve::parse_gear_contact_input(prm));
    input->require_external("the tip-relief optimiser");
    const auto &sv = input->solve;
    if (sv.positions != solve::SolveParameters::Positions::cycle)
      throw InputError("Solve/Positions", sv.positions == solve::SolveParameters::Positions::named ? "named" : "list",
                       "cycle", "the objective is a measure of the STE over one mesh cycle");
    if (std::abs(sv.pitches - 1.0) > 1e-12)
      throw InputError("Solve/Pitches", to_string_g(sv.pitches), "1", "the objective is measured over one mesh cycle");
    s.problem.torques   = sv.torques;
    s.problem.positions = sv.n_positions;
    s.problem.check();
    check_relief_geometry(s.geometry, s.problem);
    check_torques_strain(prm, s.problem.check_torques);
    (void)post::parse_post_parameters(prm);
    s.input = input;
    // optimum.prm: the study's `gearfem solve` sections with the relief of the design.
    std::ostringstream text;
    prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
    const ReliefProblem problem = s.problem;
    s.solve_case = [case_text = text.str(), problem](const std::vector<double> &x) {
      dealii::ParameterHandler out;
      solve::declare_gear_contact_input(out);
      post::declare_post_parameters(out);
      out.parse_input_from_string(case_text, "", true); // skips the Optimise and Optimiser sections
      for (int i = 0; i < 2; ++i)
        {
          const int  k = problem.per_gear ? 2 * i : 0;
          const bool r = x.at(k) >= 1e-9;
          out.enter_subsection(i == 0 ? "Gear 1" : "Gear 2");
          out.set("Tip relief", !r ? "none" : problem.kind == geometry::TipRelief::Kind::linear ? "linear" : "parabolic");
          out.set("Tip relief amount", to_string_g(r ? x[k] * 1e6 : 0.0));
          out.set("Tip relief length", to_string_g(r ? x[k + 1] * 1e3 : 0.0));
          out.set("Tip relief roll angle", "0");
          out.leave_subsection();
        }
      // The optimiser's route: `gearfem solve` of this file reproduces its STE.
      out.enter_subsection("Contact");
      out.set("Micro-geometry", "gap");
      out.leave_subsection();
      std::ostringstream o;
      out.print_parameters(o, dealii::ParameterHandler::ShortPRM);
      return o.str();
    };
    return s;
  }
} // namespace gearfem::optimise
