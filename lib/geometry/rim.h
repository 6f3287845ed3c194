#pragma once
// The inner radius of a gear body: one rule for the FE mesh (mesh/gear_domain.cc: the clamped
// bore or rim circle) and the analytical models (the Sainsot foundation of the potential-energy
// compliance, analytical/from_geometry.h), so that both describe the same body. Light layer.
#include "geometry/profile.h"

namespace gearfem::geometry
{
  /// The body's inner radius [m]: root radius - rim_thickness when rim_thickness > 0; else
  /// bore_radius when > 0; else, for a sector, root radius - 2.75 m (a rim of 2.75 modules,
  /// with the tooth depth about 5 modules of material below the tip); else half the root
  /// radius (the default bore of a full gear). Range checks are the caller's (the mesh
  /// names the entry that is out of range).
  inline double rim_inner_radius(const ToothProfile &tooth, double bore_radius = 0.0, double rim_thickness = 0.0,
                                 bool sector = false)
  {
    const double rf = tooth.radii().root;
    if (rim_thickness > 0)
      return rf - rim_thickness;
    if (bore_radius > 0)
      return bore_radius;
    if (sector)
      return rf - 2.75 * tooth.parameters().rack.module;
    return 0.5 * rf;
  }
} // namespace gearfem::geometry
