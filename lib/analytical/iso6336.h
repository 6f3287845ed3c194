#pragma once
// ISO 6336 (2006 edition), spur and helical external gears, method B where it applies.
// SI units inside; the stiffness results are also given in the standard's N/(mm um).
//  - Part 1: single stiffness c', mesh stiffness c_gamma_alpha, c_gamma_beta (clause 9).
//  - Part 2: contact stress sigma_H with Z_H, Z_E, Z_eps, Z_beta, Z_B/Z_D.
//  - Part 3: root stress with the 30-degree tangent construction on a generated fillet
//    (any fillet curve), and the standard's closed form for a rack-generated fillet.
#include <functional>
#include <string>

namespace gearfem::analytical::iso6336
{
  // ---------------------------------------------------------------- Part 1 (stiffness)
  struct StiffnessInput
  {
    int z1 = 0, z2 = 0;          ///< numbers of teeth (z2 < 0: internal gear, q' uses z_n2 = inf)
    double x1 = 0.0, x2 = 0.0;   ///< profile shift coefficients
    double beta = 0.0;           ///< helix angle [rad]
    double alpha_n = 0.0;        ///< normal pressure angle of the basic rack [rad]
    double module = 0.0;         ///< m_n [m]
    double h_fP1 = 1.25, h_fP2 = 1.25; ///< basic-rack dedendum / m_n of each gear (C_B)
    double rim_ratio = 1.0;      ///< b_s/b, web thickness over face width (1 = solid, C_R = 1)
    double rim_thickness = 0.0;  ///< s_R [m] (only used when rim_ratio < 1)
    double C_M = 0.8;            ///< theoretical-to-measured correction (ISO 6336-1: 0.8)
    double eps_alpha = 0.0;      ///< transverse contact ratio
    double eps_beta = 0.0;       ///< overlap ratio (0 for spur)
    /// F_t K_A/b [N/m]; 0 means ">= 100 N/mm" (no load correction).
    double load_per_width = 0.0;
  };

  struct Stiffness
  {
    double q_prime = 0;       ///< minimum flexibility q' [mm um/N] (the standard's unit)
    double c_th = 0;          ///< theoretical single stiffness 1/q' [N/(mm um)]
    double C_M = 0, C_R = 0, C_B = 0;
    double load_factor = 1;   ///< (F_t K_A/b/100)^0.25 below 100 N/mm, else 1
    double c_prime = 0;       ///< c' [N/(mm um)]
    double c_gamma_alpha = 0; ///< c' (0.75 eps_alpha + 0.25) [N/(mm um)]
    double c_gamma_beta = 0;  ///< 0.85 c_gamma_alpha [N/(mm um)]
  };

  /// q' = 0.04723 + 0.15551/z_n1 + 0.25791/z_n2 - 0.00635 x1 - 0.11654 x1/z_n1 - 0.00193 x2
  ///      - 0.24188 x2/z_n2 + 0.00529 x1^2 + 0.00182 x2^2   [mm um/N]   (ISO 6336-1 eq. 71)
  double q_prime(double zn1, double zn2, double x1, double x2);
  /// All of clause 9 (method B). Throws InputError for z < 5, alpha_n out of range, etc.
  Stiffness mesh_stiffness(const StiffnessInput &in);

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
  /// A plane curve given by functions (so that any fillet, rack-generated or not, can be
  /// used). Tooth frame: gear centre at the origin, tooth axis +y, this curve on the x > 0
  /// side or the x < 0 side (|x| is used). Units m.
  struct PlaneCurve
  {
    std::function<double(double, int)> x, y; ///< (t, derivative order 0..2)
    double t0 = 0, t1 = 1;
  };

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
} // namespace gearfem::analytical::iso6336
