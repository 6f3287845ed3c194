#pragma once
// The entries of one shaft (Segments, Bearings, Young's modulus, Poisson's ratio), shared by
// the `System` section of `gearfem helical` and the `Train` section of `gearfem system`.
// Internal to the module.
#include "shafts/shaft.h"

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::system_deflection
{
  /// Declares a shaft's entries in the current subsection.
  void declare_shaft_entries(dealii::ParameterHandler &prm);
  /// Shaft i from subsection `section` of the current one (`parent` names it in errors); its
  /// bearings, named "<bearing_prefix> bearing <n>", are appended to `bearings`.
  shafts::Shaft parse_shaft(dealii::ParameterHandler &prm, const std::string &parent, const std::string &section, int i,
                            const std::string &bearing_prefix, std::vector<shafts::Bearing> &bearings);
} // namespace gearfem::system_deflection
