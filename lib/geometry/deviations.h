#pragma once
// Manufacturing deviations of a spur gear pair: single-pitch, profile-slope, profile-form and
// runout deviations of each gear, the ISO 1328-1:2013 tolerances of an accuracy grade, seeded
// random draws within them, and the normal offset each deviation puts on a loaded (drive)
// flank point. Light layer (Eigen only). SI values; docs/deviations.md states the conventions.
//
// Conventions (ISO 1328-1:2013 and ISO 21771 for the terms; docs/deviations.md):
// - Teeth are numbered counter-clockwise in each gear's body frame (tooth k at +k 2 pi / z
//   from tooth 0), as in the mesh (mesh/gear_domain.h).
// - Every deviation is positive for "plus material" on the loaded flank (ISO's sign for
//   profile deviations); f_pt,k is the deviation of the pitch from tooth k - 1 to tooth k on the
//   loaded flanks (positive: longer than nominal), F_p,k = sum_{i=1..k} f_pt,i the cumulative
//   pitch deviation (F_p,0 = 0; the f_pt of a gear sum to zero). A longer pitch moves tooth k
//   counter-clockwise, which puts material on the loaded flank of either gear of an external
//   pair (the pinion turns counter-clockwise and drives with its counter-clockwise-facing
//   flank; gear 2 turns clockwise and is loaded on its counter-clockwise-facing flank).
// - The normal offset along the line of action of a tangential deviation s on the reference
//   circle is s cos(alpha) (involute: the flank normal is tangent to the base circle).
// - Profile deviations are functions of the roll length xi = sqrt(r^2 - r_b^2) over the
//   evaluation range [xi_start, xi_end] of the loaded flank (the active profile of the pair).
// - Runout is an eccentricity e of the gear's geometric centre from its axis of rotation, at
//   body-frame angle psi (from the body x axis, counter-clockwise); ISO's radial runout F_r (a
//   probe in every tooth space) reads F_r = 2 e.
#include "base/units.h"

