#pragma once
// Rating of an internal pair: an external pinion (geometry::ToothProfile, rack generated)
// meshing with a ring cut by a pinion-type shaper (geometry::InternalToothProfile), with the
// kinematics of geometry::InternalMesh. ISO 6336-2/-3 (2006, method B) and AGMA 2101-D04 /
// 908-B89, every factor an audited RatingRow, so RatingReport's markdown and CSV writers
// apply. SI inputs; the report is in engineering units (MPa, mm, N, deg).
//
// Sign convention: tooth counts are positive in the inputs (internal.h). Where ISO 6336
// writes the internal gear with z2 < 0 (u = z2/z1 < 0, d_a2 and d_b2 < 0 in Z_B, the root
// closed form) the sign is applied here and stated in the row's clause.
#include "rating/rating.h"
#include "geometry/internal.h"
#include "geometry/internal_profile.h"

namespace gearfem::rating
{
  namespace iso6336
  {
    /// Rim thickness factor of an external gear, ISO 6336-3:2006 clause 8 (unchanged in
    /// 2019): Y_B = 1 for s_R/h_t >= 1.2, Y_B = 1.6 ln(2.242 h_t/s_R) for 0.5 < s_R/h_t < 1.2.
    /// s_R rim thickness below the root circle, h_t tooth depth [m]. Throws InputError for
    /// s_R/h_t <= 0.5 (outside the standard's range).
    double Y_B_external(double s_R, double h_t);
    /// Rim thickness factor of an internal gear, ISO 6336-3:2006 clause 8 (the internal-gear
    /// relation is in module, not tooth depth): Y_B = 1 for s_R/m_n >= 3.5, Y_B = 1.15
    /// ln(8.324 m_n/s_R) for 1.75 < s_R/m_n < 3.5. s_R rim thickness outside the root circle
    /// [m]. Throws InputError for s_R/m_n <= 1.75.
    double Y_B_internal(double s_R, double m_n);

    /// The critical section of an internal gear by the closed form of ISO 6336-3 (2006)
    /// clause 6.2, method B, written for the internal gear: z_n = -z2 < 0, the critical
    /// section where the fillet tangent makes 60 deg with the tooth axis (T = pi/6 in H instead
    /// of pi/3, so the factors sqrt(3) = 2 cos 30 deg of the external form become 2 cos 60 deg
    /// = 1). In module units:
    ///   E = pi/4 - h_fP tan a_n + s_pr/cos a_n - (1 - sin a_n) rho_fP/cos a_n,
    ///   G = rho_fP - h_fP + x2,  H = 2/z_n (pi/2 - E) - pi/6,  theta = 2G/z_n tan theta - H,
    ///   s_Fn = z_n sin(pi/6 - theta) + (G/cos theta - rho_fP),
    ///   y = -[z_n/2 cos(pi/6 - theta) + (G/cos theta - rho_fP) sin(pi/3)]   (chord height).
    /// The root radius at the section is the shaper cutter's tip radius, rho_F = rho_fP =
    /// rho_a0 (the rack form's trochoid term does not apply to a shaper-cut ring; the exact
    /// generated fillet, an envelope of the tip arc, is never sharper: 0.5 % above it for a
    /// 56-tooth ring cut by 36 teeth, 11 % for 74 cut by 25).
    struct InternalSection
    {
      double theta = 0, E = 0, G = 0, H = 0; ///< [rad, -, -, -] (E, G in module units)
      double s_Fn = 0;  ///< chord [m]
      double y = 0;     ///< distance of the chord from the ring centre along the tooth axis [m]
      double rho_F = 0; ///< [m]
    };
    /// @param z2 ring teeth (> 0); @param h_fP, rho_fP, s_pr in module units: the basic-rack
    /// dedendum of the ring (from its root circle: (r_f2 - r2)/m + x2), the cutter tip radius
    /// and the protuberance; @param x2 ring profile shift (internal.h sign = ISO 21771).
    InternalSection internal_gear_section(int z2, double module, double alpha_n, double x2, double h_fP,
                                          double rho_fP, double s_pr = 0.0);

    /// Y_F, Y_S (ISO 6336-3 eqs. 24, 43) of an internal gear loaded at radius r_e of its
    /// involute, from a critical section (s_Fn, height y from the ring centre, rho_F). The
    /// ring's half tooth angle widens outwards, gamma_e = psi_b + inv a_en (flank.psi_b =
    /// s2/(2 r2) - inv a), the load line makes alpha_Fen = a_en + gamma_e with the normal to
    /// the tooth axis and meets the axis at r_b/cos alpha_Fen, outside the load point, so
    /// h_Fe = y - r_b/cos alpha_Fen.
    RootFactors internal_root_factors(double s_Fn, double y, double rho_F, const InvoluteFlank &flank, double r_e,
                                      double module, double alpha_n);
  } // namespace iso6336

  /// The inputs of rate_internal: the common load and factor choices plus the rims.
  struct InternalRatingInput
  {
    /// Pinion torques (per mesh), materials (1 pinion, 2 ring), AGMA and ISO factors. Its
    /// K_B must stay 1: the rim factors come from the rim thicknesses below. ISO accuracy
    /// grade 0 only (K_Halpha = K_Falpha = 1; ISO 6336-1's stiffness of internal pairs is
    /// not implemented).
    RatingInput rating;
    /// Ring face width [m]; 0: the pinion's. The rated width is the smaller.
    double ring_face_width = 0.0;
    /// Rim thickness s_R1 = t_R1 below the pinion root circle [m]; 0: solid (Y_B1 = K_B1 = 1).
    double pinion_rim_thickness = 0.0;
    /// Rim thickness s_R2 = t_R2 outside the ring root circle [m]; 0: not given (Y_B2 = K_B2 = 1).
    double ring_rim_thickness = 0.0;
  };

  /// Rate an internal pair for each pinion torque. ISO 6336-2 contact stress (Z_H at
  /// alpha_w, Z_B from M1 with z2 < 0, Z_D = 1 for the internal gear), ISO 6336-3 method B
  /// root stress of the pinion (30 deg tangent on its generated fillet) and of the ring
  /// (InternalSection, load at its outer point of single contact B) with the generated ring
  /// fillet's 60 deg section as a check row, Y_B of both; AGMA 2101-D04 contact stress with
  /// the internal Z_I and bending of the pinion (908-B89 trochoid) and of the ring (908's
  /// Lewis parabola on the generated ring fillet: 908 covers external teeth only), K_B of
  /// both. Throws InputError naming the entry for bad factors, rims thinner than the
  /// standards' ranges, and a mesh that does not belong to the two profiles.
  RatingReport rate_internal(const geometry::ToothProfile &pinion, const geometry::InternalToothProfile &ring,
                             const geometry::InternalMesh &mesh, const InternalRatingInput &in);
} // namespace gearfem::rating
