#pragma once
// ParameterHandler binding of the `Rating` section: the load and rating factors of
// `gearfem rate`. Engineering units at the interface (N m, rpm, MPa), SI in the structs.
// Compiled into gearfem_rating_params (deal.II); the light target has no deal.II.
#include "rating/rating.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::rating
{
  /// Declare the `Rating` section (defaults: the choices of Siasos 2010 sec. 4.1).
  void declare_rating_parameters(dealii::ParameterHandler &prm);
  /// Read it; materials (E, nu) are not part of it and are left at their defaults.
  RatingInput parse_rating_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::rating
