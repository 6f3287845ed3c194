// The contact options: method and gap-rule names, checks of the `Contact` entries.
#include "contact/options.h"

#include "base/errors.h"

#include <string>

namespace gearfem::contact
{
  Method method_from_string(const std::string &s)
  {
    if (s == "penalty")
      return Method::penalty;
    if (s == "lagrange")
      return Method::lagrange;
    throw InputError("Contact/Method", s, "penalty | lagrange");
  }

  const char *to_string(Method m) { return m == Method::penalty ? "penalty" : "lagrange"; }

  GapRule gap_rule_from_string(const std::string &s)
  {
    if (s == "node")
      return GapRule::node;
    if (s == "integrated")
      return GapRule::integrated;
    throw InputError("Contact/Gap", s, "node | integrated");
  }

  const char *to_string(GapRule g) { return g == GapRule::node ? "node" : "integrated"; }

  void ContactOptions::validate() const
  {
    require_greater("Contact/Penalty factor", penalty_factor, 0.0, "-");
    require_greater("Contact/Search distance", search_distance, 0.0, "m");
    if (!(tolerance > 0 && tolerance < 1e-2))
      throw InputError("Contact/Tolerance", to_string_g(tolerance), "(0, 1e-2)");
    if (max_active_set_iterations < 1)
      throw InputError("Contact/Max active-set iterations", std::to_string(max_active_set_iterations), ">= 1");
    if (max_geometry_iterations < 1)
      throw InputError("Contact/Max geometry iterations", std::to_string(max_geometry_iterations), ">= 1");
    if (max_load_cuts < 0)
      throw InputError("Contact/Max load cuts", std::to_string(max_load_cuts), ">= 0");
    if (!(friction >= 0.0 && friction <= 1.0))
      throw InputError("Contact/Friction coefficient", to_string_g(friction), "[0, 1]");
    if (!(friction_tolerance > 0.0 && friction_tolerance <= 0.1))
      throw InputError("Contact/Friction sliding tolerance", to_string_g(friction_tolerance), "(0, 0.1]");
    if (slave != 1 && slave != 2)
      throw InputError("Contact/Slave body", std::to_string(slave), "1 | 2");
  }
} // namespace gearfem::contact
