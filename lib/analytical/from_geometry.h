#pragma once
// The bridge from the generated geometry (lib/geometry) to the analytical models: the
// tooth thickness function t(y) with the real fillet, the involute data, the line of
// action and the exact fillet curves for the root-stress constructions. SI units.
#include "analytical/iso6336.h"
#include "analytical/tooth.h"
#include "geometry/pair.h"

namespace gearfem::analytical
{
  /// The cantilever of a generated tooth: t(y) = 2 half_width_at_height(r_f + y) tabulated
  /// on `n` equally spaced heights from the root circle to the tip and interpolated
  /// (Catmull-Rom); psi_b from the generated thickness on the flank.
  /// @param rim_inner_radius bore/rim inner radius [m] for the Sainsot foundation (0: unset).
  InvoluteTooth involute_tooth(const geometry::ToothProfile &profile, double rim_inner_radius = 0.0,
                               int n = 401);

  /// Line-of-action data of a generated pair.
  PairLine pair_line(const geometry::GearPair &pair);

  /// The coast-side (x > 0) fillet of a generated tooth as a PlaneCurve (exact curve and
  /// derivatives of lib/geometry). Throws InputError when the profile has no fillet.
  iso6336::PlaneCurve fillet_curve(const geometry::ToothProfile &profile);
} // namespace gearfem::analytical
