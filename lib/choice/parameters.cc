#include "choice/parameters.h"

#include <deal.II/base/parameter_handler.h>
#include <cctype>
#include <cstdio>

namespace gearfem::choice
{
  FixedSettings fixed_settings(const dealii::ParameterHandler &prm)
  {
    const std::set<std::string> unset = prm.get_entries_wrongly_not_set();
    // The names are the mangled paths ("Mesh.h_5fcontact", "Finite_20elements.Degree"): every
    // character but a letter or digit becomes '_' and its two hexadecimal digits.
    auto mangle = [](const std::string &s) {
      std::string m;
      for (const char c : s)
        if (std::isalnum(static_cast<unsigned char>(c)))
          m += c;
        else
          {
            char hex[4];
            std::snprintf(hex, sizeof hex, "_%02x", static_cast<unsigned char>(c));
            m += hex;
          }
      return m;
    };
    auto set = [&](const std::string &section_text, const std::string &entry_text) {
      return unset.count(mangle(section_text) + "." + mangle(entry_text)) == 0;
    };
    FixedSettings f;
    f.h_contact = set("Mesh", "h_contact");
    f.h_fillet  = set("Mesh", "h_fillet");
    f.h_corner  = set("Mesh", "h_corner");
    f.model     = set("Mesh", "Model");
    f.degree    = set("Finite elements", "Degree");
    return f;
  }
} // namespace gearfem::choice
