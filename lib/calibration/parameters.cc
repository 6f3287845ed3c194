// The `Calibration` section of `gearfem calibrate` (deal.II ParameterHandler binding of the
// calibration stage). Engineering units at the interface (mm, um), SI in the structs.
#include "calibration/parameters.h"

#include "base/errors.h"
#include "base/number.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <set>

namespace gearfem::calibration
{
  void declare_calibration_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Calibration");
    prm.declare_entry("Results files", "", Anything(),
                      "Comma-separated results.h5 files of `gearfem solve` for this pair (relative "
                      "to the input file). Units: none.");
    prm.declare_entry("Condensed cycle", "", Anything(),
                      "condensed.h5 of `gearfem condense` for this pair (relative to this file; empty: none): the "
                      "FE STE at `Cycle torques` is re-solved on the stored cycle (about 1 ms per position, within "
                      "0.1 % of the full FE; docs/model-choice.md) and fitted with the positions of `Results files`, "
                      "if any. Units: none.");
    params::declare_torques(prm, "Cycle torques", "",
                            "Pinion torques at which the condensed cycle is sampled, within the range it was built "
                            "for (its Condense/Torque range); empty: 6 torques spread geometrically over that range.");
    prm.declare_entry("Model", "weber-cornell", Selection("weber-cornell|potential-energy"),
                      "Analytical pair compliance that is calibrated. Units: none.");
    prm.declare_entry("Fit factors", "beam, hertz, body, corner",
                      MultipleSelection("beam|foundation|hertz|body|corner|extended"),
                      "Factors the fit may change: multipliers on the beam, foundation and Hertz "
                      "compliances, a series body compliance, and the effective radius of the tip "
                      "corners in the Hertz term of the corner contact (`corner`; `extended` is its "
                      "former name, kept for old inputs). Units: none.");
    prm.declare_entry("Corner contact", "true", Bool(),
                      "Corner contact OA/BΓ outside the path A..E with the exact rigid gap of the "
                      "tip corners (lib/analytical/corner.h). Units: none.");
    prm.declare_entry("Corner radius", "0.1", Double(),
                      "Radius of curvature of the tip corners in the Hertz term of a corner contact "
                      "(the start value when `corner` is fitted); 0: the tip rounding of the geometry, "
                      "or the involute radii at the path end for sharp teeth. Units: mm. Allowed: >= 0.");
    prm.declare_entry("Table positions", "200", Integer(), "Roll angles over one pitch in the tables. Units: none. Allowed: >= 8.");
    prm.declare_entry("Table loads", "50", Integer(), "Load (or compression) points in the tables. Units: none. Allowed: >= 4.");
    prm.declare_entry("Table load factor", "2", Double(),
                      "Largest table load over the largest FE load. Units: none. Allowed: >= 1.");
    prm.declare_entry("Backlash", "-1", Double(),
                      "Total clearance b along the line of action for a two-sided T(theta, delta) "
                      "table (format version 2): T = 0 on [-b, 0] and the reverse-flank branch "
                      "below -b (coast flanks mapped onto the drive flanks, b shared equally by "
                      "the two gears); < 0: a one-sided table (delta >= 0). Units: um.");
    prm.leave_subsection();
  }

  Input parse_calibration_parameters(dealii::ParameterHandler &prm)
  {
    Input in;
    prm.enter_subsection("Calibration");
    in.files = dealii::Utilities::split_string_list(prm.get("Results files"), ',');
    in.cycle = dealii::Utilities::trim(prm.get("Condensed cycle"));
    in.cycle_torques = params::get_torques(prm, "Cycle torques", "Calibration/Cycle torques", true);
    in.model = prm.get("Model");
    const auto fit_set = dealii::Utilities::split_string_list(prm.get("Fit factors"), ',');
    const bool corner  = params::get_bool(prm, "Corner contact");
    const double rho0  = params::get_double(prm, "Corner radius") * 1e-3;
    auto &g            = in.options.grid;
    g.n_theta          = params::get_integer(prm, "Table positions");
    g.n_load           = params::get_integer(prm, "Table loads");
    g.load_factor      = params::get_double(prm, "Table load factor");
    const double b_um  = params::get_double(prm, "Backlash");
    g.backlash         = b_um >= 0 ? b_um * 1e-6 : -1.0;
    prm.leave_subsection();
    if (in.files.empty() && in.cycle.empty())
      throw InputError("Calibration/Results files", "(empty)",
                       "at least one results.h5 of `gearfem solve`, or a Calibration/Condensed cycle");
    if (!in.cycle_torques.empty() && in.cycle.empty())
      throw InputError("Calibration/Cycle torques", "(set)", "empty without a Calibration/Condensed cycle");
    if (!(rho0 >= 0))
      throw InputError("Calibration/Corner radius", to_string_g(rho0 * 1e3) + " mm", ">= 0");
    if (g.n_theta < 8)
      throw InputError("Calibration/Table positions", std::to_string(g.n_theta), ">= 8");
    if (g.n_load < 4)
      throw InputError("Calibration/Table loads", std::to_string(g.n_load), ">= 4");
    if (!(g.load_factor >= 1))
      throw InputError("Calibration/Table load factor", to_string_g(g.load_factor), ">= 1");
    std::set<std::string> fs(fit_set.begin(), fit_set.end());
    auto &mask = in.options.mask;
    mask.beam = fs.count("beam"), mask.foundation = fs.count("foundation"), mask.hertz = fs.count("hertz");
    mask.body = fs.count("body"), mask.corner_radius = fs.count("corner") || fs.count("extended");
    if (mask.corner_radius && !corner)
      throw InputError("Calibration/Fit factors", "corner", "no `corner` without corner contact",
                       "Calibration/Corner contact is false");
    if (mask.corner_radius && !(rho0 > 0))
      throw InputError("Calibration/Corner radius", "0 mm", "> 0 when `corner` is fitted (the start value)");
    in.options.start.corner        = corner;
    in.options.start.corner_radius = rho0;
    return in;
  }
} // namespace gearfem::calibration
