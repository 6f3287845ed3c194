#include "model_choice/parameters.h"
#include "params/checked.h"

#include <deal.II/base/parameter_handler.h>

namespace gearfem::model_choice
{
  FixedSettings fixed_settings(const dealii::ParameterHandler &prm)
  {
    const std::set<std::string> unset = prm.get_entries_wrongly_not_set();
    // The names are the mangled paths ("Mesh.h_5fcontact", "Finite_20elements.Degree").
    auto set = [&](const std::string &section_text, const std::string &entry_text) {
      return unset.count(params::mangled_name(section_text) + "." + params::mangled_name(entry_text)) == 0;
    };
    FixedSettings f;
    f.h_contact = set("Mesh", "h_contact");
    f.h_fillet  = set("Mesh", "h_fillet");
    f.h_corner  = set("Mesh", "h_corner");
    f.model     = set("Mesh", "Model");
    f.tiled     = set("Mesh", "Tiled teeth");
    f.h_body    = set("Mesh", "h_body");
    f.h_tooth   = set("Mesh", "h_tooth");
    f.degree    = set("Finite elements", "Degree");
    return f;
  }
} // namespace gearfem::model_choice
