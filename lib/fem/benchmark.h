#pragma once
// The fem benchmark: a full gear of the input's gear 1 with
// h_contact = h_fillet = 0.4, 0.2, 0.1 mm on the fine teeth (Mesh section otherwise), Q2,
// clamped bore, ISO tip load on tooth 0; prints cells, DoFs, the times to mesh, assemble,
// factorise and solve, peak memory and the fillet-stress error against the finest level.
// Figures only: nothing is asserted.
#include <filesystem>
#include <ostream>

namespace gearfem::fem
{
  /// Run the benchmark on `prm_file` (sections Rack, Gear 1/2, Pair, Material, Mesh,
  /// Finite elements; other sections are ignored) and print a Markdown table to `out`.
  void benchmark(const std::filesystem::path &prm_file, std::ostream &out);
} // namespace gearfem::fem