#include <Eigen/Dense>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::geometry
{
  /// ISO 1328-1:2013 flank tolerances of one gear [m], from the standard's formulas (clause 5.3)
  /// for the accuracy grade A (1..11) with the step factor sqrt(2) per grade about grade 5,
  /// rounded by the standard's rule (rounded) or as computed (exact).
  struct Iso1328Tolerances
  {
    int grade = 6;
    double f_pT = 0;  ///< single pitch: (0.001 d + 0.4 m_n + 5) sqrt2^(A-5) [um]
    double F_pT = 0;  ///< cumulative pitch: (0.002 d + 0.55 sqrt(d) + 0.7 m_n + 12) sqrt2^(A-5)
    double f_HaT = 0; ///< profile slope: (0.4 m_n + 0.001 d + 4) sqrt2^(A-5)
    double f_faT = 0; ///< profile form: (0.55 m_n + 5) sqrt2^(A-5)
    double F_aT = 0;  ///< total profile: sqrt(f_HaT^2 + f_faT^2)
    double f_HbT = 0; ///< helix slope: (0.05 sqrt(d) + 0.35 sqrt(b) + 4) sqrt2^(A-5)
    double f_fbT = 0; ///< helix form: (0.07 sqrt(d) + 0.45 sqrt(b) + 4) sqrt2^(A-5)
    double F_bT = 0;  ///< total helix: sqrt(f_HbT^2 + f_fbT^2)
    double F_rT = 0;  ///< radial runout: 0.9 F_pT
  };

  /// The standard's rounding of a tolerance (ISO 1328-1:2013, 5.2): above 10 um to 1 um, from
  /// 5 to 10 um to 0.5 um, below 5 um to 0.1 um. [m] in, [m] out.
  double iso1328_round(double value);

  /// Tolerances of accuracy grade `grade` (1..11) for normal module m_n, reference diameter d
  /// and face width b [m], within the standard's range of application (0.5 <= m_n <= 70 mm,
  /// 5 <= d <= 15 000 mm, 4 <= b <= 1 200 mm); InputError naming `entry` otherwise.
  Iso1328Tolerances iso1328_tolerances(int grade, double m_n, double d, double b, bool rounded = true,
                                       const std::string &entry = "Deviations/Accuracy grade");

  /// The parabolic or tabulated form deviation of a profile.
  struct ProfileForm
  {
    enum class Kind
    {
      none,
      parabolic, ///< amplitude f_fa: f_fa (1/3 - 4 u^2), u in [-1/2, 1/2] over the range
      table      ///< measured trace: (roll length [m] from xi_start, deviation [m]), linear
    };
    Kind kind = Kind::none;
    double amplitude = 0; ///< [m]; > 0 crowned (plus material mid-profile), < 0 hollow
    std::vector<std::pair<double, double>> trace;
    /// Deviation [m] at normalised position u = (xi - xi_mid) / L_alpha and roll length
    /// s = xi - xi_start [m].
    double at(double u, double s) const;
  };

  /// The deviations of one gear. Per-tooth vectors hold z values, or one value common to all.
  struct GearDeviations
  {
    std::vector<double> f_pt;       ///< single pitch deviations [m] (empty: none), sum 0
    std::vector<double> f_Ha;       ///< profile slope deviation [m] per tooth or common
    std::vector<ProfileForm> form;  ///< per tooth or common (empty: none)
    double flank_offset = 0;        ///< common normal offset of every loaded flank [m]
    double eccentricity = 0;        ///< runout e [m] (F_r = 2 e)
    double eccentricity_phase = 0;  ///< psi [rad]
    /// Cumulative pitch deviation F_p,k of tooth k [m].
    std::vector<double> cumulative_pitch() const;
    bool empty() const;
  };

  /// The evaluation range of a gear's loaded flank: roll lengths [m] and base radius.
  struct FlankRange
  {
    double base_radius = 0, xi_start = 0, xi_end = 0;
    double cos_alpha = 1; ///< cos of the reference pressure angle (pitch to normal offset)
  };

  /// The deviations of a pair, with the data that turn them into normal flank offsets.
  struct PairDeviations
  {
    GearDeviations gear[2];
    FlankRange range[2];
    int teeth[2] = {0, 0};
    /// F_p,k of each gear about their mean (set by finalise(); empty without pitch deviations):
    /// the teeth's mean position is the datum, so a pitch deviation does not shift the mean STE.
    std::vector<double> cumulative[2];
    /// Call after filling gear[]: caches the cumulative pitch deviations.
    void finalise();
    bool empty() const { return gear[0].empty() && gear[1].empty(); }
    /// Plus material [m] on the loaded flank of tooth `tooth` (any integer, taken mod z) of
    /// gear `body` (1, 2) at radius r [m]: flank offset, F_p cos(alpha), slope and form.
    double plus_material(int body, int tooth, double r) const;
    /// The part of it that moves the whole involute flank along its normal: flank offset and
    /// F_p cos(alpha) [m]. An involute moved along its normal by d is the same involute turned
    /// by d / r_b about the gear axis (counter-clockwise for plus material, either gear), so this
    /// part is a rigid rotation of the tooth (tooth_rotation).
    double rigid_plus_material(int body, int tooth) const;
    /// rigid_plus_material / r_b [rad], counter-clockwise.
    double tooth_rotation(int body, int tooth) const;
    /// The rest: profile slope and form at radius r [m].
    double profile_plus_material(int body, int tooth, double r) const;
    /// Displacement [m] of gear `body`'s centre by its runout when its body frame is turned by
    /// `angle` [rad] in the pair frame (pair-frame vector).
    Eigen::Vector2d runout(int body, double angle) const;
  };

  /// Checks the sizes (z or 1 per-tooth values), the pitch closure (|sum f_pt| <= 1e-3 of
  /// max |f_pt|, or 1e-12 m) and the finiteness; InputError naming `section`.
  void check_deviations(const GearDeviations &d, int teeth, const std::string &section);

  /// Distribution of a random draw.
  enum class Distribution
  {
    uniform,          ///< uniform within +-tolerance
    truncated_normal  ///< normal with sigma = tolerance / 3, truncated at +-tolerance
  };
  Distribution distribution_from_string(const std::string &s, const std::string &entry);
  const char *to_string(Distribution d);

  /// A seeded draw of a gear's deviations within tolerances `t` (ISO 1328-1 meanings):
  /// - f_pt,k within +-f_pT, the mean removed (closure); when a single pitch then exceeds f_pT
  ///   or the cumulative deviations span more than F_pT, all f_pt are scaled by one factor to
  ///   meet both (a gear that passes inspection);
  /// - f_Ha per tooth within +-f_HaT;
  /// - a parabolic form per tooth of amplitude within +-f_faT;
  /// - F_r within [0, F_rT] (half-normal for truncated_normal), e = F_r / 2, phase uniform.
  /// The same (seed, stream) gives the same draw on every machine (own generator, no
  /// std::distribution).
  GearDeviations draw_deviations(const Iso1328Tolerances &t, int teeth, Distribution dist, std::uint64_t seed,
                                 std::uint64_t stream);

  /// Hunting period of a pair: the number of pitches after which every tooth pair recurs,
  /// lcm(z1, z2) = z1 z2 / gcd(z1, z2).
  long hunting_pitches(int z1, int z2);
} // namespace gearfem::geometry
