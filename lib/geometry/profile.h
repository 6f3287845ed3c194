#pragma once
// The tooth and gear outline produced by rack generation, evaluable at any parameter
// (later attached to the mesh as an exact boundary). SI units.
//
// Frame: gear centre at the origin, tooth 0 axis along +y. The outline of tooth 0 runs
// counter-clockwise from the middle of the right root space (polar angle pi/2 - pi/z) to
// the middle of the left root space (pi/2 + pi/z):
//   root(coast) -> fillet(coast) -> flank(coast) -> [tip rounding] -> tip -> flank(drive)
//   -> fillet(drive) -> root(drive).
// The DRIVE flank is the counter-clockwise side of a tooth (x < 0 for tooth 0): it carries
// the load when the pinion turns counter-clockwise, and for the gear (which turns
// clockwise) it is the flank that the pinion's drive flank pushes.
#include "geometry/rack.h"

#include <string>
#include <vector>

namespace gearfem::geometry
{
  enum class SegmentType
  {
    root,
    fillet,
    flank,
    tip_rounding,
    tip
  };
  enum class Side
  {
    coast,
    drive,
    none ///< tip arc
  };
  const char *to_string(SegmentType t);
  const char *to_string(Side s);

  /// One exact piece of the outline: the curve restricted to [t0, t1] (t0 > t1 allowed;
  /// the outline runs from t0 to t1).
  struct ProfileSegment
  {
    SegmentType type;
    Side side;
    CurvePtr curve;
    double t0, t1;
    Vec2 point(double s) const;       ///< s in [0, 1] maps to t0 + s (t1 - t0)
    Vec2 start() const { return point(0.0); }
    Vec2 end() const { return point(1.0); }
  };

  /// A sampled outline point with everything downstream code needs.
  struct ProfilePoint
  {
    Vec2 p;            ///< position [m]
    Vec2 normal;       ///< outward unit normal
    double curvature;  ///< signed [1/m], > 0 convex (as seen from outside the tooth)
    int tooth;         ///< tooth index (0 for the single-tooth outline)
    int segment;       ///< index into ToothProfile::segments()
    double s;          ///< segment-local parameter in [0, 1]
    SegmentType type;
    Side side;
  };

  /// Undercut diagnosis (the trochoid cutting into the involute).
  struct UndercutReport
  {
    bool present = false;
    double depth = 0.0;          ///< max normal depth of material removed from the involute [m]
    double radius = 0.0;         ///< radius of the intersection (top of undercut) [m]
    bool cuts_active_profile = false; ///< set by GearPair when the mate's contact starts below `radius`
  };

  struct KeyRadii
  {
    double base = 0, reference = 0, tip = 0, root = 0;
    double form = 0;             ///< start of the flank (end of fillet), r_Ff [m]
    double tip_form = 0;         ///< end of the flank (start of tip rounding/relief region) [m]
    double relief_start = 0;     ///< radius where tip relief begins (= tip if none) [m]
  };

  class ToothProfile
  {
  public:
    /// Generate one tooth by rack generation, with design checks. Throws InputError
    /// (naming the parameter) for z < 5, m <= 0, alpha outside 10..35 deg, a pointed tip,
    /// and a rack that cannot generate a closed tooth. Warnings are collected.
    static ToothProfile generate(const GearParameters &gear);
    /// The same from an explicit generating rack (used for the mate of a B-spline gear).
    static ToothProfile generate(const GearParameters &gear, const GeneratingRack &rack);
    /// The mate of `gear1`: standard racks generate it from its own parameters; B-spline
    /// racks and flanks generate it from the complementary rack of gear 1.
    static ToothProfile generate_mate(const GearParameters &mate, const ToothProfile &gear1);

    const GearParameters &parameters() const { return gear_; }
    const std::vector<ProfileSegment> &segments() const { return segments_; }
    const KeyRadii &radii() const { return radii_; }
    const UndercutReport &undercut() const { return undercut_; }
    const std::vector<std::string> &warnings() const { return warnings_; }
    const GeneratingRack &rack() const { return rack_; }
    int teeth() const { return gear_.teeth; }
    /// Circular tooth thickness on the tip circle s_a [m].
    double tip_thickness() const { return tip_thickness_; }
    /// Indices into segments() of the coast and drive flank pieces (one, or two with tip
    /// relief: unmodified then relieved on the coast side, the mirror on the drive side).
    std::vector<int> flank_segments(Side side) const;
    double angular_pitch() const;

    /// Points of tooth 0 with spacing <= max_spacing [m] (segment ends included).
    std::vector<ProfilePoint> sample(double max_spacing) const;
    /// The whole gear: tooth k rotated by 2 pi k / z (counter-clockwise), closed loop.
    std::vector<ProfilePoint> sample_gear(double max_spacing) const;
    /// Rotate a tooth-0 point to tooth k.
    Vec2 rotate_to_tooth(const Vec2 &p, int k) const;
    /// Signed curvature (> 0 convex, as ProfilePoint::curvature) of the outline at its point
    /// nearest to p (body frame, any tooth) [1/m].
    double curvature_at(const Vec2 &p) const;

    /// Half of the tooth width (|x| of the coast side) at height y along the tooth axis
    /// (y measured from the gear centre) [m]; the narrowest value where undercut makes the
    /// outline multi-valued. Valid for root <= y <= tip.
    double half_width_at_height(double y) const;
    /// Circular (arc) tooth thickness at radius r [m], from the generated outline.
    double thickness_at_radius(double r) const;
    /// Profile deviation from the unmodified flank at radius r (tip relief) [m].
    double relief_at_radius(double r) const;

    GearParameters gear_;
    std::vector<ProfileSegment> segments_;
    KeyRadii radii_;
    UndercutReport undercut_;
    std::vector<std::string> warnings_;
    GeneratingRack rack_;
    double tip_thickness_ = 0;
  };

  /// Closed forms for cross-checking the generator.
  namespace closed_form
  {
    /// Involute of the base circle rb at roll angle xi, tooth axis +y, flank on the coast
    /// (x > 0) side, with half tooth-thickness angle `psi_b` at the base circle.
    Vec2 involute(double rb, double psi_b, double xi);
    /// Trochoid of Siasos 2010 for reference radius r0, cutter tip radius rc and
    /// cutter addendum hf (including shift), at generating angle theta; coast side.
    /// (In Siasos' frame: the cutter tip-arc centre crosses the tooth axis at theta = 0.)
    Vec2 trochoid(double r0, double rc, double hf, double theta);
    /// The same trochoid in the gear frame of ToothProfile (tooth axis +y, coast side),
    /// for a cutter tip-arc centre at rack abscissa uc [m]: Rot(-uc/r0) trochoid(...).
    Vec2 trochoid_gear_frame(double r0, double rc, double hf, double uc, double theta);
    /// inv(a) = tan a - a
    double inv(double a);
    /// Inverse of inv by Newton.
    double inv_inverse(double value);
  } // namespace closed_form
} // namespace gearfem::geometry
