#pragma once
// ParameterHandler binding of the `Contact` section (engineering units at the interface:
// mm, deg, urad; SI in the structs).
#include "contact/options.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::contact
{
  void declare_contact_parameters(dealii::ParameterHandler &prm);
  /// Read and validate `Contact` (InputError). `E1`, `E2` resolve `Slave body = auto` (the
  /// softer body; the pinion when equal).
  ContactOptions parse_contact_parameters(dealii::ParameterHandler &prm, double E1, double E2);

} // namespace gearfem::contact
