#pragma once
// Corner contact of an external involute pair (Gkimisis 2019, contact path
// segments OA and BΓ): outside the line of action A..E a tooth pair can still touch under
// load, the tip corner of one tooth on the involute flank of the other. This file gives the
// exact rigid gap of that contact from the involute polar coordinates: a point of the
// involute of base radius rb at radius r lies at the polar angle inv(acos(rb/r)) behind
// the start of the involute on the base circle, and the involutes of one base circle are
// parallel curves, so the rotation that brings an involute flank onto a point is the
// point's polar-angle offset from the flank at the point's radius, and rb times it is the
// normal distance between them. Light layer (no deal.II). SI units (m, rad).
#include <limits>

namespace gearfem::analytical
{
  /// What the corner-gap computation needs to know about the pair (distances from T1
  /// along the line of action, as in PairLine).
  struct CornerGeometry
  {
    double rb1 = 0, rb2 = 0;         ///< base radii [m]
    double length = 0;               ///< T1T2 = a sin(alpha_w) [m]
    double g_A = 0, g_E = 0;         ///< start and end of the involute contact [m]
    double r_form1 = 0, r_form2 = 0; ///< start of the involute flanks (end of the fillets) [m]; 0: the base circle
    /// Tip rounding radius of each tooth [m] (0: sharp corner). The rounding is an arc tangent
    /// to the flank and internally tangent to the tip circle, as in lib/geometry; the flank
    /// (and the path, A..E) then ends at the tangent point, which depends on the radius.
    double rounding1 = 0, rounding2 = 0;
    /// Tip radii [m]: needed with a rounding; otherwise only the limit of the mate's flank
    /// (0: no limit). With rounding = 0 the corner is the end of the involute at E (pinion)
    /// and A (gear), whatever these are.
    double r_tip1 = 0, r_tip2 = 0;
  };

  /// How the compression is counted.
  enum class GapFrame
  {
    /// The gear stays at its rigid conjugate angle and the pinion turns (`gearfem solve`,
    /// x = R_g1 (omega_1 - omega_1n) of Gkimisis 2019): the compression of the mesh models.
    pinion,
    /// The body that carries the touched flank turns (the gear for BΓ beyond E, the pinion
    /// for OA before A); for OA this is the same as `pinion`.
    mating
  };

  /// A corner contact of one tooth pair.
  struct CornerContact
  {
    /// Rigid gap [m]: base-circle arc (rb1 times the pinion rotation for GapFrame::pinion,
    /// rb of the turning body for GapFrame::mating) that closes the gap. 0 on the path,
    /// +infinity where the corner cannot touch the mating involute (the touching point lies
    /// below the mating base or form circle, or above the mating tip circle when given).
    double gap = std::numeric_limits<double>::infinity();
    /// Lever arm of the contact force about O1 over rb1 [-]. The force acts along the normal
    /// of the touched flank, tangent to the mating base circle through the touching point:
    /// 1 on the path and for OA (the normal of the pinion flank is tangent to the pinion
    /// base circle); for BΓ the distance from O1 to the gear-flank normal, over rb1.
    double arm = 1;
    /// True when the touching point is the corner or its rounding (outside the involute path
    /// of the rounded teeth); false on the path.
    bool on_corner = false;
    /// Radius of curvature [m] of the touched (mating) involute at the touching point (only
    /// with on_corner); the corner itself has the rounding radius of its tooth (0: sharp).
    double mate_curvature = 0;
  };

  /// The corner gap of the pair whose rigid-kinematics contact position (the pinion roll
  /// distance from T1 of its involute, extended if need be) is g [m]. Inside [g_A, g_E] of
  /// the rounded teeth: gap 0. Beyond the end (g > g_E) the pinion tip corner (or rounding)
  /// meets the gear flank (BΓ), before the start (g < g_A) the gear tip corner meets the
  /// pinion flank (OA). Near the ends the gap is d^2/(2 R) to leading order (see
  /// corner_gap_curvature_radius). Throws InputError for inconsistent geometry.
  CornerContact corner_contact(const CornerGeometry &geo, double g, GapFrame frame = GapFrame::pinion);

  /// The end (at_end = true, E) or start (A) of the involute path of the rounded teeth [m]:
  /// g_E and g_A without rounding.
  double corner_path_end(const CornerGeometry &geo, bool at_end);

  /// Shorthand for corner_contact(geo, g, frame).gap [m].
  double corner_gap(const CornerGeometry &geo, double g, GapFrame frame = GapFrame::pinion);

  /// The leading-order radius R [m] of the gap d^2/(2 R) at distance d beyond E (at_end =
  /// true) or before A, for sharp corners (both frames agree to leading order):
  /// R = rb_c^2 rho_m / (rho_c (rho_c + rho_m)), with rb_c the base radius of the tooth that
  /// carries the corner, rho_c = sqrt(r_c^2 - rb_c^2) its involute radius of curvature at the
  /// corner and rho_m = T1T2 - rho_c that of the mating flank at the same point.
  /// Derivation in docs/analytical.md.
  double corner_gap_curvature_radius(const CornerGeometry &geo, bool at_end);
} // namespace gearfem::analytical
