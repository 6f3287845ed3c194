#pragma once
// ParameterHandler binding of the `Analytical` section (stiffness model choices of the
// analytical mesh cycle). Engineering units at the interface, SI in the structs.
// Compiled into gearfem_analytical_params (deal.II); the light target has no deal.II.
#include "analytical/cycle_table.h"
#include "analytical/tooth.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::analytical
{
  /// The `Analytical` section.
  struct AnalyticalInput
  {
    PairModelOptions options;
    double bore_radius1 = 0.0, bore_radius2 = 0.0; ///< [m] (Sainsot foundation; 0 = unset)
    int positions = 200;                            ///< mesh positions over one pitch
    bool corner_contact = true; ///< mesh cycle with the corner contacts OA/BΓ (corner.h)
    CycleLaw law = CycleLaw::load_sharing; ///< law of the mesh-cycle output (cycle_table.h)
  };
  void declare_analytical_parameters(dealii::ParameterHandler &prm);
  AnalyticalInput parse_analytical_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::analytical
