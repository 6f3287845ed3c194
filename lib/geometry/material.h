#pragma once
// Linear-elastic material of one gear body (SI units). Pure C++ (light layer).
namespace gearfem::geometry
{
  /// Isotropic linear elasticity plus density; `plane_strain` selects the 2-D model
  /// (false: plane stress, the default; see ../shared/reference/VALIDATION.md, Hertz).
  struct Material
  {
    double youngs_modulus = 207e9; ///< E [Pa]
    double poisson_ratio  = 0.3;   ///< nu [-]
    double density        = 7850;  ///< rho [kg/m^3]

    /// Plane-stress or plane-strain effective modulus E' [Pa]: E, or E/(1 - nu^2).
    double effective_modulus(bool plane_strain) const
    {
      return plane_strain ? youngs_modulus / (1 - poisson_ratio * poisson_ratio) : youngs_modulus;
    }
  };

  /// The materials of a pair and the plane model.
  struct PairMaterial
  {
    Material gear1, gear2;
    bool     plane_strain = false; ///< "Plane model = plane strain"
  };
} // namespace gearfem::geometry
