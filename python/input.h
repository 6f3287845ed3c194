#pragma once
// The Python module's inputs (python/module.cc): the text of a .prm file with later `set`s
// appended, parsed and checked as `gearfem <command>` parses a file.
#include <pybind11/pybind11.h>

#include <map>
#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::python
{
  /// A solve input. Immutable: with() returns a changed copy.
  struct Input
  {
    std::string text;               ///< the .prm text
    std::string name = "input.prm"; ///< its file name (the results' `input` attribute)
    std::string dir;                ///< its folder (relative file names in it resolve there)
    /// The input with each entry ("Section/Sub/Entry" -> value) set after the others.
    Input with(const std::map<std::string, std::string> &entries) const;
    /// The value of entry "Section/Entry" as the input gives it (its default where unset).
    std::string get(const std::string &path) const;
  };

  /// A Python value as a .prm value: str as it is, bool as true/false, numbers with 17
  /// digits, a list or tuple comma-separated.
  std::string prm_value(const pybind11::handle &v);
  /// The `set` of one entry, "Section/Sub/Entry" = value, as .prm text.
  std::string entry_text(const std::string &path, const std::string &value);
  /// The text of nested sections {"Rack": {"Module": 3}, "Material": {"Gear 1": {...}}}.
  std::string sections_text(const pybind11::dict &sections, int depth = 0);

  /// Checks `in` against the parameters of every command (a misspelt entry is an InputError,
  /// as in the CLI) and reads the entries `prm` declares.
  void parse(const Input &in, dealii::ParameterHandler &prm);
} // namespace gearfem::python
