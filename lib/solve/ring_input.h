#pragma once
// The input of an internal pair in `gearfem solve`: `Pair/Type = internal` makes gear 2 a
// ring (internal gear) cut by a shaper. Gear 2's entries give the ring's tooth count,
// profile shift (ISO 21771 sign: > 0 thickens the ring teeth and moves its circles towards
// the centre), tip shortening and face width; the `Ring` section gives its shaper cutter and
// the support of its outer circle; `Mesh` and `Mesh/Gear 2` give its element sizes, fine
// teeth and rim thickness (docs/internal-gears.md). Engineering units at the interface.
#include "geometry/internal_profile.h"
#include "geometry/rack.h"
#include "mesh/gear_mesh.h"
#include "mesh/ring_domain.h"

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::solve
{
  struct RingInput
  {
    geometry::InternalGearParameters gear;
    double face_width = 0; ///< [m]
    mesh::RingMeshParameters mesh;
  };

  /// Declare `Pair/Type` and the `Ring` section.
  void declare_ring_parameters(dealii::ParameterHandler &prm);
  /// True when `Pair/Type = internal`.
  bool internal_pair_requested(dealii::ParameterHandler &prm);
  /// The ring from gear 2's parsed geometry (`gear2`, the rack's module, pressure angle and
  /// addendum) and mesh (`mesh2`: sizes, model, fine teeth, rim thickness) and the `Ring`
  /// section. InputError naming the entry for what a ring cannot take (a tip relief on
  /// gear 2, a closed or B-spline rack, global refinements, a bore radius).
  RingInput parse_ring_parameters(dealii::ParameterHandler &prm, const geometry::GearParameters &gear2,
                                  const mesh::GearMeshParameters &mesh2);
} // namespace gearfem::solve
