#pragma once
// The FE stress source of a gearbox study (`Stress source = FE`): the meshes solved
// as `gearfem solve` sector models (fe_stress.h), their stresses put into the result, the
// per-mesh table written, and the FE section of gearbox.md.
#include "gearbox/fe/fe_stress.h"

#include <filesystem>
#include <string>

namespace gearfem::gearbox::fe
{
  struct FeSourceOutcome
  {
    std::string source;  ///< the sentence that describes the source in the report
    std::string text;    ///< the FE section of gearbox.md
    std::string failure; ///< a solver failure of one mesh (the finished meshes are kept), or empty
  };

  /// Solve the meshes (into options.output_dir), use their stresses in `r`, write
  /// `table_file` (fe_stresses.csv).
  FeSourceOutcome apply_fe_source(gb::GearboxResult &r, const gb::GearboxInput &in, const FeStressOptions &options,
                                  const std::filesystem::path &table_file);
} // namespace gearfem::gearbox::fe
