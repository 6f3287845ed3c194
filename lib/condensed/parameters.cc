// `Condense` section.
#include "condensed/parameters.h"

#include "base/errors.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

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
    prm.leave_subsection();
  }

  CondenseParameters parse_condense_parameters(dealii::ParameterHandler &prm)
  {
    CondenseParameters p;
    prm.enter_subsection("Condense");
    p.build_torque = params::get_double(prm, "Build torque");
    const auto range = params::get_doubles(prm, "Torque range");
    p.torque_lo = range.at(0), p.torque_hi = range.at(1);
    prm.leave_subsection();
    require_range("Condense/Build torque", p.build_torque, 0.0, 1e9, "N m");
    require_range("Condense/Torque range", p.torque_lo, 0.0, 1e9, "N m");
    require_range("Condense/Torque range", p.torque_hi, 0.0, 1e9, "N m");
    return p;
  }
} // namespace gearfem::condensed
