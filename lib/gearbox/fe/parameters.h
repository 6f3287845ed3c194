#pragma once
// The `FE stresses` section of `gearfem gearbox` (used with `Gearbox/Stress source = FE`):
// engineering units at the interface (mm), SI in FeStressOptions. Every value is checked
// with a named InputError (entry, value, allowed range).
#include "gearbox/fe/fe_stress.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::gearbox::fe
{
  void declare_fe_stress_parameters(dealii::ParameterHandler &prm);
  /// Read and check `FE stresses` against the number of stages of the study.
  FeStressOptions parse_fe_stress_parameters(dealii::ParameterHandler &prm, std::size_t n_stages);
} // namespace gearfem::gearbox::fe
