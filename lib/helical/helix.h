#pragma once
// Helical pairs by face-width slicing: the helix of a pair whose transverse section is the
// 2-D pair gearfem generates (ISO 21771 conventions), where the slices of the face sit on
// the roll angle, and the lead modifications and misalignment as gap offsets along the face.
// SI units. No deal.II (light module).
#include "geometry/parameters.h"

#include <string>
#include <vector>

namespace gearfem::helical
{
  /// Lead modifications and misalignment along the face width [m]. All are amounts in the
  /// transverse plane along the line of action (normal to the involute, as ISO 1328-1 measures
  /// helix deviations), summed over both gears; z runs over [-b/2, b/2] from gear 1's
  /// reference face.
  struct LeadModification
  {
    double crowning = 0;          ///< C_beta: removed at each end by a parabolic crowning
    double end_relief = 0;        ///< C_I: removed at each end by a linear end relief
    double end_relief_length = 0; ///< b_I: length of each end relief from its end
    /// f_Hbeta: helix slope deviation over the face width, > 0 opens the gap towards z = +b/2.
    double slope = 0;
    /// f_Sigma_beta: inclination of the axes (out of their plane) over the face width; it
    /// tilts the plane of action by f cos(alpha_wt).
    double misalignment = 0;
    /// f_Sigma_delta: deviation of the axes in their plane over the face width: the centre
    /// distance changes along the face, which tilts the contact by f sin(alpha_wt) (the
    /// change of the slices' working pressure angle with it is not represented).
    double deviation = 0;
    /// A gap offset along the face given point by point (z [m] over [-b/2, b/2], increasing;
    /// gap [m]), interpolated linearly and held at the ends; empty: none. The shaft-and-bearing
    /// coupling (system_deflection/coupled.h) gives the mismatch of its deflections this way.
    std::vector<double> profile_z, profile_gap;
    /// The linear part: f_Hbeta + f_Sigma_beta cos(alpha_wt) + f_Sigma_delta sin(alpha_wt).
    double mesh_misalignment(double alpha_wt) const;
  };

  /// How the slices of one tooth pair are joined across the face (helical/slicing.h).
  enum class Coupling
  {
    bending, ///< a beam along the face on the sections' foundation (free ends)
    shear    ///< a Pasternak shear layer between neighbouring sections
  };

  /// What joins the sections of the face (helical/slicing.h).
  enum class FaceModel
  {
    slices, ///< the beam (or shear layer) of the `Coupling` entries
    solid   ///< the coarse 3-D FE body of each gear (three_d/face_compliance.h)
  };

  /// The 3-D FE model of the face (`Helical/Model = 3-D FE`).
  struct SolidFace
  {
    double element_size = 0;  ///< of the coarse section [m]; 0: m_n / 3
    unsigned degree     = 2;  ///< FE_Q(p), {1, 2}
    int layers_per_slice = 1; ///< cells across one slice
    int flank_points    = 7;  ///< grid points over each drive flank
    int sector_teeth    = 3;  ///< teeth of each gear's sector, odd, >= 1
  };

  /// The `Helical` section.
  struct HelixInput
  {
    double beta = 0;  ///< helix angle at the reference circle [rad], 0 <= beta < 45 deg
    int hand = 1;     ///< +1: gear 1 right hand (gear 2 left); -1: gear 1 left hand
    /// true: the Rack and Gear sections give the normal section (m_n, alpha_n, x_n, rack
    /// coefficients in m_n), converted to the transverse section by transverse_section();
    /// false: they give the transverse section itself.
    bool normal_section = true;
    int slices = 21;  ///< slices over the face width
    Coupling coupling = Coupling::bending;
    /// Length l of the coupling between neighbouring slices [m] (helical/slicing.h): a point
    /// load spreads over an effective width 2 l; 0: uncoupled slices; < 0: one normal module.
    double coupling_length = -1;
    FaceModel model = FaceModel::slices;
    SolidFace solid;
    LeadModification lead;
  };

  /// The transverse section of a helical pair given in its normal section (ISO 21771):
  /// m_t = m_n / cos(beta), tan(alpha_t) = tan(alpha_n) / cos(beta), and every length given in
  /// normal modules keeps its length (x_t m_t = x_n m_n; the rack's addendum, dedendum, root
  /// and tip radius, the tip shortening; the thickness allowance becomes s_n / cos(beta)).
  /// The rack's root radius rho in the transverse plane is an ellipse with radii of curvature
  /// from rho cos(beta) to rho / cos^2(beta); it is kept as the circle of radius rho.
  /// InputError for a B-spline rack (its normal section is not defined here).
  geometry::GeometryInput transverse_section(const geometry::GeometryInput &normal, double beta);

  /// The helix of a pair: angles [rad], lengths [m].
  struct Helix
  {
    double beta = 0, beta_b = 0;       ///< at the reference and the base cylinder
    double m_n = 0, m_t = 0;           ///< normal and transverse module
    double alpha_n = 0, alpha_t = 0;   ///< normal and transverse pressure angle of the rack
    double face_width = 0;             ///< b
    double axial_pitch = 0;            ///< p_x = pi m_n / sin(beta) (infinite for spur)
    double overlap_ratio = 0;          ///< eps_beta = b sin(beta) / (pi m_n)
    /// Roll angle of gear 1 by which the transverse section at axial position z lags the
    /// section at z = 0: hand z tan(beta_b) / r_b1 per unit z [rad/m].
    double roll_per_length = 0;
  };
  /// From the transverse module m_t and rack pressure angle alpha_t of the 2-D pair, the
  /// base radius r_b1 of gear 1, the face width b and the helix of `in`.
  Helix helix(const HelixInput &in, double m_t, double alpha_t, double r_b1, double b);

  /// Centres of n equal slices of [-b/2, b/2] [m].
  std::vector<double> slice_centres(double b, int n);

  /// The gap offset of `m` at axial position z (material removed, >= 0) [m]: the crowning
  /// C_beta (2z/b)^2, the end reliefs, the mesh misalignment as a linear opening that is
  /// zero at the tight end, and the point-by-point profile.
  double lead_gap(const LeadModification &m, double z, double b, double alpha_wt);

  /// InputError for a profile whose positions are not increasing within [-b/2, b/2], whose
  /// lengths differ or whose gaps are not finite.
  void check_profile(const LeadModification &m, double face_width);

  /// InputError naming the `Helical` entry of the first value out of range.
  void check(const HelixInput &in, double face_width);
} // namespace gearfem::helical
