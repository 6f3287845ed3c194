#pragma once
// ParameterHandler bindings of the geometry sections: `Rack`, `Gear 1`, `Gear 2`, `Pair`,
// `Material`. Engineering units at the interface (mm, deg, um, GPa), SI in the structs.
// Compiled into gearfem_geometry_params (deal.II); the light target has no deal.II.
#include "geometry/material.h"
#include "geometry/pair.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::geometry
{
  /// Everything the geometry sections define.
  struct GeometryInput
  {
    GearParameters gear1, gear2;
    PairParameters pair;
  };

  /// Declare the sections Rack, Gear 1, Gear 2, Pair (each entry with a Pattern, a unit
  /// and a default).
  void declare_geometry_parameters(dealii::ParameterHandler &prm);
  /// Declare the Material section (E [GPa], Poisson ratio, density [kg/m^3] per gear,
  /// Plane model).
  void declare_material_parameters(dealii::ParameterHandler &prm);
  /// Read the sections declared above, converting to SI. Throws InputError for values
  /// the Patterns cannot express (e.g. a malformed control-point list).
  GeometryInput parse_geometry_parameters(dealii::ParameterHandler &prm);
  PairMaterial  parse_material_parameters(dealii::ParameterHandler &prm);

  /// Generate both profiles and the pair from the input (all design checks run here).
  GearPair build_pair(const GeometryInput &in);
} // namespace gearfem::geometry
