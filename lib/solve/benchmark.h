#pragma once
// `gearfem bench solve case.prm`: the contact sweep of the case (first torque) with both
// methods, each position evaluated as `gearfem solve` does (the `Post` section of the case);
// prints DoFs, iterations, time per position (search / flexibility / contact solve /
// post-processing), total sweep time and peak memory; then, on the same model with its
// flexibility cached, frictionless against frictional sweeps (the input's coefficient, else
// 0.05) per position. Figures are printed, never asserted.
#include <filesystem>
#include <ostream>

namespace gearfem::solve
{
  void benchmark(const std::filesystem::path &prm_file, std::ostream &out);
} // namespace gearfem::solve
