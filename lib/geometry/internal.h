#pragma once
// Kinematics and interference checks of an external pinion (planet) meshing with an
// internal gear (ring). SI units (m, rad). The ring's generated tooth outline is in
// internal_profile.h.
//
// Sign convention (stated once, used everywhere in this file and internal_profile.h):
// tooth counts are positive (z2 = number of ring teeth > z1), and the ring's profile shift
// coefficient x2 has the meaning of ISO 21771:2007 (and DIN 3960, Siasos 2010 eq. 2.1.2-4,
// lib/gearbox): x2 > 0 makes the ring teeth thicker, s2 = m (pi/2 + 2 x2 tan a), and moves
// all its circles towards the centre by x2 m (tip r_a2 = r2 - (h_a* + x2 - k*) m). With
// ISO's negative z2 the formulas are the external ones; with positive z2 they read
//   inv a_w = inv a - 2 tan a (x1 + x2)/(z2 - z1),  a = m (z2 - z1) cos a/(2 cos a_w).
// The SDP-SI / KHK tables write inv a_w = inv a + 2 tan a (x2' - x1)/(z2 - z1): their x2'
// is -x2.
//
// Pair frame: pinion centre O1 = (0, 0), ring centre O2 = (0, -a), so the pitch point C =
// (0, r_w1) lies above the pinion as in GearPair. The pinion drives counter-clockwise; the
// ring turns counter-clockwise too, at z1/z2 of the pinion's speed. Line of action through C
// tangent to both base circles on the same side: T1 = r_b1 (sin a_w, cos a_w), direction
// d = (-cos a_w, sin a_w), g = distance from T1 along d; T2 = T1 - a sin a_w d lies BEHIND
// T1 (g_T2 = -a sin a_w). Radii of curvature rho1 = g (convex), rho2 = g + a sin a_w
// (concave ring flank).
#include "geometry/pair.h"

#include <string>
#include <vector>

namespace gearfem::geometry
{
  /// The numbers that define an external-internal mesh. Radii from a generated outline, or
  /// from internal_mesh_input() for standard proportions.
  struct InternalMeshInput
  {
    std::string pinion_name = "Pinion"; ///< error-message prefix of the pinion entries
    std::string ring_name   = "Ring";   ///< error-message prefix of the ring entries
    int z1 = 0;                         ///< pinion teeth
    int z2 = 0;                         ///< ring teeth (positive, > z1)
    double module         = 0; ///< m [m]
    double pressure_angle = 0; ///< a [rad]
    double x1 = 0, x2 = 0;     ///< profile shift coefficients (x2: ISO 21771 sign, see above)
    double tip_radius1  = 0;   ///< pinion tip radius r_a1 [m]
    double tip_radius2  = 0;   ///< ring tip (inner) radius r_a2 [m]
    double root_radius1 = 0;   ///< pinion root radius r_f1 [m] (0: clearance not checked)
    double root_radius2 = 0;   ///< ring root (outer) radius r_f2 [m] (0: clearance not checked)
    /// Pinion form radius r_Ff1 (fillet meets involute) [m]; 0: the base circle.
    double form_radius1 = 0;
    /// Ring form radius r_Ff2 (outer end of the involute, where the fillet starts) [m];
    /// 0: no fillet check.
    double form_radius2 = 0;
    /// Operating centre distance [m]; 0: zero backlash from the shifts.
    double center_distance = 0;
  };

  /// Standard proportions: r_a1 = r1 + (h_a* + x1 - k*) m, r_f1 = r1 - (h_f* - x1) m,
  /// r_a2 = r2 - (h_a* + x2 - k*) m, r_f2 = r2 + (h_f* - x2) m (ISO 21771 with z2 < 0; rack
  /// proportions: a shaper cutter's root differs, see InternalToothProfile).
  InternalMeshInput internal_mesh_input(int z1, int z2, double module, double alpha, double x1,
                                        double x2, double addendum = 1.0, double dedendum = 1.25,
                                        double tip_shortening = 0.0);

