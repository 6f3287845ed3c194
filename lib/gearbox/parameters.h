#pragma once
// ParameterHandler bindings of `gearfem gearbox` (Siasos 2010 system level): sections
// `Gearbox`, `Stage 1` .. `Stage 4`, `Spectrum`, `Lubricant`, plus the AGMA factors of the
// `Rating` section (declare_rating_parameters, shared with `gearfem rate`). Engineering
// units at the interface (mm, deg, N m, rpm, MPa, um, GPa), SI in the structs.
// Compiled into gearfem_gearbox_params (deal.II).
#include "gearbox/life.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::gearbox
{
  constexpr int max_stages = 4;

  /// Where the stresses of the damage sum come from.
  enum class StressSource
  {
    agma, ///< AGMA 2101-D04 / 908-B89 from the geometry (gearbox.h)
    iso,   ///< ISO 6336-2/-3 from the geometry (iso_stresses)
    table, ///< per-mesh stresses given at a reference torque, scaled (scaled_stresses)
    fe     ///< every mesh from FE sweeps (lib/gearbox/fe, a layer above solve), the
           ///< internal meshes AGMA; the table of stresses is given to use_stress_table
  };
  struct GearboxStudy
  {
    GearboxInput input;
    StressSource source = StressSource::agma;
    double reference_torque = 45000;                    ///< [N m] (table source)
    std::vector<std::vector<MeshStress>> reference;     ///< [stage][mesh] (table source)
  };

  void declare_gearbox_parameters(dealii::ParameterHandler &prm);
  /// Read and check the study (every stage through build_stage, so a design-check failure
  /// is an InputError at parse time, before anything is written).
  GearboxStudy parse_gearbox_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::gearbox
