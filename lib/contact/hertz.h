#pragma once
// Two elastic discs pressed together (2-D Hertz line contact), the closed-form check of
// the contact solver. Body 1 (radius R1, centre (0, 0)) is pushed by a rigid translation
// along +y against body 2 (radius R2, centre (0, R1 + R2)); both bores are clamped. Closed
// form (Johnson, Contact Mechanics, 1985, sec. 4.3, eqs. 4.43-4.45), P = load per unit
// thickness: a^2 = 4 P R / (pi E*), p0 = 2 P / (pi a), p(s) = p0 sqrt(1 - s^2/a^2), with
// 1/R = 1/R1 + 1/R2 and 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 in plane strain, 1/E1 + 1/E2
// in plane stress. With unequal thicknesses t1, t2 each body's compliance is that of its own
// thickness, 1/(E* t) -> (1/E1' t1 + 1/E2' t2), a^2 = 4 F R (1/(E1' t1) + 1/(E2' t2)) / pi, and
// the line load q0 = 2 F / (pi a) acts over the common width min(t1, t2): p0 = q0 / min(t1, t2).
// SI units.
#include "contact/two_body.h"
#include "fem/elasticity.h"

#include <array>
#include <vector>

namespace gearfem::contact
{
  struct HertzCase
  {
    double R1 = 20e-3, R2 = 20e-3;   ///< disc radii [m]
    double E1 = 210e9, E2 = 210e9;   ///< [Pa]
    double nu1 = 0.3, nu2 = 0.3;
    double thickness = 10e-3;        ///< [m]
    double thickness2 = 0;           ///< body 2's thickness [m]; 0: `thickness`
    double force = 10e3;             ///< total normal force [N]
    fem::PlaneModel model = fem::PlaneModel::plane_stress;
    double h_contact = 0;            ///< element size at the contact [m]; 0: a/8
    double h_body    = 2e-3;         ///< element size far away [m]
    unsigned int degree = 2;
    Method method = Method::lagrange;
    double penalty_factor = 100.0;
    int slave = 0;                   ///< body carrying the slave nodes; 0: the softer (tie: 1)
  };

  /// Closed-form half-width a [m] and peak pressure p0 [Pa].
  std::pair<double, double> hertz_closed_form(const HertzCase &c);

  struct HertzResult
  {
    double a_exact = 0, p0_exact = 0;
    double a_fit = 0, p0_fit = 0;  ///< least-squares ellipse through the nodal pressures
    double p0_nodal = 0;           ///< largest nodal pressure
    double profile_error = 0;      ///< RMS of (p_h - p_exact) over the contact nodes / p0_exact
    double force_balance = 0;      ///< max over bodies |resultant of nodal contact forces -/+ F| / F
    int n_active = 0;              ///< slave nodes in contact
    unsigned int n_dofs = 0;       ///< both bodies
    double h_contact = 0;
    double seconds = 0;            ///< mesh + assemble + solve
    std::vector<std::pair<double, double>> profile; ///< (s [m], p [Pa]) of the contact nodes
    ContactSolution solution;
  };

  /// Mesh, solve and compare with the closed form.
  HertzResult solve_hertz(const HertzCase &c);

  /// Ellipse fit p^2 = p0^2 (1 - (s - s0)^2 / a^2) to (s, p) samples with p > 0 (linear least
  /// squares in p^2 = c0 + c1 s + c2 s^2). Returns {a, p0, s0}; zeros when it is degenerate
  /// (fewer than 3 samples or no downward curvature).
  std::array<double, 3> fit_ellipse(const std::vector<std::pair<double, double>> &samples);
} // namespace gearfem::contact
