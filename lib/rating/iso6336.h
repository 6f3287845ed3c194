#pragma once
// ISO 6336 (2006 edition), spur and helical external gears, method B where it applies.
// SI units inside; the stiffness results are also given in the standard's N/(mm um).
//  - Part 1 (stiffness, clause 9): lib/analytical/iso6336_stiffness.h, used here.
//  - Part 2: contact stress sigma_H with Z_H, Z_E, Z_eps, Z_beta, Z_B/Z_D.
//  - Part 3: root stress with the 30-degree tangent construction on a generated fillet
//    (any fillet curve), and the standard's closed form for a rack-generated fillet.
#include "analytical/iso6336_stiffness.h"
#include "analytical/plane_curve.h"

#include <string>

namespace gearfem::rating::iso6336
{
  // Part 1 (stiffness) is a compliance model: lib/analytical/iso6336_stiffness.h.
  using analytical::iso6336::StiffnessInput;
  using analytical::iso6336::Stiffness;
  using analytical::iso6336::q_prime;
  using analytical::iso6336::mesh_stiffness;
  using analytical::PlaneCurve;

  // ---------------------------------------------------------------- Part 2 (contact)
  struct ContactFactors
  {
    double Z_H = 0, Z_E = 0, Z_eps = 0, Z_beta = 1, Z_B = 1, Z_D = 1;
    double M1 = 0, M2 = 0;
    double sigma_H0 = 0;    ///< nominal contact stress at the pitch point [Pa]
    double sigma_H1 = 0;    ///< pinion: Z_B sigma_H0 sqrt(K_A K_v K_Hbeta K_Halpha) [Pa]
    double sigma_H2 = 0;    ///< wheel: Z_D ...
  };
  struct ContactInput
  {
    int z1 = 0, z2 = 0;
    double alpha_t = 0, alpha_wt = 0, beta = 0, beta_b = 0;
    double d1 = 0;                    ///< reference diameter of the pinion [m]
    double da1 = 0, da2 = 0, db1 = 0, db2 = 0; ///< tip and base diameters [m]
    double b = 0;                     ///< face width [m]
    double Ft = 0;                    ///< nominal tangential load at the reference circle [N]
    double E1 = 0, nu1 = 0, E2 = 0, nu2 = 0;
    double eps_alpha = 0, eps_beta = 0;
    double K_A = 1, K_v = 1, K_Hbeta = 1, K_Halpha = 1;
  };
  /// ISO 6336-2 eqs. 1-9 (Z_H eq. 10, Z_E eq. 11, Z_eps eq. 19 for spur, Z_B/Z_D eqs. 12-15).
  ContactFactors contact_stress(const ContactInput &in);

  // ---------------------------------------------------------------- Part 3 (root)
  /// The 30-degree tangent construction (ISO 6336-3 clause 6.2): the fillet point whose
  /// tangent makes 30 deg with the tooth axis, bracketed on a sample and found by
  /// bisection on the curve parameter (base::find_root_bisection).
  struct CriticalSection
  {
    double t = 0;      ///< curve parameter
    double s_Fn = 0;   ///< chord 2|x| [m]
    double y = 0;      ///< height of the chord above the gear centre [m]
    double rho_F = 0;  ///< fillet radius of curvature there [m]
  };
  CriticalSection critical_section(const PlaneCurve &fillet, double tangent_angle_deg = 30.0);

  /// An involute flank: base radius and half tooth angle at the base circle.
  struct InvoluteFlank
  {
    double rb = 0;    ///< [m]
    double psi_b = 0; ///< half tooth thickness angle at the base circle [rad]
  };

  /// Form and stress-correction factors for loading at radius r_e on the involute.
  struct RootFactors
  {
    double s_Fn = 0, h_Fe = 0, rho_F = 0, alpha_Fen = 0; ///< [m, m, m, rad]
    double Y_F = 0, Y_S = 0, L = 0, q_s = 0;
  };
  /// Y_F = 6 (h_Fe/m) cos a_Fen/[(s_Fn/m)^2 cos a_n], Y_S = (1.2 + 0.13 L) q_s^(1/(1.21 + 2.3/L))
  /// (ISO 6336-3 eqs. 24, 43) with h_Fe, a_Fen from the load line at r_e.
  RootFactors root_factors(const CriticalSection &cs, const InvoluteFlank &flank, double r_e,
                           double module, double alpha_n);

  /// The standard's own closed form for a rack-generated fillet (ISO 6336-3 eqs. 25-33,
  /// theta iteration from pi/6): s_Fn, rho_F and the height of the critical section, for
  /// an independent check of critical_section() on a generated fillet.
  struct RackFilletClosedForm
  {
    double theta = 0, s_Fn = 0, rho_F = 0, y = 0, G = 0, E = 0, H = 0;
  };
  RackFilletClosedForm rack_fillet_closed_form(int zn, double module, double alpha_n,
                                               double x, double h_fP, double rho_fP,
                                               double s_pr = 0.0);

  /// Contact ratio factor for the tip-load method, Y_eps = 0.25 + 0.75/eps_alpha_n.
  double Y_eps(double eps_alpha);
  /// Helix factor Y_beta = 1 - eps_beta beta/120deg (>= 0.75 rules of ISO 6336-3 eq. 48).
  double Y_beta(double eps_beta, double beta);
} // namespace gearfem::rating::iso6336
