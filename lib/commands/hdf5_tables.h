#pragma once
// Column tables to HDF5: one group per table, one 1-D float64 dataset per column named like
// the CSV header "name [unit]" (with '/' written " per "), plus string attributes on the root. Written to a temporary
// name and renamed (no truncated file on failure). Layouts: docs/output-format.md.
#include "base/table.h"

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::commands
{
  /// HDF5 reserves '/' in names: the dataset of CSV header "k [N/m]" is "k [N per m]".
  std::string dataset_name(const std::string &header);

  void write_hdf5_tables(const std::vector<std::pair<std::string, Table>> &tables,
                         const std::filesystem::path &file,
                         const std::map<std::string, std::string> &attributes);
} // namespace gearfem::commands