  /// inv a_w = inv a - 2 tan a (x1 + x2)/(z2 - z1) (ISO 21771:2007 with z2 -> -z2) [rad].
  double internal_working_pressure_angle(double alpha, int z1, int z2, double x1, double x2);
  /// Zero-backlash centre distance a = m (z2 - z1) cos a/(2 cos a_w) [m].
  double internal_center_distance_from_shifts(double module, double alpha, int z1, int z2,
                                              double x1, double x2);

  /// Kinematics of an internal mesh (see the frame above). Points on the line of action are
  /// LoaPoints with g from T1 and roll_angle = (g - g_C)/r_b1.
  struct InternalMesh
  {
    InternalMeshInput in;
    double a = 0, alpha_w = 0;  ///< centre distance [m], working pressure angle [rad]
    double rb1 = 0, rb2 = 0;    ///< base radii [m]
    double rw1 = 0, rw2 = 0;    ///< working pitch radii r_b/cos a_w [m]
    double pb = 0;              ///< base pitch [m]
    double T1T2 = 0;            ///< a sin a_w [m]
    double contact_ratio = 0;   ///< eps_a = (g_E - g_A)/p_b
    /// Circumferential backlash on the working pitch circle, p_w - s_w1 - s_w2 [m], with
    /// s_w1 = 2 r_w1 (s1/(2 r1) + inv a - inv a_w), s_w2 = 2 r_w2 (s2/(2 r2) - inv a + inv a_w).
    double backlash_t = 0;
    double backlash_n = 0;      ///< normal backlash j_t cos a_w [m]
    /// Pinion tip to ring root, r_f2 - a - r_a1; ring tip to pinion root, r_a2 - a - r_f1 [m]
    /// (NaN when the root radius is not given).
    double clearance1 = 0, clearance2 = 0;
    /// T2, T1, A, B (LPSTC), C, D (HPSTC), E, in order of g.
    std::vector<LoaPoint> loa;

    const LoaPoint &point(const std::string &name) const;
    Vec2 center(int i) const { return i == 1 ? Vec2(0, 0) : Vec2(0, -a); }
    /// Point of the line of action at g [m].
    Vec2 position(double g) const;
    double rho1(double g) const { return g; }        ///< pinion radius of curvature [m]
    double rho2(double g) const { return g + T1T2; } ///< ring radius of curvature (concave) [m]
    /// Relative curvature of the concave-convex contact, 1/rho1 - 1/rho2 [1/m].
    double relative_curvature(double g) const { return 1.0 / rho1(g) - 1.0 / rho2(g); }
  };

  /// Build the kinematics. Throws InputError (naming the entry) when there is no mesh:
  /// z1 < 5, z2 <= z1, m <= 0, a <= r_b2 - r_b1 (centre distance below the base radii
  /// difference), a tip circle inside its base circle, or a zero-backlash centre distance
  /// that cannot be found.
  InternalMesh internal_mesh(const InternalMeshInput &in);

  /// A named interference diagnosis: `margin` > 0 is free (in `unit`), `interferes` when it
  /// is not. `parameter`, `value` and `allowed` are those of the InputError that raise()
  /// throws, so the message names the entry to change.
  struct InterferenceDiagnosis
  {
    std::string name;
    bool interferes = false;
    double margin   = 0;
    std::string unit;
    std::string parameter, value, allowed, detail;
    /// The InputError text ("invalid value for '...': ... (allowed: ...). detail").
    std::string message() const;
    /// Throws InputError when interferes.
    void raise() const;
  };

