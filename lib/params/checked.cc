#include "params/checked.h"

#include <cctype>
#include <cstdio>

#include "base/errors.h"
#include "base/number.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <memory>
#include <sstream>

namespace gearfem::params
{
  namespace
  {
    namespace Patterns = dealii::Patterns;
    using boost::property_tree::ptree;

    /// The whole tree of entries (value and pattern description of each), read back from
    /// the handler's own JSON output: ParameterHandler keeps its patterns private.
    ptree entry_tree(const dealii::ParameterHandler &prm)
    {
      std::stringstream s;
      prm.print_parameters(s, dealii::ParameterHandler::JSON);
      ptree tree;
      boost::property_tree::read_json(s, tree);
      return tree;
    }

    bool is_entry(const ptree &node)
    {
      return node.find("value") != node.not_found() &&
             node.find("pattern_description") != node.not_found();
    }

    template <typename F>
    void for_each_entry(const ptree &node, const std::string &path, const F &f)
    {
      for (const auto &child : node)
        {
          const std::string p = path.empty() ? child.first : path + "/" + child.first;
          if (is_entry(child.second))
            f(p, child.second);
          else
            for_each_entry(child.second, p, f);
        }
    }

    /// The full paths ("Gear 1/Face width") of the entries named `leaf` whose value is
    /// `value`: used to name an entry in a message (the handler's current subsection is
    /// private), at the cost of one JSON round trip on the error path only.
    std::string full_name(const dealii::ParameterHandler &prm, const std::string &leaf,
                          const std::string &value)
    {
      std::string names;
      try
        {
          for_each_entry(entry_tree(prm), "", [&](const std::string &p, const ptree &e) {
            const auto slash = p.rfind('/');
            if ((slash == std::string::npos ? p : p.substr(slash + 1)) == leaf &&
                e.get<std::string>("value") == value)
              names += (names.empty() ? "" : " or ") + p;
          });
        }
      catch (const std::exception &)
        {}
      return names.empty() ? leaf : names;
    }

    /// Check one value against one pattern; `what` is the text that names it in a message.
    void check_value(const std::string &entry, const std::string &value,
                     const Patterns::PatternBase &pattern, const std::string &whole)
    {
      const std::string allowed = pattern.description(Patterns::PatternBase::Text);
      if (dynamic_cast<const Patterns::Double *>(&pattern))
        {
          try
            {
              parse_double(entry, value);
            }
          catch (const InputError &)
            {
              throw InputError(entry, whole, std::string(finite_number_text) + "; " + allowed,
                               whole == value ? "" : "item '" + value + "' is not one");
            }
        }
      else if (dynamic_cast<const Patterns::Integer *>(&pattern))
        {
          try
            {
              parse_int(entry, value);
            }
          catch (const InputError &)
            {
              throw InputError(entry, whole, "a decimal integer that fits in an int; " + allowed,
                               whole == value ? "" : "item '" + value + "' is not one");
            }
        }
      if (!pattern.match(value))
        throw InputError(entry, whole, allowed,
                         whole == value ? "" : "item '" + value + "' does not match");
      if (const auto list = dynamic_cast<const Patterns::List *>(&pattern))
        {
          for (const auto &item : dealii::Utilities::split_string_list(value, list->get_separator()))
            check_value(entry, item, list->get_base_pattern(), whole);
        }
      else if (const auto map = dynamic_cast<const Patterns::Map *>(&pattern))
        {
          for (const auto &pair : dealii::Utilities::split_string_list(value, map->get_separator()))
            {
              const auto kv = dealii::Utilities::split_string_list(pair, map->get_key_value_separator());
              if (kv.size() == 2)
                {
                  check_value(entry, kv[0], map->get_key_pattern(), whole);
                  check_value(entry, kv[1], map->get_value_pattern(), whole);
                }
            }
        }
      else if (const auto tuple = dynamic_cast<const Patterns::Tuple *>(&pattern))
        {
          const auto items = dealii::Utilities::split_string_list(value, tuple->get_separator());
          for (unsigned int i = 0; i < items.size(); ++i)
            check_value(entry, items[i], tuple->get_pattern(i), whole);
        }
    }
  } // namespace

  double get_double(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    const std::string value = prm.get(entry);
    try
      {
        return parse_double(entry, value);
      }
    catch (const InputError &)
      {
        return parse_double(full_name(prm, entry, value), value);
      }
  }

  int get_integer(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    const std::string value = prm.get(entry);
    try
      {
        return parse_int(entry, value);
      }
    catch (const InputError &)
      {
        return parse_int(full_name(prm, entry, value), value);
      }
  }

  bool get_bool(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    const std::string value = dealii::Utilities::trim(prm.get(entry));
    if (value == "true" || value == "yes")
      return true;
    if (value == "false" || value == "no")
      return false;
    throw InputError(full_name(prm, entry, prm.get(entry)), value, "true|false|yes|no");
  }

  std::vector<double> get_doubles(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    const std::string value = prm.get(entry);
    try
      {
        return parse_double_list(entry, value);
      }
    catch (const InputError &)
      {
        return parse_double_list(full_name(prm, entry, value), value);
      }
  }

  void check_entries(const dealii::ParameterHandler &prm)
  {
    for_each_entry(entry_tree(prm), "", [](const std::string &path, const ptree &e) {
      const std::string value = e.get<std::string>("value");
      std::unique_ptr<Patterns::PatternBase> pattern;
      try
        {
          pattern = Patterns::pattern_factory(e.get<std::string>("pattern_description"));
        }
      catch (...)
        {
          return; // a pattern deal.II cannot rebuild from its description: checked at read
        }
      if (pattern)
        check_value(path, value, *pattern, value);
    });
  }

  std::string exception_text(const dealii::ExceptionBase &e)
  {
    std::ostringstream s;
    e.print_info(s);
    std::string t = s.str();
    while (!t.empty() && (t.back() == '\n' || t.back() == ' '))
      t.pop_back();
    while (!t.empty() && (t.front() == '\n' || t.front() == ' '))
      t.erase(t.begin());
    return t;
  }

  std::vector<double> get_torques(const dealii::ParameterHandler &prm, const std::string &entry,
                                  const std::string &path, bool allow_empty)
  {
    const std::vector<double> t = parse_double_list(path, prm.get(entry));
    if (t.empty() && !allow_empty)
      throw InputError(path, "(empty)", "one or more torques > 0 N m");
    for (const double T : t)
      require_greater(path, T, 0.0, "N m");
    return t;
  }

  void declare_torques(dealii::ParameterHandler &prm, const std::string &entry, const std::string &default_value,
                       const std::string &what)
  {
    prm.declare_entry(entry, default_value, dealii::Patterns::Anything(),
                      what + " Comma-separated. Units: N m. Allowed: > 0 each.");
  }

  std::string mangled_name(const std::string &name)
  {
    std::string out;
    for (const char c : name)
      if (std::isalnum(static_cast<unsigned char>(c)))
        out += c;
      else
        {
          char buf[8];
          std::snprintf(buf, sizeof buf, "_%02x", static_cast<unsigned char>(c));
          out += buf;
        }
    return out;
  }
} // namespace gearfem::params
