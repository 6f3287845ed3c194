#pragma once
// ParameterHandler bindings of the geometry sections: `Rack`, `Gear 1`, `Gear 2`, `Pair`,
// `Material`. Engineering units at the interface (mm, deg, um, GPa), SI in the structs.
// Compiled into gearfem_geometry_params (deal.II); the light target has no deal.II.
#include "geometry/material.h"
#include "geometry/pair.h"

#include <string>

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

  /// The gear-geometry entries of every command that reads a gear, each declared with one
  /// description and the ranges of geometry/limits.h (checked by the limits::check_*
  /// functions with the caller's entry path). `what` names the quantity in the description
  /// ("z1", "Z_S (gear 1 of a parallel stage)").
  void declare_teeth_entry(dealii::ParameterHandler &prm, const std::string &name, int default_teeth,
                           const std::string &what);
  void declare_module_entry(dealii::ParameterHandler &prm, const std::string &name, double default_mm);
  void declare_pressure_angle_entry(dealii::ParameterHandler &prm, const std::string &name = "Pressure angle");
  void declare_addendum_entry(dealii::ParameterHandler &prm, const std::string &name, const std::string &what);
  void declare_face_width_entry(dealii::ParameterHandler &prm, const std::string &name, double default_mm,
                                const std::string &what = "b");

  /// Generate both profiles and the pair from the input (all design checks run here).
  GearPair build_pair(const GeometryInput &in);
} // namespace gearfem::geometry
