#pragma once
// ParameterHandler binding of the `Mesh` section (engineering units: mm) for
// GearMeshParameters (SI). Compiled into gearfem_mesh_params.
#include "mesh/gear_mesh.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::mesh
{
  /// Declare the `Mesh` section: common sizes plus subsections `Gear 1`, `Gear 2` (bore,
  /// rim, fine teeth). Every entry has a Pattern, a unit and a default.
  void declare_mesh_parameters(dealii::ParameterHandler &prm);
  /// Read the `Mesh` section for gear 1 or 2 (mm -> m) and validate it (InputError).
  GearMeshParameters parse_mesh_parameters(dealii::ParameterHandler &prm, int gear);
} // namespace gearfem::mesh
