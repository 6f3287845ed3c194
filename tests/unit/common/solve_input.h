#pragma once
// A `gearfem solve` input parsed from text, for the tests that build models from it.
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace gearfem::test
{
  /// A coarse 3-tooth sector mesh section: a model that builds and sweeps in a fraction of a
  /// second, for tests of the sweep's machinery rather than of its accuracy.
  inline const std::string coarse_sector_mesh = R"(
subsection Mesh
  set Model = sector
  set Sector teeth = 3
  set h_contact = 0.3
  set h_fillet = 0.5
  set h_body = 4
end
)";

  inline solve::GearContactInput parse_solve_input(const std::string &text)
  {
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    return solve::parse_gear_contact_input(prm);
  }
} // namespace gearfem::test
