#pragma once
// ParameterHandler bindings of the tip-relief problem of `gearfem optimise`
// (`Optimise/Problem = tip relief`): the subsection `Optimise/Tip relief`, and the study read
// from it, `Optimiser` and the `gearfem solve` sections (torques and positions from `Solve`).
// Engineering units at the interface (um, mm, N m), SI in the structs.
#include "optimise/relief.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::optimise
{
  /// Declare `Tip relief` inside the current subsection (`Optimise`).
  void declare_relief_parameters(dealii::ParameterHandler &prm);
  /// Read and check the study (InputError naming Section/Entry, value and allowed range:
  /// exit status 2). Needs `Optimise/Problem = tip relief`.
  ReliefStudy parse_relief_study(dealii::ParameterHandler &prm);
} // namespace gearfem::optimise
