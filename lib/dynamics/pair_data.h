#pragma once
// Simple pair quantities the dynamic models need (base radii, contact ratio, start of
// active contact, backlash, tooth-thickness angle), in closed form for an unshifted
// standard involute spur pair at a given centre distance. SI units.
// This stands in until geometry::GearPair is available; the formulas are the textbook
// ones (e.g. Litvin & Fuentes 2004, ch. 10) and Gkimisis 2019 eq. 2.52 for the backlash.
namespace gearfem::dynamics
{
  struct PairData
  {
    int z1 = 0, z2 = 0;
    double r_b1 = 0, r_b2 = 0;       ///< base radii [m]
    double r_a1 = 0, r_a2 = 0;       ///< tip radii [m]
    double center_distance = 0;      ///< operating a [m]
    double working_pressure_angle = 0; ///< alpha_w [rad]
    double contact_ratio = 0;        ///< transverse contact ratio [-]
    double theta_A = 0;              ///< pinion roll angle of the start of contact A (0 at C) [rad]
    double backlash = 0;             ///< normal backlash along the line of action [m]
    double thickness_angle1 = 0;     ///< pinion angular tooth thickness at the working pitch circle [rad]
  };

  /// @param module m [m]; @param alpha rack pressure angle [rad]; @param addendum h_a/m [-];
  /// @param thickness1, thickness2 C_f: tooth thickness at the reference circle / (pi m) [-]
  ///        (0.5 = no backlash); @param delta_a centre-distance change from m (z1+z2)/2 [m].
  /// Backlash (Gkimisis 2019 eq. 2.52): b = cos(alpha) pi m (1 - C_f1 - C_f2)
  ///        + 2 (inv alpha_w - inv alpha)(r_b1 + r_b2).
  /// Throws InputError for z < 5, contact ratio < 1 or >= 2, impossible centre distance.
  PairData standard_pair(int z1, int z2, double module, double alpha, double addendum,
                         double thickness1, double thickness2, double delta_a);
} // namespace gearfem::dynamics
