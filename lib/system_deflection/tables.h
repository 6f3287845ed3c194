#pragma once
// The shaft tables shared by `gearfem helical` on its shafts (run.h) and `gearfem system`
// (train.h): coupling.csv, misalignment.csv, shafts.csv and bearings.csv. Internal to the
// module.
#include "system_deflection/coupled.h"
#include "system_deflection/run.h"

#include <filesystem>
#include <vector>

namespace gearfem::system_deflection
{
  /// The coupled results of one mesh over a sweep (torque-major, `grid` positions a torque).
  struct MeshTables
  {
    int stage = 0; ///< 1-based; 0: a single pair (no stage column)
    std::size_t grid = 1;
    const std::vector<CoupledResult> *coupled = nullptr;
  };

  /// The result of the positions of `results` at `torque` with their mean slice forces (the
  /// shafts are linear: the shafts under the mean forces are the mean of the shafts); n: how
  /// many positions (0: none, and the result is empty).
  CoupledResult mean_at(const std::vector<CoupledResult> &results, double torque, int &n);

  /// The four tables into `dir`, each written atomically; a `stage` column when the meshes are
  /// stages of a train.
  void write_shaft_tables(const std::vector<MeshTables> &meshes, const std::vector<TorqueShafts> &shafts,
                          const shafts::System &system, const std::filesystem::path &dir);
  /// The per-torque method C objects of system.json (without the brackets).
  void write_method_c(std::ostream &s, const std::vector<MethodC> &iso);
} // namespace gearfem::system_deflection
