#pragma once
// Tooth compliance models on a generic tooth: a variable-section cantilever along the
// tooth axis with thickness t(y). SI units (m, N, Pa, rad); compliances in m/N.
//
// One beam part serves both families of models, because for the same integration
// limits they are the same integrals:
//  - Weber/Cornell (Gkimisis 2019 eq. 3.4): C_b = 12 cos^2 phi [I2 + (0.2(1+nu) + tan^2 phi/12) I1]
//  - potential energy (Yang & Lin 1987; Tian 2004; Chen & Shao 2011): 1/k_b + 1/k_s + 1/k_a
//    with M = F cos phi (d - y) - F sin phi h, 1.2 shear factor, axial sin^2 phi.
// They differ in the foundation (O'Donnell vs Sainsot) and the Hertz term (Weber's
// load-dependent log term vs the constant pi E b/(4(1-nu^2))).
#include "analytical/elastic.h"

#include <functional>
#include <vector>

namespace gearfem::analytical
{
  /// A tooth as a cantilever clamped at the root circle. Heights y along the tooth axis
  /// are measured from the root circle (y = r - r_f on the axis).
  struct ToothBeam
  {
    std::function<double(double)> thickness; ///< full chordal thickness t(y) [m], y in [0, height]
    double height = 0.0;                      ///< root circle to tip along the axis [m]
    std::vector<double> breakpoints;          ///< heights where t(y) has a kink (fillet/involute) [m]
    double root_radius = 0.0;                 ///< r_f [m] (Sainsot h_fi, theta_f)
    double rim_inner_radius = 0.0;            ///< r_int: bore or rim inner radius [m] (Sainsot)
  };

  /// How the tooth is loaded (one contact point on the flank).
  struct ToothLoad
  {
    double phi = 0.0;       ///< load angle phi_F between the load line and the normal to the tooth axis [rad]; > 0 when the radial component compresses the tooth
    double y_contact = 0.0; ///< height of the contact point above the root circle, d [m]
    double h = 0.0;         ///< half-thickness at the contact = its distance from the axis [m]
    double rho = 0.0;       ///< profile radius of curvature at the contact (> 0 convex) [m]
    /// Height where the load line meets the tooth axis, Psi = d - h tan phi [m].
    double y_axis() const;
    /// Distance from the contact to the tooth axis along the load line, h/cos phi [m]
    /// (Weber's K_E in the Hertz log term).
    double depth_to_axis() const;
  };

  /// Thickness integrals I1 = int_0^d dy/t and I2 = int_0^d (y - Psi)^2/t^3 dy (both
  /// dimensionless), by adaptive quadrature up to the contact height d (the PE limit;
  /// Gkimisis 2019 integrates to Psi, which differs by the thin tip above the load line).
  struct BeamIntegrals
  {
    double I1 = 0.0, I2 = 0.0;
  };
  BeamIntegrals beam_integrals(const ToothBeam &tooth, const ToothLoad &load);

  /// Weber/Cornell dimensionless bending+shear+axial compliance (Gkimisis 2019 eq. 3.4):
  /// C_b = 12 cos^2 phi [I2 + (0.2(1+nu') + tan^2 phi/12) I1] = E' b delta_b/F.
  double weber_beam_coefficient(const BeamIntegrals &I, double phi, double nu);

  /// Beam compliance delta/F [m/N] = C_b/(E' b) with b the face width [m].
  double beam_compliance(const ToothBeam &tooth, const ToothLoad &load, double b,
                         const PlaneElastic &mat);

  /// The three potential-energy parts separately [m/N] (Tian 2004 eqs.; identical sum).
  struct BeamParts
  {
    double bending = 0.0, shear = 0.0, axial = 0.0;
    double total() const { return bending + shear + axial; }
  };
  BeamParts beam_compliance_parts(const ToothBeam &tooth, const ToothLoad &load, double b,
                                  const PlaneElastic &mat);

  /// Constant of the first O'Donnell term. Cornell (1981, eq. 11) prints 16.67/pi =
  /// 50/(3 pi); Gkimisis 2019 eq. 3.7 has 50/(2 pi). Default: Cornell (docs/analytical.md).
  enum class ODonnellConstant
  {
    cornell_50_over_3pi,
    seed000_50_over_2pi
  };

  /// O'Donnell (1960) foundation, in Cornell's form (Gkimisis 2019 eq. 3.7; the NTUA
  /// tooth-mass thesis), as a dimensionless coefficient E' b delta_f/F:
  ///   (1-nu^2) cos^2 phi [c X^2 + 2(1-2nu)/(1-nu) X + (4.82/pi)(1 + tan^2 phi/(2.4(1+nu)))]
  /// with X = Psi/t_f (t_f the root thickness) and nu the plane-strain-equivalent Poisson
  /// ratio (the formula is a plane-strain result; its (1-nu^2)/E is 1/E').
  double odonnell_foundation_coefficient(double X, double phi, double nu_plane_strain,
                                         ODonnellConstant c = ODonnellConstant::cornell_50_over_3pi);

  /// O'Donnell foundation compliance [m/N].
  double odonnell_foundation_compliance(const ToothBeam &tooth, const ToothLoad &load, double b,
                                        const PlaneElastic &mat,
                                        ODonnellConstant c = ODonnellConstant::cornell_50_over_3pi);

  /// Sainsot, Velex & Duverger (2004) polynomial coefficients L*, M*, P*, Q*:
  /// X* = A/theta_f^2 + B h_fi^2 + C h_fi/theta_f + D/theta_f + E h_fi + F.
  struct SainsotCoefficients
  {
    double L, M, P, Q;
  };
  /// @param h_fi r_f/r_int [-]; @param theta_f half tooth angle at the root circle [rad].
  SainsotCoefficients sainsot_coefficients(double h_fi, double theta_f);

  /// Sainsot fillet-foundation compliance [m/N]:
  /// delta_f/F = cos^2 phi/(E' b) [L* (u_f/S_f)^2 + M* (u_f/S_f) + P* (1 + Q* tan^2 phi)],
  /// u_f = Psi, S_f = t(0), theta_f = S_f/(2 r_f), h_fi = r_f/r_int (plane stress in E').
  /// Throws InputError when the rim inner radius is not set or h_fi is outside [1, 10].
  double sainsot_foundation_compliance(const ToothBeam &tooth, const ToothLoad &load, double b,
                                       const PlaneElastic &mat);
} // namespace gearfem::analytical
