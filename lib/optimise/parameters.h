#pragma once
// ParameterHandler bindings of `gearfem optimise`: the sections `Optimise` (case, pair,
// sampling, constraints, start point) and `Optimiser` (methods and their settings).
// Engineering units at the interface (mm, deg), SI in the structs. Compiled into
// gearfem_optimise_params (deal.II); the light target has no deal.II.
#include "optimise/study.h"

#include <string>
#include <vector>

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
  /// The `Optimiser` section as written: the settings every method shares (`settings.method`
  /// is the first listed) and the listed methods in order (empty items skipped; an unknown
  /// name: InputError naming Optimiser/Methods). Each problem adds its own restrictions: the
  /// profile problem runs every method, the tip-relief problem exactly one and ignores Bound.
  struct OptimiserSection
  {
    OptimiserSettings settings;
    std::vector<Method> methods;
    std::string methods_text; ///< Optimiser/Methods as written
  };
  OptimiserSection read_optimiser_section(dealii::ParameterHandler &prm);
  /// Read and check (check_study: InputError naming the parameter, exit status 2).
  Study parse_study_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::optimise
