#pragma once
// The designs of a batch study (pure C++, no deal.II): a design is one set of values for
// parameter paths of the case file ("Gear 1/Tip relief amount", "Material/Gear 2/Young's
// modulus"), each value as text, exactly as it would be written after `set ... =`.
//
// Three sources, one result (DesignSet):
//   - a design table: a CSV file whose header names the paths, one design per row;
//   - a full factorial over value lists per path;
//   - a Latin hypercube over ranges per path, with a seed (McKay, Beckman & Conover 1979):
//     each range is cut into n equal strata and every stratum holds exactly one sample.
// Every error names what is wrong and where (column, row), as an InputError (exit 2).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::batch
{
  struct Design
  {
    std::string id;                  ///< folder name of the job: [A-Za-z0-9._-]+
    std::vector<std::string> values; ///< one per DesignSet::paths
    std::string origin;              ///< where it came from, for messages ("row 3 of d.csv")
  };

  struct DesignSet
  {
    std::vector<std::string> paths; ///< parameter paths "Section/.../Entry"
    std::vector<Design> designs;
  };

  /// The name of the optional design-id column of a design table.
  inline constexpr const char *id_column = "id";

  /// Parse the CSV text of a design table (`name` is the file name used in messages).
  /// Header: parameter paths, and optionally a column `id` (else the ids are
  /// design_001, design_002, ... by row). Cells are trimmed; a cell may be quoted with
  /// "..." (for values containing commas). Blank lines and lines starting with '#' are
  /// skipped. Refused, naming the column and the row (1-based line of the file): an empty
  /// table, an empty or duplicate column name, a row with another number of cells than the
  /// header, an empty cell, an id that is not a folder name, a duplicate id.
  DesignSet parse_design_table(const std::string &text, const std::string &name);

  /// Read and parse a design table file (InputError if it cannot be read).
  DesignSet read_design_table(const std::string &file);

  /// "path: v1, v2, ...; path: ..." -> (path, items). `entry` names the source in messages.
  /// `expect_items` > 0 requires exactly that many items per path.
  std::vector<std::pair<std::string, std::vector<std::string>>>
  parse_path_lists(const std::string &entry, const std::string &text, std::size_t expect_items = 0);

  /// Every combination of the value lists, the first path varying slowest (ids ff_001, ...).
  DesignSet full_factorial(const std::vector<std::pair<std::string, std::vector<std::string>>> &lists);

  /// `n` Latin-hypercube samples of the ranges [lo, hi] (one per path), reproducible from
  /// `seed` on every platform (std::mt19937_64 with our own uniform and shuffle, not the
  /// implementation-defined std distributions). Ids lhs_001, ...; values with 12 digits.
  DesignSet latin_hypercube(const std::vector<std::pair<std::string, std::pair<double, double>>> &ranges,
                            std::size_t n, std::uint64_t seed);

  /// Split a parameter path into its subsections and its entry ("Material/Gear 2/Young's
  /// modulus" -> {"Material", "Gear 2"}, "Young's modulus"). InputError for an empty part.
  std::pair<std::vector<std::string>, std::string> split_path(const std::string &path);
} // namespace gearfem::batch
