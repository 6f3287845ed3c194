#pragma once
// Pair kinematics of a spur gear pair (external mesh). SI units.
//
// Pair frame: pinion (gear 1) centre O1 = (0, 0), gear 2 centre O2 = (0, a). The pinion
// drives, turning counter-clockwise; gear 2 turns clockwise. The line of action runs
// from T1 (tangent point on the pinion base circle) to T2; contact travels from A to E.
// A mesh position is the pinion roll angle phi1 [rad] measured from the position where
// pinion tooth 0 is in contact at the pitch point C (phi1 = 0 at C, < 0 at A).
#include "geometry/meshing_pair.h"
#include "geometry/profile.h"

#include <string>
#include <vector>

namespace gearfem::geometry
{
  struct PairParameters
  {
    /// Operating centre distance [m]; 0 means "from the profile shifts" (zero-backlash
    /// centre distance from inv a_w = inv a + 2 tan a (x1 + x2)/(z1 + z2)).
    double center_distance = 0.0;
  };

  class GearPair : public MeshingPair
  {
  public:
    /// Throws InputError for impossible centre distances, contact ratio < 1, tip-to-fillet
    /// interference, negative backlash, mismatched module/pressure angle.
    GearPair(ToothProfile gear1, ToothProfile gear2, const PairParameters &pair);

    const ToothProfile &gear(int i) const { return i == 1 ? g1_ : g2_; }
    double center_distance() const override { return a_; }
    double working_pressure_angle() const override { return alpha_w_; }
    double working_pitch_radius(int i) const override { return i == 1 ? rw1_ : rw2_; }
    double base_radius(int i) const override;
    double base_pitch() const override;
    double ratio() const override; ///< z2 / z1

    /// T1, T2, A, B (LPSTC), C (pitch), D (HPSTC), E, in that order.
    const std::vector<LoaPoint> &line_of_action() const override { return loa_; }
    const LoaPoint &point(const std::string &name) const override;
    double contact_ratio() const override { return eps_alpha_; }
    double normal_backlash() const { return jn_; }          ///< [m]
    double circumferential_backlash() const { return jt_; } ///< on the working pitch circle [m]
    double tip_clearance(int i) const;                      ///< gear i's tip to the mate's root [m]

    /// Rigid placement of gear i in the pair frame at pinion position phi1 (gear 2 at its
    /// unloaded conjugate angle: drive flanks touching, no load).
    Placement placement(int i, double phi1) const override;
    /// Gear 2 rotation angle for pinion position phi1. Closed form for involute pairs;
    /// gap-closing search on the exact outlines for any other pair.
    double conjugate_angle(double phi1) const;
    /// The same, always by the gap-closing search (for testing the closed form).
    double conjugate_angle_by_search(double phi1) const;
    /// Equivalent curvature 1/rho1 + 1/rho2 at pinion position phi1 for the pair in contact
    /// nearest to C [1/m] (signed curvatures of the profiles; convex positive).
    double equivalent_curvature(double phi1) const;
    /// Contact point (pair frame) of the tooth pair nearest to C at pinion position phi1
    /// [m]: on the line of action for involute pairs, on the rack-generated path of contact
    /// otherwise.
    Vec2 contact_point(double phi1) const;
    /// Point of the path of contact at pinion position phi1 for the tooth pair that is at C
    /// when phi1 = 0 (no reduction to the pair nearest C; phi1 within [A, E]) [m].
    Vec2 path_point(double phi1) const override;
    /// Equivalent curvature along the whole path of contact (same pair as path_point) [1/m].
    double path_curvature(double phi1) const;
    /// True when both gears are involutes (standard racks): closed-form kinematics apply.
    bool is_involute() const override { return involute_; }
    /// Zero-backlash centre distance for these tooth thicknesses [m].
    double zero_backlash_center_distance() const { return a0_; }

