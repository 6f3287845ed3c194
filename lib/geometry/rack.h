#pragma once
// Basic racks (ISO 53 terms) and the generating rack (cutter) of a gear.
// SI units throughout (m, rad). Dimensionless coefficients are multiples of the module.
#include "geometry/curve.h"

#include <string>
#include <vector>

namespace gearfem::geometry
{
  /// Tip relief: material removed along the profile normal near the tip.
  struct TipRelief
  {
    enum class Kind
    {
      none,
      linear,   ///< C_a (xi - xi_s)/(xi_a - xi_s)
      parabolic ///< C_a ((xi - xi_s)/(xi_a - xi_s))^2
    };
    Kind kind = Kind::none;
    double amount = 0.0; ///< C_a at the tip [m]
    /// Length of the relief measured along the line of action (roll length) from the
    /// tip downwards [m]. If roll_angle > 0 it is used instead.
    double length = 0.0;
    double roll_angle = 0.0; ///< relief length as a roll angle [rad]; 0 = use `length`
  };

  /// The basic rack of one gear (ISO 53 terms, coefficients times the module).
  /// Smallest tooth tip rounding rho_aP* [module] other than 0 (sharp): below it the arc is
  /// far under any mesh size.
  inline constexpr double min_tip_radius = 0.005;

  struct RackParameters
  {
    enum class Kind
    {
      standard, ///< straight flanks at the pressure angle
      bspline_rack, ///< rack flank given by B-spline control points (Koronaios 2021 case 1)
      bspline_flank ///< gear flank given by B-spline control points, rack recovered (case 2)
    };
    Kind kind = Kind::standard;
    double module = 0.0;          ///< m [m]
    double pressure_angle = 0.0;  ///< alpha [rad]
    double addendum = 1.0;        ///< h_aP* : tooth addendum (sets the tip circle)
    double dedendum = 1.25;       ///< h_fP* : cut by the cutter addendum (sets the root circle)
    double root_radius = 0.25;    ///< rho_fP* : cutter tip radius, generates the trochoid fillet
    double tip_radius = 0.0;      ///< rho_aP* : optional tooth-tip rounding (0 = sharp)
    /// For the B-spline kinds: control points in module units. For bspline_rack: points
    /// (u, v) of the rack flank in rack coordinates (u along the pitch line from the
    /// middle of the tooth space, v normal to it, positive away from the gear centre).
    /// For bspline_flank: points (x, y) of the gear flank in the gear frame (tooth axis +y).
    std::vector<Vec2> control_points;
    unsigned int spline_degree = 4;
  };

  /// Everything that defines one gear's tooth (SI units).
  struct GearParameters
  {
    std::string name = "Gear";        ///< used in error messages ("Gear 1")
    int teeth = 0;                    ///< z
    double profile_shift = 0.0;       ///< x
    double tip_shortening = 0.0;      ///< k* (tip circle lowered by k* m)
    double thickness_allowance = 0.0; ///< reduction of circular tooth thickness at the reference circle [m] (backlash)
    double face_width = 0.0;          ///< b [m]
    RackParameters rack;
    TipRelief relief;

    double reference_radius() const { return 0.5 * rack.module * teeth; }
  };

  /// One smooth piece of the generating rack (one side). `generates` says which kind of
  /// gear-tooth segment its conjugate becomes.
  struct RackSegment
  {
    CurvePtr curve;
    /// If set: the exact gear-frame curve this segment generates, with the same parameter
    /// as `curve` (a B-spline flank given directly; its rack was recovered from it).
    CurvePtr gear_curve;
    enum class Generates
    {
      tip,
      flank,
      fillet,
      root
    } generates;
  };

  /// The generating rack of one gear, one side, in rack coordinates (u along the pitch
  /// line, u = 0 at the middle of the cutter tooth space = the gear tooth axis; v positive
  /// away from the gear centre), ordered from the gear tip towards the gear root. The
  /// profile shift and thickness allowance are already included.
  class GeneratingRack
  {
  public:
    /// Build the cutter for a gear. Throws InputError on inconsistent rack data.
    static GeneratingRack from_parameters(const GearParameters &gear);
    /// The generating rack of the mating gear for a non-standard (B-spline) pair: the
    /// flank of this rack seen from the other side, (u, v) -> (p/2 - u, -v), completed
    /// by the mate's own cutter tip (arc tangent to the flank end, tip line at
    /// (x - h_fP*) m). Throws InputError if the mate's dedendum cannot be reached.
    GeneratingRack complement_for(const GearParameters &mate) const;
    /// Module, pressure angle and kind of the rack this was built from.
    double module() const { return m_; }
    const std::vector<RackSegment> &segments() const { return segments_; }
    double generating_pitch_radius() const { return r0_; }
    /// v of the line that generates the root circle (the cutter tip line; for a closed
    /// rack its trough) [m].
    double root_line() const { return v_root_; }
    /// A closed rack: a B-spline flank that starts level on the gear tooth axis (u = 0,
    /// its crest generates the tooth tip) and ends level in the middle of the cutter tooth
    /// (u = p/2, its trough generates the root), like the sinusoid and case-1 racks of Koronaios 2021.
    /// It needs no cutter tip: the whole rack generates flank, fillet and root, and the
    /// concave part of the tooth (its fillet) may carry contact.
    bool closed() const { return closed_ != nullptr; }

    std::vector<RackSegment> segments_;
    double r0_     = 0.0;
    double m_      = 0.0;
    double v_root_ = 0.0;
    CurvePtr closed_; ///< the whole closed rack flank (crest to trough), or null
  };
} // namespace gearfem::geometry
