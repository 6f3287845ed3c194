#pragma once
// A `gearfem solve` input parsed from text, for the tests that build models from it.
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace gearfem::test
{
  inline solve::GearContactInput parse_solve_input(const std::string &text)
  {
    dealii::ParameterHandler prm;
    solve::declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    return solve::parse_gear_contact_input(prm);
  }
} // namespace gearfem::test
