#pragma once
// A gearbox study end to end, without the FE stress source: the standard stresses of every
// mesh replaced by the study's stress source (AGMA from the geometry, ISO 6336, or a table
// scaled from a reference torque), and every output file of `gearfem gearbox` (gearbox.md,
// gearbox.csv, gearbox_life.csv, gearbox_sn.csv, scuffing_path.csv and gearbox.h5). The FE
// source is gearbox/fe/source.h. Light layer (no deal.II). SI units.
#include "gearbox/parameters.h"
#include "gearbox/report.h"

#include <filesystem>
#include <string>

namespace gearfem::gearbox
{
  /// The stress source's name as `--validate` reports it ("AGMA", "ISO", "table", "FE").
  const char *source_name(StressSource s);

  /// Apply the study's standard stress source (agma: nothing to do; iso; table) to `r`;
  /// returns the sentence that describes the source in the report. The FE source is applied
  /// by gearbox::fe::apply_fe_source, which returns its own sentence.
  std::string apply_standard_source(GearboxResult &r, const GearboxStudy &study);

  /// Write every output of the study into `dir` (docs/output-format.md): `input_name` is the
  /// study file's name (title and the HDF5 `input` attribute), `fe_text` the FE section of
  /// gearbox.md (empty without the FE source).
  void write_gearbox_outputs(const GearboxInput &in, const GearboxResult &r, const std::string &source,
                             const std::filesystem::path &dir, const std::string &input_name,
                             const std::string &fe_text = {});
} // namespace gearfem::gearbox
