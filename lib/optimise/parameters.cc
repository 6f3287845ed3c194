// ParameterHandler bindings of `gearfem optimise` (see parameters.h).
#include "optimise/parameters.h"
#include "geometry/parameters.h"
#include "base/units.h"

#include "base/errors.h"
#include "solve/input.h"
#include "optimise/relief_parameters.h"
#include "params/checked.h"
#include "post/parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <sstream>

namespace gearfem::optimise
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  void declare_study_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Optimise");
    prm.declare_entry("Problem", "profile", Selection("profile|tip relief"),
                      "profile: the B-spline tooth of Koronaios 2021 (the entries below, docs/optimise.md); tip relief: "
                      "amount and length of tip relief for minimum STE with the FE model in the loop "
                      "(subsection Tip relief, and the gearfem solve sections Rack ... Solve). Units: none.");
    prm.declare_entry("Case", "case 2", Selection("case 1|case 2"),
                      "Koronaios 2021 case: 1 = pinion rack B-spline (4 free coordinates), objective max + mean "
                      "+ std of |1/R|; 2 = pinion flank B-spline (8 free coordinates), objective "
                      "2.5 int (1/R)^2 dx + std(1/R) + 0.1/eps. Units: none.");
    geometry::declare_teeth_entry(prm, "Pinion teeth", 19, "z1");
    geometry::declare_teeth_entry(prm, "Gear teeth", 55, "z2");
    geometry::declare_module_entry(prm, "Module", 2.5);
    geometry::declare_pressure_angle_entry(prm);
    geometry::declare_addendum_entry(prm, "Addendum coefficient",
                                     "h_a*: tip circles r + h_a* m of both gears; also of the involute reference");
    prm.declare_entry("Dedendum coefficient", "1.25", Double(),
                      "Cutter addendum of the case-2 geometry (the recovered rack must stay above it). "
                      "Units: multiples of the module.");
    prm.declare_entry("Root radius coefficient", "0.25", Double(),
                      "Cutter tip radius of the case-2 geometry. Units: multiples of the module.");
    geometry::declare_face_width_entry(prm, "Face width", 20, "b, written to optimum.prm");
    prm.declare_entry("Samples", "201", Integer(),
                      "Points along the active flank in each evaluation. Units: none. Allowed: 11 to 1e6.");
    prm.declare_entry("Report samples", "2001", Integer(),
                      "Points of the reported statistics and curves. Units: none. Allowed: 11 to 1e6.");
    prm.declare_entry("Minimum contact ratio", "1", Double(),
                      "Constraint eps >= this (eps = rack-displacement range / pitch). Units: none. "
                      "Allowed: 0 to 5.");
    prm.declare_entry("Start radius", "0", Double(),
                      "Start of the sampled pinion range (involute and case 2); 0 = the start of active "
                      "profile. Units: mm.");
    prm.declare_entry("Design checks", "true", Bool(),
                      "Case 2: run gearfem's design checks (GearPair: interference, undercut into the "
                      "active profile, pointed tip) on every evaluation. Units: none.");
    prm.declare_entry("Start point", "", Anything(),
                      "Free coordinates, comma-separated (case 1: u1, u2, v2, u3; case 2: x0, y0, ..., "
                      "x3, y3); empty = the default start (docs/optimise.md). Units: multiples of the module.");
    prm.declare_entry("Fixed end", "tip", Selection("tip|root"),
                      "Case 2: the control point that stays fixed: tip = P4 on the involute just beyond the tip "
                      "circle (P0..P3 free, tip thickness kept); root = P0 of the start fit (P1..P4 free). "
                      "Units: none.");
    prm.declare_entry("Objective weights", "2.5, 1, 0.1", Anything(),
                      "Case 2: w0, w1, w2 of the objective w0 int (1/R)^2 dx + w1 std(1/R) + w2/eps "
                      "(Koronaios 2021: 2.5, 1, 0.1). Units: w0 none (dx in mm), w1 none, w2 1/mm. "
                      "Allowed: each 0 to 1e6, not all zero.");
    declare_relief_parameters(prm);
    prm.leave_subsection();

    prm.enter_subsection("Optimiser");
    prm.declare_entry("Methods", "steepest descent, slsqp, cobyla, isres", Anything(),
                      "Comma-separated, each run from the same start: " + method_names() + ". Units: none.");
    prm.declare_entry("Max evaluations", "3000", Integer(),
                      "Design evaluations per method, finite differences included. Units: none. Allowed: >= 1.");
    prm.declare_entry("Bound", "0.5", Double(),
                      "Box half-width about the start point. Units: multiples of the module. Allowed: (0, 2].");
    prm.declare_entry("Finite-difference step", "1e-6", Double(),
                      "Forward differences of the gradient-based methods. Units: multiples of the module.");
    prm.declare_entry("Relative x tolerance", "1e-8", Double(), "NLopt xtol_rel. Units: none. Allowed: 0 to 1.");
    prm.declare_entry("Relative f tolerance", "1e-10", Double(),
                      "NLopt ftol_rel; steepest descent stops below it. Units: none. Allowed: 0 to 1.");
    prm.declare_entry("Iterations", "100", Integer(), "Steepest descent iterations (thesis: 100). Units: none.");
    prm.declare_entry("Golden-section tolerance", "1e-8", Double(),
                      "Line-search interval (thesis: 1e-8). Units: multiples of the module. Allowed: > 0.");
    prm.declare_entry("Line-search steps", "100", Integer(),
                      "Bracketing and golden-section steps per line search (thesis: 100). Units: none.");
    prm.declare_entry("Seed", "3", Integer(), "Random seed of the global methods. Units: none.");
    prm.declare_entry("Population", "0", Integer(), "Global methods; 0 = NLopt's default. Units: none.");
    prm.declare_entry("Multistart", "0", Integer(),
                      "0 = off; n > 0: 20 n random points of the box are evaluated and each method runs from "
                      "the start point (when feasible) and the n best feasible of them; the start point may "
                      "then be infeasible (it is the centre of the box). Units: none. Allowed: 0 to 1000.");
    prm.leave_subsection();
    // The case the tip-relief problem optimises (`gearfem solve` sections).
    solve::declare_gear_contact_input(prm);
    post::declare_post_parameters(prm);
  }

  bool is_relief_problem(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Optimise");
    const bool r = prm.get("Problem") == "tip relief";
    prm.leave_subsection();
    return r;
  }

  OptimiserSection read_optimiser_section(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Optimiser");
    OptimiserSection r;
    OptimiserSettings &o = r.settings;
    o.max_evaluations    = params::get_integer(prm, "Max evaluations");
    o.bound              = params::get_double(prm, "Bound");
    o.fd_step            = params::get_double(prm, "Finite-difference step");
    o.xtol_rel           = params::get_double(prm, "Relative x tolerance");
    o.ftol_rel           = params::get_double(prm, "Relative f tolerance");
    o.iterations         = params::get_integer(prm, "Iterations");
    o.golden_tolerance   = params::get_double(prm, "Golden-section tolerance");
    o.line_search_steps  = params::get_integer(prm, "Line-search steps");
    const int seed       = params::get_integer(prm, "Seed");
    require_range("Optimiser/Seed", seed, 0, 2147483647);
    o.seed         = static_cast<unsigned int>(seed);
    o.population   = params::get_integer(prm, "Population");
    o.multistart   = params::get_integer(prm, "Multistart");
    r.methods_text = prm.get("Methods");
    prm.leave_subsection();
    std::stringstream methods(r.methods_text);
    for (std::string item; std::getline(methods, item, ',');)
      {
        const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
        if (b != std::string::npos)
          r.methods.push_back(method_from_string(item.substr(b, e - b + 1), "Optimiser/Methods"));
      }
    if (!r.methods.empty())
      o.method = r.methods.front();
    return r;
  }

  Study parse_study_parameters(dealii::ParameterHandler &prm)
  {
    Study s;
    prm.enter_subsection("Optimise");
    s.kind                   = prm.get("Case") == "case 1" ? DesignKind::case1_rack : DesignKind::case2_flank;
    s.pair.z1                = params::get_integer(prm, "Pinion teeth");
    s.pair.z2                = params::get_integer(prm, "Gear teeth");
    s.pair.module            = params::get_double(prm, "Module") * 1e-3;
    s.pair.pressure_angle    = params::get_double(prm, "Pressure angle") * units::deg;
    s.pair.addendum          = params::get_double(prm, "Addendum coefficient");
    s.pair.dedendum          = params::get_double(prm, "Dedendum coefficient");
    s.pair.root_radius       = params::get_double(prm, "Root radius coefficient");
    s.face_width             = params::get_double(prm, "Face width") * 1e-3;
    s.eval.samples           = params::get_integer(prm, "Samples");
    s.report_samples         = params::get_integer(prm, "Report samples");
    s.eval.min_contact_ratio = params::get_double(prm, "Minimum contact ratio");
    s.eval.start_radius      = params::get_double(prm, "Start radius") * 1e-3;
    s.eval.design_checks     = params::get_bool(prm, "Design checks");
    s.start                  = params::get_doubles(prm, "Start point");
    s.fixed_end              = prm.get("Fixed end") == "root" ? FixedEnd::root : FixedEnd::tip;
    const auto w             = params::get_doubles(prm, "Objective weights");
    if (w.size() != 3)
      throw InputError("Optimise/Objective weights", prm.get("Objective weights"), "three numbers w0, w1, w2");
    s.eval.weights = {w[0], w[1], w[2]};
    prm.leave_subsection();

    const OptimiserSection o = read_optimiser_section(prm);
    for (const Method m : o.methods)
      {
        s.runs.push_back(o.settings);
        s.runs.back().method = m;
      }
    check_study(s);
    return s;
  }
} // namespace gearfem::optimise
