#pragma once
// Output helpers of the fem module (the VTU writer itself is ElasticBody::write_vtu).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace gearfem::fem
{
  /// Write a ParaView .pvd collection of (time or position, vtu file name) records, atomically.
  void write_pvd(const std::filesystem::path &file,
                 const std::vector<std::pair<double, std::string>> &records);
} // namespace gearfem::fem
