#pragma once
// Error types shared by every module. Pure C++ (no deal.II), so that the light layer
// (geometry, analytical, dynamics) reports user errors the same way as the rest.
//
// Exit status convention of the CLI (lib/commands):
//   InputError  -> 2 (bad parameter, bad file, design check failed)
//   SolverError -> 3 (non-convergence after all safeguards)
//   anything else -> 1 (internal error; a bug)
#include <sstream>
#include <stdexcept>
#include <string>

namespace gearfem
{
  /// A user error: names the parameter, its value and the allowed range.
  class InputError : public std::runtime_error
  {
  public:
    /// @param parameter  e.g. "Gear 1/Number of teeth"
    /// @param value      the offending value as the user wrote it (or computed)
    /// @param allowed    the allowed range or set, e.g. ">= 5" or "{1, 2}"
    /// @param detail     optional explanation
    InputError(const std::string &parameter,
               const std::string &value,
               const std::string &allowed,
               const std::string &detail = "")
      : std::runtime_error(format(parameter, value, allowed, detail))
      , parameter_(parameter)
    {}

    /// A free-form input error (missing file, corrupt table) that still names its subject.
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}

    const std::string &parameter() const { return parameter_; }

  private:
    static std::string format(const std::string &parameter,
                              const std::string &value,
                              const std::string &allowed,
                              const std::string &detail)
    {
      std::ostringstream s;
      s << "invalid value for '" << parameter << "': " << value << " (allowed: " << allowed
        << ")";
      if (!detail.empty())
        s << ". " << detail;
      return s.str();
    }
    std::string parameter_;
  };

  /// A computation that failed after all safeguards (non-convergence, no contact found).
  class SolverError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /// Format a double for messages without noise.
  inline std::string to_string_g(double v)
  {
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
  }

  /// `v` with `digits` significant digits, as std::ostream writes it by default.
  inline std::string to_string_g(double v, int digits)
  {
    std::ostringstream s;
    s.precision(digits);
    s << v;
    return s.str();
  }

  /// A length [m] as millimetre text for a message: "12.5 mm".
  inline std::string mm_text(double metres) { return to_string_g(metres * 1e3) + " mm"; }

  /// Throw InputError unless lo <= v <= hi (inclusive); units are part of the text.
  inline void require_range(const std::string &parameter, double v, double lo, double hi,
                            const std::string &unit = "")
  {
    if (!(v >= lo && v <= hi))
      throw InputError(parameter, to_string_g(v) + (unit.empty() ? "" : " " + unit),
                       "[" + to_string_g(lo) + ", " + to_string_g(hi) + "]" +
                         (unit.empty() ? "" : " " + unit));
  }

  /// Throw InputError unless v > lo (strict).
  inline void require_greater(const std::string &parameter, double v, double lo,
                              const std::string &unit = "")
  {
    if (!(v > lo))
      throw InputError(parameter, to_string_g(v) + (unit.empty() ? "" : " " + unit),
                       "> " + to_string_g(lo) + (unit.empty() ? "" : " " + unit));
  }
} // namespace gearfem