  /// Involute interference: the ring tip circle must cut the line of action beyond T1,
  /// g_A = sqrt(r_a2^2 - r_b2^2) - a sin a_w > 0 (margin g_A [m]); the limit is
  /// r_a2 > |O2 T1| = sqrt(r_b2^2 + (a sin a_w)^2). Equivalent to SDP-SI (1996) eq. 5-5,
  /// z1/z2 >= 1 - tan a_a2/tan a_w. Names `<ring>/Tip diameter`.
  InterferenceDiagnosis involute_interference(const InternalMesh &mesh);
  /// Ring tip against the pinion fillet: the start of contact must lie on the pinion
  /// involute, g_A >= sqrt(r_Ff1^2 - r_b1^2) (margin [m]). Names `<ring>/Tip diameter`.
  InterferenceDiagnosis ring_tip_pinion_fillet_interference(const InternalMesh &mesh);
  /// Pinion tip against the ring fillet: the end of contact must lie on the ring involute,
  /// rho2(E) = g_E + a sin a_w <= sqrt(r_Ff2^2 - r_b2^2) (margin [m]; free when r_Ff2 is not
  /// given). Names `<pinion>/Tip diameter`.
  InterferenceDiagnosis pinion_tip_ring_fillet_interference(const InternalMesh &mesh);
  /// Tip clearance: pinion tip to ring root and ring tip to pinion root, the smaller of
  /// the two (margin [m]; free when the root radii are not given). Names
  /// `Pair/Centre distance`.
  InterferenceDiagnosis root_clearance(const InternalMesh &mesh);
  /// Tip fouling in rotation ("trochoid interference": the pinion tip, leaving mesh after E,
  /// crossing the ring tip circle inside a ring tooth). SDP-SI, Elements of Metric Gear
  /// Technology (1996), eqs. 5-6, 5-7 (also KHK Gear Technical Reference):
  ///   theta1 z1/z2 + inv a_w - inv a_a2 - theta2 >= 0,
  ///   theta1 = acos((r_a2^2 - r_a1^2 - a^2)/(2 a r_a1)) + inv a_a1 - inv a_w,
  ///   theta2 = acos((a^2 + r_a2^2 - r_a1^2)/(2 a r_a2)).
  /// Margin = the left side [rad]. Names `<ring>/Number of teeth`.
  InterferenceDiagnosis tip_fouling_in_rotation(const InternalMesh &mesh);
  /// Tip fouling when the pinion is withdrawn radially ("trimming interference"; the pair
  /// must then be assembled axially). SDP-SI (1996) eqs. 5-9, 5-10:
  ///   theta1 + inv a_a1 - inv a_w - (z2/z1)(theta2 + inv a_a2 - inv a_w) >= 0,
  ///   theta1 = asin sqrt((1 - (cos a_a1/cos a_a2)^2)/(1 - (z1/z2)^2)),
  ///   theta2 = asin sqrt(((cos a_a2/cos a_a1)^2 - 1)/((z2/z1)^2 - 1)).
  /// Margin = the left side [rad]. Reproduces SDP-SI table 5-3a (pinion cutters, h_a0* =
  /// 1.25). Names `<ring>/Number of teeth`.
  InterferenceDiagnosis tip_fouling_radial(const InternalMesh &mesh);
  /// All of the above, in that order.
  std::vector<InterferenceDiagnosis> interference_checks(const InternalMesh &mesh);

  /// Independent check of the tip-fouling conditions by sweeping the mesh: the tip corners
  /// of the pinion (radius r_a1, flanks through s1) are moved through +-`pitches` pinion
  /// pitches around C (drive flanks touching at C at phi1 = 0, ring at phi1 z1/z2) and
  /// tested against the ring's involute teeth, and the ring's tip corners against the
  /// pinion's. Returns the largest penetration depth (radius times angle inside a tooth)
  /// [m]; <= 0 (touching within rounding) when no tip enters a tooth. Involute teeth only:
  /// a corner below a base circle is not tested.
  double tip_corner_penetration(const InternalMesh &mesh, int samples = 20000,
                                double pitches = 3.0);
} // namespace gearfem::geometry
