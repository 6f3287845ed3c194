#pragma once
// ParameterHandler bindings of the `Dynamics` section (engineering units at the interface:
// mm, deg, N m, rpm, um, N/(mm um); SI inside DynamicsCase). Compiled into the separate
// target gearfem_dynamics_params so that gearfem_dynamics itself stays free of deal.II.
#include "dynamics/case.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::dynamics
{
  /// Declare every entry of subsection "Dynamics" (with Patterns, units and defaults).
  void declare_parameters(dealii::ParameterHandler &prm);
  /// Read the "Dynamics" section into a DynamicsCase (SI) and check it. Throws InputError
  /// naming "Dynamics/<subsection>/<entry>" for invalid values. Relative paths (STE file)
  /// are resolved against `input_dir`.
  DynamicsCase parse_parameters(dealii::ParameterHandler &prm, const std::string &input_dir = "");
} // namespace gearfem::dynamics
