#pragma once
// The 3-D FE model of a helical or spur pair's face (`Helical/Model = 3-D FE`, docs/three_d.md):
// each gear's coarse 3-D sector (three_d/face_compliance.h) joins the slices in place of the
// beam. The route of `gearfem helical` (run_job) attaches it; nothing else changes.
#include "helical/slicing.h"
#include "solve/input.h"

#include <ostream>

namespace gearfem::system_deflection
{
  /// The section mesh of gear i (1, 2) for its 3-D body: a sector of `solid.sector_teeth` teeth
  /// with the coarse element size everywhere (m_n/3 by default), no grading or splits.
  mesh::GearMeshParameters solid_mesh(const solve::GearContactInput &section, const helical::SlicingOptions &o, int i);

  /// `o` with its `face` set from the two gears' 3-D bodies (o.model must be solid); the
  /// set-up's progress and figures to `out` when not null.
  helical::SlicingOptions with_solid_face(const solve::GearContactInput &section, helical::SlicingOptions o,
                                          std::ostream *out = nullptr);
} // namespace gearfem::system_deflection
