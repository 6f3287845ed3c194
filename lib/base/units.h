#pragma once
// Unit conversions at the I/O boundary. Everything inside gearfem is SI (m, N, Pa, rad).
#include <cmath>

namespace gearfem::units
{
  inline constexpr double pi = 3.14159265358979323846;
  inline constexpr double mm = 1e-3;             ///< metres per millimetre
  inline constexpr double um = 1e-6;             ///< metres per micrometre
  inline constexpr double MPa = 1e6;             ///< pascals per megapascal
  inline constexpr double GPa = 1e9;             ///< pascals per gigapascal
  inline constexpr double deg = pi / 180.0;      ///< radians per degree
  inline constexpr double urad = 1e-6;           ///< radians per microradian
  inline constexpr double N_per_mm_um = 1e9;     ///< N/m per N/(mm um)
  inline constexpr double rpm = 2.0 * pi / 60.0; ///< rad/s per rev/min
} // namespace gearfem::units
