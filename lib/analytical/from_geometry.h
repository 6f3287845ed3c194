#pragma once
// The bridge from the generated geometry (lib/geometry) to the analytical models: the
// tooth thickness function t(y) with the real fillet, the involute data, the line of
// action and the exact fillet curves for the root-stress constructions. SI units.
#include "analytical/plane_curve.h"
#include "analytical/tooth.h"
#include "geometry/pair.h"

namespace gearfem::analytical
{
  /// The cantilever of a generated tooth: t(y) = 2 half_width_at_height(r_f + y) tabulated
  /// on `n` equally spaced heights from the root circle to the tip and interpolated
  /// (Catmull-Rom); psi_b from the generated thickness on the flank.
  /// @param rim_inner_radius bore/rim inner radius [m] for the Sainsot foundation; 0: the
  /// FE body's default (geometry::rim_inner_radius, half the root radius).
  InvoluteTooth involute_tooth(const geometry::ToothProfile &profile, double rim_inner_radius = 0.0,
                               int n = 401);

  /// Line-of-action data of a generated pair.
  PairLine pair_line(const geometry::GearPair &pair);

  /// The coast-side (x > 0) fillet of a generated tooth as a PlaneCurve (exact curve and
  /// derivatives of lib/geometry). Throws InputError when the profile has no fillet.
  analytical::PlaneCurve fillet_curve(const geometry::ToothProfile &profile);

  /// The tooth-pair compliance of a generated pair: both teeth (involute_tooth, with the rim
  /// radii rim1, rim2; 0: the FE default of geometry::rim_inner_radius), the smaller face
  /// width and the line of action. The one place a PairCompliance is built from a GearPair.
  PairCompliance pair_compliance(const geometry::GearPair &pair, const Material &m1, const Material &m2,
                                 const PairModelOptions &options = {}, double rim1 = 0.0, double rim2 = 0.0);
} // namespace gearfem::analytical
