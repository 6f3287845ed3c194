#pragma once
// The solve-results contract: what `gearfem solve` (or any run of the loading sweep)
// writes and what the calibration and the dynamics read. One owner for the column names,
// one writer and one reader (layout: docs/output-format.md).
//
//   <dir>/sweep.csv, pairs.csv, pressure.csv, line_of_action.csv   one row per record
//   <dir>/results.h5   root attributes: format = "gearfem-solve-results",
//                      format_version = "1", program, geometry_hash, method, input
//                      /sweep, /pairs, /pressure, /line_of_action: one 1-D float64
//                      dataset per column, named like the CSV header "name [unit]"
//                      ('/' written " per ")
//
// HDF5 through the C API (io/hdf5_util.h), like the mesh tables: a light module.
#include "base/table.h"

#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace gearfem::io
{
  inline constexpr const char *solve_results_format = "gearfem-solve-results";
  inline constexpr const char *solve_results_format_version = "1";

  /// Header labels of the sweep columns that other modules read by name.
  namespace sweep_column
  {
    inline constexpr const char *torque     = "torque [N m]";
    inline constexpr const char *roll_angle = "roll angle [deg]";
    inline constexpr const char *ste        = "STE [um]";
    inline constexpr const char *normal_force = "F_n [N]";
    inline constexpr const char *time       = "time [s]";
  } // namespace sweep_column

  struct SolveResults
  {
    Table sweep;          ///< one row per (torque, position)
    Table pairs;          ///< one row per loaded tooth pair and position
    Table pressure;       ///< one row per contact node of each pair and position
    Table line_of_action; ///< the points A..E of the path of contact
    /// Root attributes besides format and format_version: program, geometry_hash,
    /// method, input.
    std::map<std::string, std::string> attributes;
  };

  /// Empty tables with the contract's columns, in the order they are written.
  SolveResults make_solve_results();

  /// Write the four CSV files and results.h5 into `dir`, each atomically (temporary name,
  /// then rename). Every value is checked finite before anything is opened (InputError
  /// naming the file and column otherwise).
  void write_solve_results(const SolveResults &results, const std::filesystem::path &dir);

  /// Read results.h5. Throws InputError naming the file and the missing or bad item for a
  /// missing, foreign or corrupt file, a wrong format, and missing columns. Columns added
  /// to the contract after a file was written are left empty in the returned table only
  /// if `require_all` is false (then only torque, roll angle and STE are required).
  SolveResults read_solve_results(const std::filesystem::path &file, bool require_all = false);

  /// HDF5 reserves '/' in names: the dataset of CSV header "k [N/m]" is "k [N per m]".
  std::string dataset_name(const std::string &header);

  /// Column tables to an HDF5 file: one group per table, one float64 dataset per column
  /// (named dataset_name(header)), string attributes on the root. Atomic; values checked
  /// finite first. Empty tables are skipped.
  /// `text_columns`: (group, dataset name, values) written as 1-D string datasets (e.g.
  /// the design ids and status messages of a batch table).
  void write_table_file(const std::vector<std::pair<std::string, const Table *>> &tables,
                        const std::filesystem::path &file,
                        const std::map<std::string, std::string> &attributes,
                        const std::vector<std::tuple<std::string, std::string, std::vector<std::string>>>
                          &text_columns = {});
} // namespace gearfem::io
