#pragma once
// ParameterHandler bindings of the analytical module: the `Rating` section (load and
// rating factors of `gearfem rate`) and the `Analytical` section (stiffness model
// choices). Engineering units at the interface (N m, rpm, mm), SI in the structs.
// Compiled into gearfem_analytical_params (deal.II); the light target has no deal.II.
#include "analytical/rating.h"
#include "analytical/cycle_table.h"
#include "analytical/tooth.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::analytical
{
  /// Declare the `Rating` section (defaults: seed 001's choices, Siasos 2010 sec. 4.1).
  void declare_rating_parameters(dealii::ParameterHandler &prm);
  /// Read it; materials (E, nu) are not part of it and are left at their defaults.
  RatingInput parse_rating_parameters(dealii::ParameterHandler &prm);

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