    // MeshingPair: the gear-by-gear facts of the two external gears.
    int teeth(int i) const override { return gear(i).teeth(); }
    double module() const override { return g1_.parameters().rack.module; }
    double face_width(int i) const override { return gear(i).parameters().face_width; }
    bool closed_rack(int i) const override { return gear(i).rack().closed(); }
    /// The involute arc (r_tf^2 - r^2)/(2 r_b) (every flank: the contact model's reach test).
    double flank_length_to_tip(int i, double r) const override;
    bool beyond_tip_form(int i, double r, double tol) const override;
    /// Involutes: sqrt(r^2 - r_b^2); other profiles: the outlines' curvature (0, 0 when the
    /// pair's relative curvature is not positive).
    std::array<double, 2> radii_of_curvature(const Vec2 &x, const std::array<Placement, 2> &P) const override;
    double relief_at_radius(int i, double r) const override { return gear(i).relief_at_radius(r); }
    bool has_relief(int i) const override;

    const std::vector<std::string> &warnings() const { return warnings_; }

    ToothProfile g1_, g2_;
    double a_ = 0, alpha_w_ = 0, rw1_ = 0, rw2_ = 0;
    double eps_alpha_ = 0, jn_ = 0, jt_ = 0;
    std::vector<LoaPoint> loa_;
    std::vector<std::string> warnings_;
    double phase1_ = 0, phase2_ = 0; ///< body angles at phi1 = 0
    bool   involute_ = true;
    double a0_ = 0;
    /// Non-involute pairs: the pinion's rack flank pieces generating its coast flank
    /// (root to tip) with their parameter ranges, and the piece and rack parameter of the
    /// contact at pinion position phi1.
    struct PathPiece
    {
      CurvePtr rack;
      double   tl, th;
    };
    std::vector<PathPiece>      path_;
    std::pair<int, double>      path_parameter(double phi1) const;

    double signed_gap(double beta, double phi1) const;

  private:
    /// Constructor phases, in this order: the centre distance (given or from the shifts)
    /// with its checks and the working pitch circles; the backlash and body phases; the
    /// path of contact, contact ratio and line-of-action points; the design checks on the
    /// path (interference, undercut, form circle, tip clearance).
    void set_centre_distance(const PairParameters &pair);
    void set_backlash();
    void set_path_of_contact(const PairParameters &pair);
    void check_design();
  };

  /// A short hex fingerprint (FNV-1a, 64 bit) of the pair's defining numbers: teeth, module,
  /// pressure angle, shifts, face widths, centre distance, and the tip, root and base radii
  /// (12 significant digits). Result files carry it so that tables are never applied to a
  /// different geometry.
  std::string geometry_fingerprint(const GearPair &pair);
  /// FNV-1a (64 bit) of a text, as a hex string (the fingerprints' hash).
  std::string text_fingerprint(const std::string &text);

  /// Siasos 2010: minimum number of teeth free of undercut,
  /// Z_min = 2[(h_fP* - x) - rho_fP*(1 - sin a)] / sin^2 a.
  double minimum_teeth_without_undercut(double alpha, double dedendum, double root_radius,
                                        double shift);
  /// The pinion teeth k (pinion tooth k meshes with gear tooth -k) that carry load at some
  /// pinion position of `roll` [rad] under a positive (drive-side) torque: those whose own
  /// roll angle phi1 + k 2 pi / z1 falls within [A - margin, E + margin], margin
  /// `margin_pitches` angular pitches, which takes the contact a loaded pair makes before A
  /// (the last positions of a pitch from A load the next pair: Parker 50/50 at 340 N m, 0.03
  /// pitch early). Sorted.
  std::vector<int> loaded_teeth(const GearPair &pair, const std::vector<double> &roll, double margin_pitches = 0.2);

  /// Centre distance from the shifts (zero backlash): inv a_w = inv a + 2 tan a (x1+x2)/(z1+z2).
  double center_distance_from_shifts(double module, double alpha, int z1, int z2, double x1,
                                     double x2);
} // namespace gearfem::geometry
