// `Condense` section.
#include "condensed/parameters.h"

#include "base/errors.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace gearfem::condensed
{
  void declare_condense_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Condense");
    prm.declare_entry("Build torque", "0", dealii::Patterns::Double(),
                      "Pinion torque at which the condensed cycle is solved and linearised. The stored "
                      "candidates are the slave nodes within Contact/Search distance of the mating flank "
                      "there; re-solves far above it may reach their edge and are then refused. Units: N m. "
                      "Allowed: >= 0; 0 takes the largest of Solve/Torques.");
    prm.declare_entry("Torque range", "0, 0", dealii::Patterns::List(dealii::Patterns::Double(), 2, 2),
                      "Lowest and highest pinion torque a re-solve on the cycle may take. Which body is the slave "
                      "of a tooth pair near a tip corner depends on the load; the cycle stores every such scene of "
                      "this range (each solved at the build torque clamped into its own range), and refuses "
                      "torques outside it. Units: N m. Allowed: 0 < low <= build torque <= high; 0, 0 takes a "
                      "quarter of the smallest and twice the largest of Solve/Torques.");
    prm.declare_entry("Scene torque ratio", "auto", dealii::Patterns::Anything(),
                      "The condensation is exact at the load it was solved at, and its error grows with the "
                      "ratio of a re-solve's torque to that load (the candidates' projections and the tip-corner "
                      "rounding enter only through the gap's curvature). The torque range is cut at build torque x "
                      "ratio^(j + 1/2) and each part solved at the build torque or at its geometric middle: no "
                      "re-solve is more than sqrt(ratio) from its build (ratio 4: within 0.1 % of the full FE on the "
                      "three pairs of validation/speed_vs_error). Each part costs one more solve per position. "
                      "auto: 4, except for the transverse section of gearfem helical, which is not split (its "
                      "slices move by at most 2e-4 against ratio 4 on validation/helical, for a third of the build). "
                      "Units: none. Allowed: auto, 0 (no split: one build per slave configuration) or 1.5 to 1e6.");
    prm.declare_entry("Table file", "", dealii::Patterns::Anything(),
                      "Also write the FE-exact mesh torque table T(theta, delta) (docs/mesh-tables.md) to this file "
                      "in the output folder: contact solves on the cycle under rotation control at each position "
                      "(the theta axis: Solve/Positions must be one pitch of equally spaced roll angles) and "
                      "compression, up to the compression every position reaches at the top of the torque range. "
                      "Empty: no table. Units: none.");
    prm.declare_entry("Table compressions", "60", dealii::Patterns::Integer(),
                      "Compressions of the table's drive side, 0 included. Units: none. Allowed: >= 4.");
    prm.declare_entry("Backlash", "-1", dealii::Patterns::Double(),
                      "Total clearance b along the line of action of a two-sided table (format version 2: "
                      "T = 0 on [-b, 0], the reverse flank below -b as the calibrated tables map it); < 0: a "
                      "one-sided table. Units: um.");
    prm.leave_subsection();
  }

  CondenseParameters parse_condense_parameters(dealii::ParameterHandler &prm)
  {
    CondenseParameters p;
    prm.enter_subsection("Condense");
    p.build_torque = params::get_double(prm, "Build torque");
    const auto range = params::get_doubles(prm, "Torque range");
    p.torque_lo = range.at(0), p.torque_hi = range.at(1);
    const std::string ratio = dealii::Utilities::trim(prm.get("Scene torque ratio"));
    p.scene_ratio           = ratio == "auto" ? -1.0 : params::get_double(prm, "Scene torque ratio");
    p.table_file         = dealii::Utilities::trim(prm.get("Table file"));
    p.table_compressions = params::get_integer(prm, "Table compressions");
    const double b_um    = params::get_double(prm, "Backlash");
    p.backlash           = b_um >= 0 ? b_um * 1e-6 : -1.0;
    prm.leave_subsection();
    require_range("Condense/Build torque", p.build_torque, 0.0, 1e9, "N m");
    require_range("Condense/Torque range", p.torque_lo, 0.0, 1e9, "N m");
    require_range("Condense/Torque range", p.torque_hi, 0.0, 1e9, "N m");
    if (ratio != "auto" && !(p.scene_ratio == 0 || (p.scene_ratio >= 1.5 && p.scene_ratio <= 1e6)))
      throw InputError("Condense/Scene torque ratio", ratio, "auto, 0 (no split) or 1.5 to 1e6");
    if (p.table_compressions < 4)
      throw InputError("Condense/Table compressions", std::to_string(p.table_compressions), ">= 4");
    if (!std::isfinite(b_um) || b_um > 1e4)
      throw InputError("Condense/Backlash", to_string_g(b_um), "< 0 (one-sided) or [0, 1e4] um");
    if (p.table_file.find('/') != std::string::npos)
      throw InputError("Condense/Table file", p.table_file, "a file name (written in the output folder)");
    return p;
  }
} // namespace gearfem::condensed
