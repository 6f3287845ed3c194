#pragma once
// ParameterHandler binding of the `Condense` section (gearfem condense).
namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::condensed
{
  struct CondenseParameters
  {
    /// Pinion torque of the build solves [N m]; 0: the largest of Solve/Torques.
    double build_torque = 0;
    /// Torques a re-solve may take [N m]; 0: a quarter of the smallest and twice the
    /// largest of Solve/Torques.
    double torque_lo = 0, torque_hi = 0;
  };
  void declare_condense_parameters(dealii::ParameterHandler &prm);
  /// InputError naming "Condense/Build torque" for a negative or non-finite value.
  CondenseParameters parse_condense_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::condensed
