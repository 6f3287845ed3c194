#pragma once
// ParameterHandler binding of the `Helical` section (gearfem helical).
#include "helical/helix.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::helical
{
  void declare_helical_parameters(dealii::ParameterHandler &prm);
  /// The section in SI units; unchecked against the face width (helical::check does that).
  HelixInput parse_helical_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::helical
