#pragma once
// Plane elastic constants and Hertz line contact. SI units (Pa, m, N).
//
// Convention (docs/analytical.md): every 2-D formula in this module is written in its
// PLANE-STRESS form in the effective constants (E', nu'). Plane strain is obtained with
// the exact substitution E' = E/(1 - nu^2), nu' = nu/(1 - nu) (a plane-strain body with
// (E, nu) behaves like a plane-stress body with (E', nu')). The same switch as the FE
// ("plane stress" default, "plane strain" for validation) selects it.

namespace gearfem::analytical
{
  enum class PlaneCondition
  {
    plane_stress,
    plane_strain
  };

  /// Isotropic linear-elastic material [Pa, -].
  struct Material
  {
    double E = 206e9;
    double nu = 0.3;
  };

  /// Effective plane constants (E', nu') for the chosen plane condition.
  struct PlaneElastic
  {
    double E;  ///< E' [Pa]: E (plane stress) or E/(1-nu^2) (plane strain)
    double nu; ///< nu' [-]: nu (plane stress) or nu/(1-nu) (plane strain)
    /// Shear modulus E'/(2(1+nu')) = E/(2(1+nu)) in both conditions [Pa].
    double G() const { return E / (2.0 * (1.0 + nu)); }
    /// Poisson ratio of the plane-strain body equivalent to this one, nu'/(1+nu'): lets a
    /// formula derived in plane strain (O'Donnell, Weber) be evaluated in either condition.
    double nu_plane_strain() const { return nu / (1.0 + nu); }
  };

  /// (E', nu') of a material; throws InputError for E <= 0 or nu outside (-1, 0.5).
  PlaneElastic plane_elastic(const Material &m, PlaneCondition c);

  /// Contact modulus E* with 1/E* = 1/E1' + 1/E2' [Pa] (VALIDATION.md, Hertz line contact;
  /// plane strain: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2).
  double contact_modulus(const PlaneElastic &b1, const PlaneElastic &b2);

  /// Hertz line contact of two cylinders (Johnson 1985, sec. 4.3).
  struct HertzLineContact
  {
    double reduced_radius; ///< R = R1 R2/(R1 + R2) [m]
    double half_width;     ///< a = sqrt(4 w R/(pi E*)) [m]
    double peak_pressure;  ///< p0 = 2 w/(pi a) = sqrt(w E*/(pi R)) [Pa]
    double max_shear;      ///< tau_max = 0.300 p0 [Pa]
    double max_shear_depth;///< z = 0.786 a [m]
    /// Pressure p(s) = p0 sqrt(1 - s^2/a^2) at distance s from the centre [Pa].
    double pressure(double s) const;
  };

  /// @param w  load per unit face width [N/m]; @param R1, R2 radii of curvature [m]
  /// (> 0 convex; a concave R2 < 0 with |R2| > R1 is allowed for internal contact).
  HertzLineContact hertz_line_contact(double w, double R1, double R2, const PlaneElastic &b1,
                                      const PlaneElastic &b2);

  /// Weber (1949) Hertz approach of one body, from the contact to a point at depth h
  /// along the load line (h = distance from the contact to the tooth centreline):
  ///   delta_i = (2 F/(pi b E_i')) [ln(2 h_i/a) - nu_i'/2]      [m]
  /// With equal materials the pair sum is the thesis formula (Gkimisis 2019 eq. 3.8; the NTUA tooth-mass thesis):
  ///   C_H = E b delta/F = (2(1-nu^2)/pi)[ln(4 h1 h2/a^2) - nu/(1-nu)]   (plane strain).
  /// @param F normal load [N]; b face width [m]; a Hertz half-width [m].
  double weber_hertz_approach(double F, double b, double a, double h, const PlaneElastic &body);

  /// Load-independent Hertz stiffness of the potential-energy method (Yang & Lin 1987;
  /// Tian 2004): k_h = pi E b/(4(1-nu^2)) for two equal plane-strain bodies, i.e.
  /// k_h = pi b E*/2 with the contact modulus E* of the selected condition [N/m].
  double hertz_stiffness_pe(const PlaneElastic &b1, const PlaneElastic &b2, double b);
} // namespace gearfem::analytical
