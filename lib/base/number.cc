#include "base/number.h"

#include "base/errors.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace gearfem
{
  const char *const finite_number_text =
    "a finite decimal number, 0 or |x| in [2.22507e-308, 1.79769e+308]";

  namespace
  {
    std::string trim(const std::string &s)
    {
      std::size_t b = 0, e = s.size();
      while (b < e && std::isspace(static_cast<unsigned char>(s[b])))
        ++b;
      while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1])))
        --e;
      return s.substr(b, e - b);
    }

    /// Only the characters of a decimal floating-point literal: refuses hexadecimal floats,
    /// inf, nan and anything strtod would accept as a prefix of a longer text.
    bool decimal_characters(const std::string &t)
    {
      for (char c : t)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.' ||
              c == 'e' || c == 'E'))
          return false;
      return true;
    }

    /// The reason why `t` is not a representable double, or "" if it is (value in x).
    std::string convert(const std::string &t, double &x)
    {
      if (t.empty())
        return "empty value";
      if (!decimal_characters(t))
        return "not a decimal number";
      errno         = 0;
      char *end     = nullptr;
      x             = std::strtod(t.c_str(), &end);
      const int err = errno;
      if (end == t.c_str() || *end != '\0')
        return "not a decimal number";
      if (!std::isfinite(x) || (err == ERANGE && std::abs(x) > 1.0))
        return "overflows a double";
      if (x != 0 && std::abs(x) < std::numeric_limits<double>::min())
        return "subnormal: below the smallest normal double 2.22507e-308";
      if (err == ERANGE)
        return "underflows a double";
      return "";
    }

    std::string range_text(double lo, double hi)
    {
      return std::string(finite_number_text) + ", within [" + to_string_g(lo) + ", " +
             to_string_g(hi) + "]";
    }
  } // namespace

  bool is_representable(double x)
  {
    return std::isfinite(x) && (x == 0 || std::abs(x) >= std::numeric_limits<double>::min());
  }

  void require_finite_output(double x, const std::string &file, const std::string &what)
  {
    if (!std::isfinite(x))
      throw std::runtime_error("non-finite value " + to_string_g(x) + " in " + what + " of " + file +
                               ": not written (no NaN or inf reaches an output file)");
  }

  double parse_double(const std::string &entry, const std::string &text)
  {
    double x = 0;
    const std::string why = convert(trim(text), x);
    if (!why.empty())
      throw InputError(entry, text, finite_number_text, why);
    return x;
  }

  double parse_double(const std::string &entry, const std::string &text, double lo, double hi)
  {
    double x = 0;
    const std::string why = convert(trim(text), x);
    if (!why.empty())
      throw InputError(entry, text, range_text(lo, hi), why);
    if (!(x >= lo && x <= hi))
      throw InputError(entry, text, range_text(lo, hi), "out of range");
    return x;
  }

  int parse_int(const std::string &entry, const std::string &text)
  {
    return parse_int(entry, text, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
  }

  int parse_int(const std::string &entry, const std::string &text, long long lo, long long hi)
  {
    const std::string t = trim(text);
    const std::string allowed =
      "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    std::size_t i = (!t.empty() && (t[0] == '+' || t[0] == '-')) ? 1 : 0;
    bool digits   = i < t.size();
    for (std::size_t k = i; k < t.size(); ++k)
      digits = digits && std::isdigit(static_cast<unsigned char>(t[k]));
    if (!digits)
      throw InputError(entry, text, allowed, t.empty() ? "empty value" : "not an integer");
    errno             = 0;
    const long long v = std::strtoll(t.c_str(), nullptr, 10);
    if (errno == ERANGE || v < lo || v > hi)
      throw InputError(entry, text, allowed, "out of range");
    return static_cast<int>(v);
  }

  std::vector<std::string> split_trimmed(const std::string &text, char separator)
  {
    std::vector<std::string> items;
    std::size_t start = 0;
    while (true)
      {
        const std::size_t p = text.find(separator, start);
        items.push_back(trim(text.substr(start, p == std::string::npos ? std::string::npos : p - start)));
        if (p == std::string::npos)
          break;
        start = p + 1;
      }
    return items;
  }

  std::vector<double> parse_double_list(const std::string &entry, const std::string &text,
                                        char separator)
  {
    std::vector<double> v;
    for (const auto &item : split_trimmed(text, separator))
      if (!item.empty())
        {
          double x = 0;
          const std::string why = convert(item, x);
          if (!why.empty())
            throw InputError(entry, text,
                             std::string("a '") + separator + "'-separated list of " +
                               finite_number_text,
                             "item '" + item + "': " + why);
          v.push_back(x);
        }
    return v;
  }

  std::vector<int> parse_int_list(const std::string &entry, const std::string &text, char separator)
  {
    std::vector<int> v;
    for (const auto &item : split_trimmed(text, separator))
      if (!item.empty())
        {
          try
            {
              v.push_back(parse_int(entry, item));
            }
          catch (const InputError &)
            {
              throw InputError(entry, text, std::string("a '") + separator + "'-separated list of integers",
                               "item '" + item + "' is not an integer in range");
            }
        }
    return v;
  }
} // namespace gearfem
