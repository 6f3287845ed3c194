#pragma once
// `gearfem bench condensed case.prm`: the condensed cycle of the case against the full FE,
// in one process on one model. Builds the cycle at the first torque of the case (range a
// quarter to four times it), then solves variants (half and twice the torque, and a 10 um
// long linear tip relief on both gears on the gap route) both ways over the case's
// positions and prints, per variant: the time per position of each route and their ratio,
// and the largest differences in STE, root stress and load share. Figures are printed,
// never asserted.
#include <filesystem>
#include <ostream>

namespace gearfem::condensed
{
  void benchmark(const std::filesystem::path &prm_file, std::ostream &out);
} // namespace gearfem::condensed
