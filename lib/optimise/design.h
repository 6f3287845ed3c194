#pragma once
// Koronaios (NTUA 2021) tooth-profile designs: the two B-spline cases, their
// free coordinates, objectives and constraints, and the two reference profiles (involute,
// sinusoidal rack). SI inside (m); design vectors in module units. No deal.II.
//
// Choices the thesis does not state (docs/optimise.md, "Unstated choices"):
//  - Case 1 (pinion rack, degree 4, 5 control points, 4 free coordinates): the rack flank
//    over half a period, crest (gear tip) to trough (gear root), in rack coordinates (u, v)
//    of lib/geometry: P0 = (0, 1) and P4 = (pi/2, -1) fixed, P1 = (u1, 1) and P3 = (u3, -1)
//    level (v' = 0 at crest and trough, so the even mirror images that complete the pitch
//    join smoothly), P2 = (u2, v2). Free: x = (u1, u2, v2, u3). Start: the fit of the
//    sinusoid v = cos 2u with equally spaced u (u(t) then linear): x0 = (pi/8, pi/4, 0, 3pi/8).
//  - Case 2 (pinion flank, degree 4, 5 control points, 8 free coordinates): P0..P3 free,
//    P4 fixed on the involute 0.001 m beyond the tip circle (tip thickness kept). Start: the
//    least-squares fit of the involute flank between the base circle + half the base-to-SAP
//    distance and the tip, at parameters uniform in roll angle.
//  - Bounds: a box of +-`bound` (module units) about the start point.
//  - The x in 2.5 int (1/R)^2 dx: the flank abscissa in position 2 (the tooth turned two
//    pitches anticlockwise), from the start of active profile to the tip, in mm.
#include "geometry/pair.h"
#include "base/units.h"
#include "optimise/kinematics.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gearfem::optimise
{
  /// The pair (Koronaios 2021: 19/55, m 2.5 mm, standard addendum, reference centre distance).
  struct PairData
  {
    int z1 = 19, z2 = 55;
    double module = 2.5e-3;                    ///< m [m]
    double pressure_angle = 20.0 * units::deg; ///< of the involute reference [rad]
    double addendum = 1.0;                     ///< h_a* (tip circles r + h_a* m)
    double dedendum = 1.25;                    ///< h_f* of the generating cutter (case 2 geometry)
    double root_radius = 0.25;                 ///< rho_fP* of the cutter tip (case 2 geometry)
    double r01() const { return 0.5 * module * z1; }
    double r02() const { return 0.5 * module * z2; }
    double tip_radius(int i) const { return (i == 1 ? r01() : r02()) + addendum * module; }
  };

  enum class DesignKind
  {
    involute,     ///< reference: straight rack at the pressure angle
    sinusoid,     ///< reference: rack v = m cos(2u/m) (y = m sin(2x/m) of the thesis)
    case1_rack,   ///< B-spline pinion rack, objective max + mean + std
    case2_flank   ///< B-spline pinion flank, objective 2.5 int (1/R)^2 dx + std + 0.1/eps
  };
  const char *to_string(DesignKind k);

  /// What is evaluated and how.
  struct EvaluationSettings
  {
    int samples = 1001;            ///< sample points along the active flank (>= 11)
    double min_contact_ratio = 1.0; ///< constraint eps >= this
    /// Start of the sampled range on the pinion (pinion-radius sampling) [m]; 0 = the start
    /// of active profile (where the path of contact meets the gear-2 tip circle).
    double start_radius = 0.0;
    /// Run gearfem's own design checks (GearPair: interference, undercut into the active
    /// profile, pointed tip) on every case-2 evaluation.
    bool design_checks = true;
    /// Case 2's objective w0 int (1/R)^2 dx + w1 std(1/R) + w2/eps (thesis: 2.5, 1, 0.1).
    std::array<double, 3> weights = {2.5, 1.0, 0.1};
  };

  /// Named constraints, each c <= 0 when met (dimensionless).
  enum Constraint
  {
    decreasing_in_position_2 = 0, ///< max of T_x T_y / |T|^2 over the flank (position 2)
    flanks_do_not_overlap,        ///< max(-x)/m over the flank (position 1)
    contact_ratio_minimum,        ///< eps_min - eps
    positive_relative_curvature,  ///< -min(1/R) m: 1/R <= 0 means the flanks cross (interference)
    reaches_gear2_tip,            ///< case 2: (r_a2 - r2 of the lowest flank point)/m: the path meets gear 2's tip
    rack_above_cutter_tip,        ///< case 2: (-h_fP* m - lowest recovered rack v)/m
    rack_monotone,                ///< case 2: recovered rack u strictly monotone (max step against the trend / mean step)
    n_constraints
  };
  const char *constraint_name(int c);

  /// One evaluated design.
  struct Evaluation
  {
    bool feasible = false;
    std::string reason;      ///< why it is infeasible (empty when feasible)
    bool computable = false; ///< statistics and constraints exist (false: geometry failed)
    double objective = 0;    ///< [1/mm]
    Statistics stats;        ///< of 1/R [1/m]
    double integral = 0;     ///< int (1/R)^2 dx [1/mm] (case 2's first term, before the 2.5)
    double x_extent = 0;     ///< |x(end) - x(start)| of the sampled flank in position 2 [mm]
    double contact_ratio = 0;
    double start_radius = 0; ///< first sample's pinion radius [m]
    std::vector<double> constraints = std::vector<double>(n_constraints, 1.0);
    std::vector<ContactSample> samples;
  };

  /// Case 2: which end control point is fixed (the thesis fixes 2 of the 10 coordinates
  /// without saying which).
  enum class FixedEnd
  {
    tip, ///< P4 on the involute 0.001 m beyond the tip circle; P0..P3 free (tip thickness kept)
    root ///< P0 at the start fit's P0 (below the SAP); P1..P4 free (the tip may move)
  };

  /// A design: its kind, the pair and the free coordinates.
  class Design
  {
  public:
    Design(DesignKind kind, const PairData &pair, FixedEnd fixed_end = FixedEnd::tip);
    DesignKind kind() const { return kind_; }
    const PairData &pair() const { return pair_; }
    /// Number of free coordinates (0 for the references, 4 case 1, 8 case 2).
    int n_free() const;
    /// The start point described in the header [module units].
    std::vector<double> default_start() const;
    /// Names of the free coordinates ("u1", "x0", ...), for tables and messages.
    std::vector<std::string> free_names() const;
    /// Control points [module units] (B-spline kinds) for the free coordinates x.
    std::vector<Vec2> control_points(const std::vector<double> &x) const;
    /// Pinion flank (pinion body frame, SI) and, for rack kinds, its rack.
    geometry::CurvePtr flank(const std::vector<double> &x) const;
    geometry::CurvePtr rack(const std::vector<double> &x) const;
    /// gearfem's gear parameters for a B-spline design (case 1: bspline rack, case 2:
    /// bspline flank), with the cutter data of PairData.
    geometry::GearParameters gear_parameters(int i, const std::vector<double> &x) const;
    /// Evaluate objective, statistics and constraints. Never throws for a bad design:
    /// failures become an infeasible Evaluation with a named reason.
    Evaluation evaluate(const std::vector<double> &x, const EvaluationSettings &s) const;

  private:
    Evaluation evaluate_unchecked(const std::vector<double> &x, const EvaluationSettings &s) const;
    /// Case 2: least-squares fit of P0..P3 to the involute with P4 = tip_point_ [module units].
    std::vector<Vec2> involute_fit() const;
    DesignKind kind_;
    PairData pair_;
    FixedEnd fixed_end_;
    Vec2 tip_point_;  ///< case 2: P4 of the start fit [module units]
    Vec2 root_point_; ///< case 2: P0 of the start fit [module units]
  };

  /// Objective of a case from the statistics [1/mm]; `weights` are case 2's (w0, w1, w2) of
  /// w0 int (1/R)^2 dx + w1 std(1/R) + w2/eps (EvaluationSettings::weights).
  double objective(DesignKind kind, const Statistics &st_per_m, double integral_per_mm,
                   double contact_ratio, const std::array<double, 3> &weights = {2.5, 1.0, 0.1});
} // namespace gearfem::optimise
