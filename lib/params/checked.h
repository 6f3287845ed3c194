#pragma once
// Checked reads of ParameterHandler values: every numeric entry of gearfem is read through
// these functions, which convert with the one strict conversion of base/number.h and throw
// gearfem::InputError (exit status 2) naming the entry, the value and the allowed range.
//
// Why deal.II 9.4 alone is not enough (found with tests/fuzz):
//  1. ParameterHandler::parse_input()/set() do not check a value against its pattern when
//     the value contains a '{': such values are reserved for MultipleParameterLoop variants
//     ("{ 1 | 2 }", "{{ ... }}"), which are expanded later. So "${X}" (or "{", "{1|2}") is
//     stored unchecked in a Double, Integer, Bool, Selection or List entry; get_double() then
//     fails with "Can't convert the parameter value <${X}> ..." (ExcMessage, exit 1), and
//     get() silently returns the text (a Selection read with get() falls to a default).
//     Patterns::Double().match("${X}") itself is false.
//  2. Patterns::Double::match() reads with an istringstream, which accepts a subnormal value
//     such as 1e-320, but get_double() converts with Utilities::string_to_double(), i.e.
//     strtod(), which sets ERANGE for it, and that is refused. A List of Double has the same
//     gap for its items.
// check_entries() closes (1) for every pattern type by matching every entry of a parsed
// handler again, item by item for List/Map/Tuple, with the strict conversion for Double and
// Integer items; get_double()/get_integer() close (1) and (2) at each read.
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
  class ExceptionBase;
}

namespace gearfem::params
{
  /// prm.get(entry) converted by base/number.h parse_double (finite, 0 or normal).
  double get_double(const dealii::ParameterHandler &prm, const std::string &entry);
  /// prm.get(entry) converted by base/number.h parse_int (decimal digits, fits in an int).
  int get_integer(const dealii::ParameterHandler &prm, const std::string &entry);
  /// prm.get(entry): true/false/yes/no, as Patterns::Bool.
  bool get_bool(const dealii::ParameterHandler &prm, const std::string &entry);
  /// A comma-separated list of doubles (empty items skipped), each checked as get_double.
  std::vector<double> get_doubles(const dealii::ParameterHandler &prm, const std::string &entry);

  /// The one form of a torque list: a comma-separated list of pinion torques [N m], each
  /// finite and > 0; `path` ("Solve/Torques") names the entry in errors. Empty is an error
  /// unless `allow_empty`. Declare such entries with declare_torques (Anything pattern: the
  /// check is here, with the allowed range in the message).
  std::vector<double> get_torques(const dealii::ParameterHandler &prm, const std::string &entry,
                                  const std::string &path, bool allow_empty = false);
  void declare_torques(dealii::ParameterHandler &prm, const std::string &entry, const std::string &default_value,
                       const std::string &what);

  /// Check every entry of `prm` (all subsections) against its declared pattern, strictly:
  /// Double and Integer values (also as List, Map and Tuple items) must convert with
  /// base/number.h, every other pattern must match (this catches the values with '{' that
  /// parse_input() lets through). Throws InputError naming "Section/Entry", the value and
  /// the pattern. Call after parse_input().
  void check_entries(const dealii::ParameterHandler &prm);

  /// ParameterHandler's private name mangling: every character but [a-zA-Z0-9] as _XX (two
  /// hexadecimal digits), the form of the names in its tree and in get_entries_wrongly_not_set().
  std::string mangled_name(const std::string &name);

  /// The message of a deal.II exception (ParameterHandler's parse errors), trimmed.
  std::string exception_text(const dealii::ExceptionBase &e);
} // namespace gearfem::params
