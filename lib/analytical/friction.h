#pragma once
// The mean coefficient of friction of a lubricated gear mesh: a constant, the ISO/TR
// 14179-2:2001 law (Schlenk; the mean coefficient of the mesh from load, sum velocity and
// radius of curvature at the pitch point, oil viscosity and roughness), or the AGMA 925-A03
// coefficient (0.06 C_R, roughness only; used by `gearbox` for scuffing). The one definition
// of these laws: the contact solver (Contact section) and the gearbox both call them. Light
// layer (geometry only). SI at the interface of the functions; docs/friction.md. The
// entries are declared in the Contact section (contact/parameters.h) and read by solve/input.h.
#include "geometry/pair.h"

#include <string>

namespace gearfem::analytical::friction
{
  enum class Law
  {
    constant,   ///< mu given
    iso_14179_2, ///< ISO/TR 14179-2:2001, mean coefficient of the mesh
    agma_925    ///< AGMA 925-A03: 0.06 C_R
  };
  Law law_from_string(const std::string &s); ///< "constant" | "ISO/TR 14179-2" | "AGMA 925"
  const char *to_string(Law law);

  /// The friction entries of the Contact section, SI.
  struct LawInputs
  {
    Law law = Law::constant;
    double mu = 0.0;           ///< constant law [-]
    double pinion_speed = 0.0; ///< [rad/s]; > 0 (the law's speeds and the power loss)
    double eta_oil = 0.0;      ///< dynamic viscosity at the oil temperature [Pa s] (ISO/TR 14179-2)
    double Ra1 = 0.0, Ra2 = 0.0; ///< arithmetic mean roughness of the flanks [m]
    double X_L = 1.0;          ///< lubricant factor of ISO/TR 14179-2 (1: mineral oil)
  };
  /// InputError naming the Contact entry that the chosen law needs and lacks, or that is out
  /// of range ("Contact/Oil viscosity", ...).
  void check(const LawInputs &in);

  /// The state of the pair at the pitch point C that the laws read.
  struct PitchPoint
  {
    double load_per_width = 0; ///< F_bt / b: transverse load at the base circle per face width [N/m]
    double v_sum = 0;          ///< sum of the tangential (rolling) speeds at C [m/s]
    double rho_red = 0;        ///< reduced radius of curvature at C [m]
  };
  /// Pitch point C of `pair` under pinion torque T1 [N m] at pinion speed omega1 [rad/s],
  /// face width b [m]: F_bt = T1 / r_b1, v_sum = 2 omega1 r_w1 sin(alpha_w),
  /// rho_i = r_bi tan(alpha_w), rho_red = rho1 rho2/(rho1 + rho2) for an external pair and
  /// rho1 rho2/(rho2 - rho1) for a pinion in a ring (its concave flank).
  PitchPoint pitch_point(const geometry::MeshingPair &pair, double T1, double omega1, double b);

  /// AGMA 925-A03 (Siasos 2010 eqs. 4.4-53/54): 0.06 C_R, C_R = 1.13 / (1.13 - Ra_avg [um])
  /// clamped to [1, 3], Ra_avg = (Ra1 + Ra2) / 2.
  double agma_925(double Ra1, double Ra2);
  /// ISO/TR 14179-2:2001: mu_mz = 0.048 (F_bt/b / (v_sum rho_red))^0.2 eta_oil^-0.05 Ra^0.25 X_L,
  /// with F_bt/b [N/mm], v_sum [m/s], rho_red [mm], eta_oil [mPa s], Ra = (Ra1 + Ra2)/2 [um].
  double iso_14179_2(const PitchPoint &c, double eta_oil, double Ra1, double Ra2, double X_L);
  /// The coefficient of `in` at the pitch-point state `c`.
  double coefficient(const LawInputs &in, const PitchPoint &c);

  /// Ohlendorf's tooth loss factor of a spur pair under the idealised load sharing (one pair
  /// carries the whole load in single contact, half each in double contact): H_V =
  /// pi (u + 1) / (z1 u) (1 - eps_alpha + eps_1^2 + eps_2^2), eps_1, eps_2 the addendum
  /// contact ratios of pinion and gear (ISO/TR 14179-2:2001; Niemann & Winter, Maschinen-
  /// elemente II, 1989). The mesh power loss is P_V = P_in mu H_V.
  double ohlendorf_hv(const geometry::GearPair &pair);
} // namespace gearfem::analytical::friction
