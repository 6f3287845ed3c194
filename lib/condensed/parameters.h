#pragma once
#include <string>
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
    /// Largest torque ratio one scene spans (condensed::CycleOptions); 0: no split; < 0
    /// (`auto`): the rule of the cycle's use (condensed::scene_ratio).
    double scene_ratio = -1;
    /// FE-exact T(theta, delta) table (condensed/table.h) written to this file in the output
    /// folder; empty: none.
    std::string table_file;
    int table_compressions = 60;
    double backlash = -1; ///< [m]; < 0: a one-sided table
  };
  void declare_condense_parameters(dealii::ParameterHandler &prm);
  /// InputError naming "Condense/Build torque" for a negative or non-finite value.
  CondenseParameters parse_condense_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::condensed
