#pragma once
// AGMA 925-A03 scuffing along the path of contact (Siasos 2010, sec. 4.4), in
// consistent SI units: flash temperature (Blok), central film thickness (Dowson-Toyoda),
// specific film thickness lambda, contact temperature and scuffing probability with its
// risk class. Walther viscosity and the pressure-viscosity constants per oil type.
// The thesis prints U = eta v_e/(2 E_r rho_n) with mixed units; here eta [Pa s],
// v_e [m/s], E_r [Pa], rho_n [m] make G, U, W dimensionless. No deal.II.
#include "rating/agma.h"
#include "rating/iso6336.h"

#include <string>
#include <vector>

namespace gearfem::gearbox::scuffing
{
  namespace agma    = rating::agma;    // AGMA 2101-D04 / 908-B89 (lib/rating)
  namespace iso6336 = rating::iso6336; // ISO 6336-2/-3 (lib/rating)

  struct Lubricant
  {
    std::string type = "mineral"; ///< mineral|PAO|PAG|MIL-L-7808K|MIL-L-23699E (AGMA 925 table 6)
    bool extreme_pressure = true; ///< EP additives (theta_S = 118 + 33 ln nu40, else 63 + ...)
    double nu40 = 220;            ///< kinematic viscosity at 40 C [mm^2/s]
    double eta40 = 194.2414e-3;   ///< dynamic viscosity at 40 C [Pa s]
    double eta100 = 15.98296e-3;  ///< dynamic viscosity at 100 C [Pa s]
  };
  /// (k, s) of alpha = k eta^s, alpha [mm^2/N], eta [mPa s] (Siasos 2010 eq. 4.4-48).
  /// Throws InputError for an unknown type.
  void pressure_viscosity_constants(const std::string &type, double &k, double &s);
  /// Walther/ASTM D341 through eta40 and eta100 (Siasos 2010 eqs. 4.4-45/46) [Pa s] at theta [C].
  double viscosity(const Lubricant &oil, double theta);
  /// alpha = k eta^s [1/Pa] at eta [Pa s].
  double pressure_viscosity(const Lubricant &oil, double eta);
  /// theta_S [C] (Siasos 2010 eqs. 4.4-58/59).
  double scuffing_temperature(const Lubricant &oil);
  /// Phi((theta_B - theta_S)/(0.15 theta_S)) without clamping (Siasos 2010 eq. 4.4-60).
  double probability_unclamped(double theta_B, double theta_S);
  /// The same clamped to [0.05, 0.95], as AGMA 925 reports it.
  double probability(double theta_B, double theta_S);
  /// Risk class of AGMA 925 table 4.4-2: < 10 % low, 10-30 % medium, > 30 % high.
  std::string risk(double P);

  struct Conditions
  {
    double theta_oil = 70.0; ///< oil inlet/sump temperature [C] (not given by Siasos 2010)
    double k_sump = 1.0;     ///< 1.0 oil bath, 1.2 spray (Siasos 2010 eq. 4.4-55)
    double Ra1 = 0.5e-6, Ra2 = 0.5e-6; ///< arithmetic mean roughness [m]
    double B_M1 = 13.6, B_M2 = 13.6;   ///< thermal contact coefficients [N/(mm s^0.5 K)]
    double E1 = 206e9, nu1 = 0.3, E2 = 206e9, nu2 = 0.3;
    double L_x = 0.8e-3;     ///< roughness filter length [m] (eq. 4.4-51)
    int points = 25;         ///< points from A to E (25..50)
  };
  /// Throws InputError naming the entry for out-of-range conditions.
  void check(const Conditions &c, const Lubricant &oil);

  struct PathPoint
  {
    double roll = 0;             ///< xi = C/r_b1 [rad]
    double rho1 = 0, rho2 = 0;   ///< radii of curvature [m]
    double rho_n = 0;            ///< normal relative radius of curvature [m] (eq. 4.4-20/21)
    double X = 0;                ///< load sharing X_Gamma
    double v1 = 0, v2 = 0;       ///< rolling speeds [m/s]
    double b_H = 0;              ///< Hertzian semi-width [m]
    double theta_fl = 0;         ///< flash temperature [K]
    double h_c = 0;              ///< central film thickness [m]
    double lambda = 0;           ///< specific film thickness
    double theta_B = 0;          ///< contact temperature [C]
  };
  struct Result
  {
    std::vector<PathPoint> path;
    double mu_m = 0, w_n = 0, E_r = 0;            ///< [-, N/m, Pa]
    double theta_fl_max = 0, theta_M = 0, theta_B_max = 0, theta_S = 0; ///< [K, C, C, C]
    double eta_M = 0, alpha = 0;                  ///< at theta_M [Pa s, 1/Pa]
    double h_c_min = 0, lambda_min = 0;
    double P_unclamped = 0, P = 0;
    std::string risk;
  };
  /// Evaluate a spur mesh: l its unit-module line of action (agma.h), m the module [m],
  /// b the face width [m], n1 the pinion speed [rpm] (relative to the carrier for a
  /// planetary mesh), F the tangential load with K_o K_v K_H applied [N] (eqs. 4.4-28..30).
  Result evaluate(const agma::LineOfAction &l, double m, bool internal, double b, double n1,
                  double F, const Lubricant &oil, const Conditions &c);
} // namespace gearfem::gearbox::scuffing
