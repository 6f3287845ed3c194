#include "model_choice/target.h"

#include "base/errors.h"
#include "base/number.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

namespace gearfem::model_choice
{
  namespace
  {
    std::string trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t");
      if (b == std::string::npos)
        return "";
      return s.substr(b, s.find_last_not_of(" \t") - b + 1);
    }

    std::string lower(std::string s)
    {
      std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
      return s;
    }

    const char *allowed = "none, a preset (dynamics tables | rating check | micro-geometry design), or a "
                          "comma-separated list of '<quantity> <percent>' with quantity mean STE | p-p STE | "
                          "root stress | p_max and percent in 0.01 to 50";

    AccuracyTarget preset(const std::string &name)
    {
      AccuracyTarget t;
      t.preset = name;
      if (name == "dynamics tables")
        t.tolerance = {0.01, 0.02, 0, 0};
      else if (name == "rating check")
        t.tolerance = {0, 0, 0.03, 0.05};
      else if (name == "micro-geometry design")
        t.tolerance = {0.02, 0.01, 0, 0.10};
      else
        t.preset.clear();
      return t;
    }
  } // namespace

  bool AccuracyTarget::active() const
  {
    return std::any_of(tolerance.begin(), tolerance.end(), [](double v) { return v > 0; });
  }

  const std::array<const char *, n_quantities> &AccuracyTarget::names()
  {
    static const std::array<const char *, n_quantities> n = {"mean STE", "p-p STE", "root stress", "p_max"};
    return n;
  }

  const std::array<const char *, n_quantities> &AccuracyTarget::keys()
  {
    static const std::array<const char *, n_quantities> k = {"mean_ste", "pp_ste", "root_stress", "p_max"};
    return k;
  }

  AccuracyTarget parse_target(const std::string &text, const std::string &entry)
  {
    const std::string t = lower(trim(text));
    if (t.empty() || t == "none")
      return {};
    if (const AccuracyTarget p = preset(t); p.active())
      return p;
    AccuracyTarget out;
    std::stringstream items(t);
    std::string item;
    const auto &names = AccuracyTarget::names();
    while (std::getline(items, item, ','))
      {
        item = trim(item);
        if (!item.empty() && item.back() == '%')
          item = trim(item.substr(0, item.size() - 1));
        const auto space = item.find_last_of(" \t");
        if (space == std::string::npos)
          throw InputError(entry, text, allowed);
        const std::string name = trim(item.substr(0, space)), value = item.substr(space + 1);
        int q = -1;
        for (int i = 0; i < n_quantities; ++i)
          if (name == lower(names[i]))
            q = i;
        if (q < 0)
          throw InputError(entry, text, allowed);
        if (out.tolerance[q] > 0)
          throw InputError(entry, text, std::string(names[q]) + " named once");
        out.tolerance[q] = parse_double(entry + " (" + names[q] + ")", value, 0.01, 50.0) / 100.0;
      }
    if (!out.active())
      throw InputError(entry, text, allowed);
    return out;
  }

  std::string to_string(const AccuracyTarget &t)
  {
    if (!t.active())
      return "none";
    std::ostringstream o;
    if (!t.preset.empty())
      o << t.preset << ": ";
    bool first = true;
    for (int i = 0; i < n_quantities; ++i)
      if (t.tolerance[i] > 0)
        {
          o << (first ? "" : ", ") << AccuracyTarget::names()[i] << " " << t.tolerance[i] * 100 << " %";
          first = false;
        }
    return o.str();
  }
} // namespace gearfem::model_choice
