#pragma once
// The Mesh and Finite elements entries an input set (they override the automatic model
// choice of `Solve/Target`). Those entries are declared with has_to_be_set, so that
// ParameterHandler tells a value the input gave from a default.
#include "model_choice/choose.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::model_choice
{
  /// Which of Mesh/h_contact, h_fillet, h_corner, Model and Finite elements/Degree `prm`'s
  /// input set (after parsing).
  FixedSettings fixed_settings(const dealii::ParameterHandler &prm);
} // namespace gearfem::model_choice
