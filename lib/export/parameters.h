#pragma once
// The `Export` section of `gearfem export` (docs/export.md). Engineering units at the
// interface (N m, um); parse_export_parameters converts to SI.
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace gearfem::exports
{
  /// What to export and from where.
  struct ExportInput
  {
    std::string source;             ///< Export/Source file (relative to the input file's folder)
    std::string source_kind;        ///< "solve results" or "mesh table"
    std::vector<double> torques;    ///< Export/Torques [N m]; empty: the source's own
    std::vector<std::string> formats; ///< subset of {ross, spline, te, force}
    double backlash = -1;           ///< Export/Backlash [m]; < 0: none given
  };

  void declare_export_parameters(dealii::ParameterHandler &prm);
  /// Throws InputError naming the entry for an empty source or an unknown format.
  ExportInput parse_export_parameters(dealii::ParameterHandler &prm);
} // namespace gearfem::exports
