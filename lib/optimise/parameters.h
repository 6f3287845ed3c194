#pragma once
// ParameterHandler bindings of `gearfem optimise`: the sections `Optimise` (case, pair,
// sampling, constraints, start point) and `Optimiser` (methods and their settings).
// Engineering units at the interface (mm, deg), SI in the structs. Compiled into
// gearfem_optimise_params (deal.II); the light target has no deal.II.
#include "optimise/study.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::optimise
{
  /// Also declares `Optimise/Problem`, `Optimise/Tip relief` (relief_parameters.h) and the
  /// `gearfem solve` sections that the tip-relief problem reads.
  void declare_study_parameters(dealii::ParameterHandler &prm);
  /// `Optimise/Problem = tip relief`.
  bool is_relief_problem(dealii::ParameterHandler &prm);
  /// Read and check (check_study: InputError naming the parameter, exit status 2).
  Study parse_study_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::optimise
