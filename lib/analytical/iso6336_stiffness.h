#pragma once
// ISO 6336-1:2006 clause 9 (method B): single stiffness c', mesh stiffness c_gamma_alpha and
// c_gamma_beta of spur and helical external gears; SI inside, the standard's N/(mm um) in the
// results. A compliance model like the others of this module (the ratings of ISO 6336-2/-3
// are in lib/rating).
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

  /// z_n = z / (cos^2 beta_b cos beta).
  /// q' = 0.04723 + 0.15551/z_n1 + 0.25791/z_n2 - 0.00635 x1 - 0.11654 x1/z_n1 - 0.00193 x2
  ///      - 0.24188 x2/z_n2 + 0.00529 x1^2 + 0.00182 x2^2   [mm um/N]   (ISO 6336-1 eq. 71)
  double q_prime(double zn1, double zn2, double x1, double x2);
  /// All of clause 9 (method B). Throws InputError for z < 5, alpha_n out of range, etc.
  Stiffness mesh_stiffness(const StiffnessInput &in);

  /// The face load factor K_Hbeta of ISO 6336-1:2006 clause 7 (method C) from the effective
  /// equivalent misalignment F_beta_y: 1 + F_beta_y c_gamma_beta / (2 F_m/b) when that is <= 2,
  /// else sqrt(2 F_beta_y c_gamma_beta / (F_m/b)). Any consistent units (the standard's: um,
  /// N/(mm um), N/mm).
  double face_load_factor_method_c(double F_beta_y, double c_gamma_beta, double F_m_over_b);
} // namespace gearfem::analytical::iso6336
