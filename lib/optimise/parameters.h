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
  void declare_study_parameters(dealii::ParameterHandler &prm);
  /// Read and check (check_study: InputError naming the parameter, exit status 2).
  Study parse_study_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::optimise
