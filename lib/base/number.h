#pragma once
// The one checked text -> number conversion of gearfem (pure C++). Every numeric value that
// comes from a user (a parameter entry, a list element, a CSV cell) goes through these
// functions, so that anything that merely looks numeric becomes a named InputError (exit
// status 2) instead of a library exception (exit status 1) or a silent NaN.
//
// Accepted: one decimal number, optionally surrounded by blanks, whose value is a finite
// double that is either 0 or normal (|x| >= 2.2250738585072014e-308). Refused: empty text,
// trailing characters ("1.5x", "${X}"), hexadecimal floats ("0x1p3"), inf, nan, overflow
// (1e400) and subnormal values (1e-320: strtod reports ERANGE for them, and no physical
// input of gearfem is that small).
#include <string>
#include <vector>

namespace gearfem
{
  /// k modulo n in [0, n) for any sign of k (n > 0): a tooth or slice index.
  inline int wrap_index(long k, long n) { return int(((k % n) + n) % n); }

  /// The allowed set that the messages of parse_double state.
  extern const char *const finite_number_text;

  /// Convert `text` (the value of `entry`) to a double. Throws InputError naming the entry,
  /// the value and the allowed range, with the reason (not a number, overflow, subnormal).
  double parse_double(const std::string &entry, const std::string &text);

  /// As parse_double, and require lo <= x <= hi (closed interval); the message states it.
  double parse_double(const std::string &entry, const std::string &text, double lo, double hi);

  /// Convert `text` to an int: optional sign and decimal digits only, within
  /// [std::numeric_limits<int>::min(), max()] and within [lo, hi] if given.
  int parse_int(const std::string &entry, const std::string &text);
  int parse_int(const std::string &entry, const std::string &text, long long lo, long long hi);

  /// A `separator`-separated list of numbers; empty items (blank text, "1,,2") are skipped.
  /// The message names the offending item and the whole list.
  std::vector<double> parse_double_list(const std::string &entry, const std::string &text,
                                        char separator = ',');
  std::vector<int> parse_int_list(const std::string &entry, const std::string &text,
                                  char separator = ',');

  /// Split at `separator` and trim blanks of each item (empty items kept).
  std::vector<std::string> split_trimmed(const std::string &text, char separator);

  /// True when x is a value that parse_double could have returned (finite, 0 or normal).
  bool is_representable(double x);

  /// The rule of every CSV and HDF5 writer: no NaN or inf reaches an output file. Throws
  /// std::runtime_error ("non-finite value nan in <what> of <file>", exit status 1: a result
  /// that is not finite is a bug of the computation, not bad input) unless x is finite. The
  /// writers check all values before the (atomic) file is committed, so nothing partial is
  /// left.
  void require_finite_output(double x, const std::string &file, const std::string &what);
} // namespace gearfem
