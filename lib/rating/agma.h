#pragma once
// AGMA 2101-D04 rating factors and AGMA 908-B89 geometry factors for external spur
// gears (Siasos 2010, ch. 4). The AGMA procedures work in unit module (all
// lengths divided by m_n) and in N, mm, N/mm^2; the C++ interface is SI.
#include "rating/iso6336.h"

#include <string>

namespace gearfem::rating::agma
{
  /// Distances along the line of action (AGMA 908 eqs. 4.3-12..19), unit module.
  struct LineOfAction
  {
    double mG = 0;           ///< gear ratio z2/z1
    double R1 = 0, R2 = 0;   ///< standard pitch radii
    double Rb1 = 0, Rb2 = 0; ///< base radii
    double Ro1 = 0, Ro2 = 0; ///< tip radii
    double Cr = 0;           ///< operating centre distance
    double phi_r = 0;        ///< operating transverse pressure angle [rad]
    double pb = 0;           ///< base pitch
    double C1 = 0, C2 = 0, C3 = 0, C4 = 0, C5 = 0, C6 = 0;
    double contact_ratio = 0; ///< m_p = (C5 - C1)/p_b
  };
  /// @param ro1, ro2 tip radii [m]; @param a operating centre distance [m]; m module [m].
  LineOfAction line_of_action(int z1, int z2, double module, double phi_n, double ro1, double ro2,
                              double a);

  /// Pitting geometry factor Z_I = cos phi_r/((1/rho1 + 1/rho2) d m_N) for spur gears
  /// (C_psi = m_N = 1), rho1 = C2 at the LPSTC, rho2 = C6 - rho1, d = 2 Cr/(mG + 1)
  /// (AGMA 908-B89; Siasos 2010 eqs. 4.3.1-1, -4, -5).
  double geometry_factor_I(const LineOfAction &loa);

  /// Internal mesh (Siasos 2010 sec. 4.3 with the lower signs, eq. 2.2.2-1): gear 2 is the
  /// internal gear, ro2 its tip (inner) radius [m], a = r_w2 - r_w1 [m];
  /// phi_r = acos((R_b2 - R_b1)/C_r), C1 = sqrt(R_o2^2 - R_b2^2) - C6, C3 = C6/(m_G - 1).
  /// Throws InputError when C1 <= 0 (the ring tip cuts the pinion below its base circle:
  /// involute interference).
  LineOfAction line_of_action_internal(int z1, int z2, double module, double phi_n, double ro1,
                                       double ro2, double a);
  /// Z_I of an internal mesh: cos phi_r/((1/rho1 - 1/rho2) d), rho1 = C2, rho2 = C6 + rho1,
  /// d = 2 C_r/(m_G - 1) (Siasos 2010 sec. 4.3, lower signs).
  double geometry_factor_I_internal(const LineOfAction &loa);

  /// Generating tool of AGMA 908 (unit module). A hob is a shaper with n_o -> infinity;
  /// the standard (and Siasos 2010) use n_o = 10000.
  struct Tool
  {
    double n_o = 10000;     ///< number of teeth of the shaper cutter
    double s_no = 1.5708;   ///< tool tooth thickness at its reference circle
    double h_ao = 1.25;     ///< tool addendum
    double x_o = 0.0;       ///< tool addendum modification (Siasos 2010 table lists 1.0; see docs)
    double rho_ao = 0.25;   ///< tool tip radius
    double delta_ao = 0.0;  ///< protuberance
  };

  /// The Lewis-parabola construction of AGMA 908-B89 (Siasos 2010 eqs. 4.3.2-2..46).
  struct BendingGeometry
  {
    double tan_phi_nW = 0;  ///< load point (HPSTC): C4/r_nb
    double phi_nL = 0;      ///< load angle [rad]
    double r_nL = 0;        ///< load radius (unit module)
    double alpha_n = 0;     ///< converged generating parameter [rad]
    int iterations = 0;     ///< Newton iterations from alpha_n = pi/4
    double s_F = 0;         ///< critical-section thickness 2 xi_nF (unit module)
    double h_F = 0;         ///< Lewis parabola height (unit module)
    double rho_F = 0;       ///< minimum fillet radius (unit module)
    double K_f = 0;         ///< stress correction H + (s_F/rho_F)^L (s_F/h_F)^M
    double Y = 0;           ///< tooth form factor
    double Y_J = 0;         ///< bending geometry factor Y C_psi/(K_f m_N)
  };
  /// @param n number of teeth; @param x_g profile shift; @param tan_phi_nW load point;
  /// @param phi_n normal pressure angle; @param phi_nr operating normal pressure angle.
  /// Throws SolverError when the Newton iteration does not converge.
  BendingGeometry geometry_factor_J(int n, double x_g, double tan_phi_nW, double phi_n,
                                    double phi_nr, const Tool &tool = Tool());

  /// Y, K_f and Y_J from the Lewis-parabola section (unit module or any consistent
  /// length unit): K_f = H + (s_F/rho_F)^L (s_F/h_F)^M, Y = 1/[(cos phi_nL/cos phi_nr)
  /// (6 h_F/s_F^2 - tan phi_nL/s_F)] (AGMA 908-B89; Siasos 2010 eqs. 4.3.2-44, -46; spur).
  void form_and_stress_factors(BendingGeometry &g, double phi_n, double phi_nr);

  /// The Lewis parabola inscribed in a generated fillet (any curve, e.g. the exact
  /// ProfileSegment fillet of lib/geometry): the point F where the parabola with vertex
  /// at the load point (0, y_L) on the tooth axis is tangent to the fillet,
  /// 2 h_F tan(beta) = |x_F| with h_F = y_L - y_F, bracketed on a sample and found by
  /// bisection on the curve parameter (base::find_root_bisection). Lengths in the curve's units. rho_F is the minimum radius of
  /// curvature of the fillet (AGMA takes it at the root, 4.3.2-40).
  struct LewisSection
  {
    double t = 0, s_F = 0, h_F = 0, rho_F = 0, y_F = 0;
  };
  LewisSection lewis_section(const analytical::PlaneCurve &fillet, double y_L);

  /// Gear-unit class for the mesh-alignment factor K_Hma = A + B b + C b^2 (b in mm;
  /// AGMA 2101-D04 table 3, Siasos 2010 table 4.1.6-1).
  enum class Enclosure
  {
    open,
    commercial,
    precision,
    extra_precision
  };
  Enclosure enclosure_from_string(const std::string &s);
  const char *to_string(Enclosure e);
  double K_Hma(double b, Enclosure e);
  /// Pinion proportion factor K_Hpf (Siasos 2010 eqs. 4.1.6-5..7), b and d in m; b/(10 d)
  /// is raised to 0.05 when smaller.
  double K_Hpf(double b, double d);
  /// Rim thickness factor K_B (m_B = t_R/h_t; 1 for m_B >= 1.2).
  double K_B(double backup_ratio);
  /// Elastic coefficient Z_E = sqrt(1/(pi((1-nu1^2)/E1 + (1-nu2^2)/E2))) [sqrt(Pa)].
  double Z_E(double E1, double nu1, double E2, double nu2);
} // namespace gearfem::rating::agma
