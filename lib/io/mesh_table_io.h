#pragma once
// HDF5 mesh-table files: the versioned contract between the FE calibration (which writes
// T(theta, delta), k(theta, F) and STE(theta, T) tables) and the dynamics module (which reads
// them into a MeshTable for TableLaw). Layout (see docs/mesh-tables.md):
//
//   /                         attributes: format = "gearfem-mesh-table" (string)
//                                         format_version = 1 or 2 (integer)
//                                         geometry_hash, source, created (strings)
//   /table                    group, attributes: period [rad], base_radius [m],
//                                                valid_min, valid_max (second axis, its unit),
//                                                backlash [m] (version 2, two-sided torque tables)
//   /table/theta              float64 [n_theta], attribute unit = "rad"
//   /table/delta              float64 [n_second], unit = "m"   (torque tables; version 2:
//                                                              may start below -backlash)
//   /table/load               float64 [n_second], unit = "N"   (stiffness tables), or
//   /table/torque             float64 [n_second], unit = "N*m" (STE tables, version 2)
//   /table/values             float64 [n_theta][n_second] (row-major, theta slowest),
//                             attributes unit = "N*m" | "N/m" | "m",
//                             quantity = "torque" | "stiffness" | "transmission error"
//
// All numbers are stored as IEEE float64, so a round trip is bit-exact. Strings are
// variable-length UTF-8 (h5py reads them as str); fixed-length strings are also accepted.
// No deal.II here: this is a light module (HDF5 C API only).
#include "io/mesh_table.h"

#include <filesystem>
#include <string>

namespace gearfem::io
{
  /// Value of the root attribute `format`.
  inline constexpr const char *mesh_table_format = "gearfem-mesh-table";
  /// The newest value of the root attribute `format_version`; the reader accepts 1 to this.
  /// Bumped on every incompatible change of the layout (docs/mesh-tables.md). Version 2
  /// adds two-sided torque tables (negative delta, attribute /table@backlash) and
  /// transmission-error tables STE(theta, T); files that need neither are still written as
  /// version 1.
  inline constexpr int mesh_table_format_version = 2;

  /// Where a table came from.
  struct TableProvenance
  {
    /// The command or run that made the table, e.g. "gearfem mesh-table pair.prm".
    std::string source;
    /// Timestamp, ISO 8601 (UTC); empty: write_mesh_table uses the current time.
    std::string created;
  };

  /// What a mesh-table file carries besides the table itself.
  struct MeshTableFileInfo
  {
    TableProvenance provenance;
    int format_version = 0;
    double valid_min = 0, valid_max = 0; ///< validity range of the second axis (m or N)
  };

  /// Write `table` to `file` atomically (temporary name in the same folder, then rename):
  /// on any failure nothing appears at `file` and an existing file there is untouched.
  /// The table is checked first (MeshTable::check). The second-axis validity range is
  /// written as [second.front(), second.back()].
  /// Throws InputError if the table is invalid or the file cannot be created (e.g. the
  /// folder does not exist), std::runtime_error for other HDF5 write failures.
  void write_mesh_table(const std::filesystem::path &file, const MeshTable &table,
                        const TableProvenance &provenance);

  /// Read a mesh table and check it (MeshTable::check, with `expected_hash` if not empty).
  /// Throws InputError naming the file and the dataset or attribute for: a missing file, a
  /// file that is not HDF5 or is corrupt, a wrong `format` or `format_version`, missing
  /// axes or values, wrong units, sizes that do not match, and a geometry-hash mismatch.
  /// @param info if not null, receives the provenance, version and validity range.
  MeshTable read_mesh_table(const std::filesystem::path &file,
                                      const std::string &expected_hash = "",
                                      MeshTableFileInfo *info = nullptr);
} // namespace gearfem::io
