#pragma once
// Isotropic linear elasticity in the plane (plane stress or plane strain): constitutive law,
// principal stresses and von Mises. Header-only, SI units (Pa, m).
#include "base/errors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace gearfem::fem
{
  enum class PlaneModel
  {
    plane_stress, ///< thin body: sigma_zz = 0 (thickness = face width)
    plane_strain  ///< long body: eps_zz = 0
  };

  /// Material and section of one body.
  struct Elasticity
  {
    double youngs_modulus = 206e9; ///< E [Pa]
    double poisson_ratio  = 0.3;   ///< nu [-]
    double thickness      = 1.0;   ///< out-of-plane thickness b (face width) [m]
    PlaneModel model      = PlaneModel::plane_stress;

    /// Throws InputError naming `section` for E <= 0, nu outside (-1, 0.5), b <= 0.
    void validate(const std::string &section = "Material") const
    {
      require_greater(section + "/Young's modulus", youngs_modulus, 0.0, "Pa");
      if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
        throw InputError(section + "/Poisson's ratio", to_string_g(poisson_ratio), "(-1, 0.5)");
      require_greater(section + "/Face width", thickness, 0.0, "m");
    }
    /// Shear modulus mu = E / (2 (1 + nu)) [Pa].
    double mu() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
    /// In-plane Lame constant: E nu / (1 - nu^2) in plane stress, E nu / ((1 + nu)(1 - 2 nu))
    /// in plane strain [Pa] (Timoshenko & Goodier 1970, sec. 16-17).
    double lambda() const
    {
      const double E = youngs_modulus, nu = poisson_ratio;
      return model == PlaneModel::plane_stress ? E * nu / (1.0 - nu * nu) :
                                                 E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    }
    /// Stress from strain (exx, eyy, gamma_xy/2 = exy): returns {sxx, syy, sxy} [Pa].
    std::array<double, 3> stress(double exx, double eyy, double exy) const
    {
      const double l = lambda(), m = mu(), tr = exx + eyy;
      return {l * tr + 2 * m * exx, l * tr + 2 * m * eyy, 2 * m * exy};
    }
    /// Out-of-plane stress: 0 in plane stress, nu (sxx + syy) in plane strain [Pa].
    double stress_zz(double sxx, double syy) const
    {
      return model == PlaneModel::plane_stress ? 0.0 : poisson_ratio * (sxx + syy);
    }
  };

  /// In-plane principal stresses {sigma_1 >= sigma_2} [Pa] (Mohr's circle).
  inline std::array<double, 2> principal_stresses(double sxx, double syy, double sxy)
  {
    const double c = 0.5 * (sxx + syy), r = std::hypot(0.5 * (sxx - syy), sxy);
    return {c + r, c - r};
  }

  /// von Mises equivalent stress with the out-of-plane stress szz [Pa].
  inline double von_mises(double sxx, double syy, double sxy, double szz = 0.0)
  {
    return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) +
                            (szz - sxx) * (szz - sxx)) +
                     3.0 * sxy * sxy);
  }
} // namespace gearfem::fem
