#pragma once
// The mesh-force law of `Law = external` built from its source (DynamicsCase::external_source):
//  - analytical: the Gkimisis 2019 torque table T(theta, delta) of the Weber/Cornell model with
//    corner contacts on the pair generated from `Dynamics/Pair`;
//  - table file: an HDF5 mesh table (io/mesh_table_io.h) checked against the case (geometry
//    hash, period, base radius, static load inside the table);
//  - ricker: the semi-analytical law of Gkimisis 2019 with Ricker-wavelet load sharing.
// Light layer (geometry, analytical, io; no deal.II).
#include "dynamics/case.h"
#include "dynamics/mesh_force.h"

#include <memory>
#include <string>
#include <vector>

namespace gearfem::dynamics
{
  /// The law of `c`. `backlash` [m]: if < 0 on entry, set to the generated pair's normal
  /// backlash (a two-sided table brings its own). `notes` receives one line describing the
  /// law. Throws InputError naming the entry for a table file that does not fit the case.
  std::shared_ptr<const MeshForceLaw> external_law(const DynamicsCase &c, double &backlash,
                                                   std::vector<std::string> &notes);
} // namespace gearfem::dynamics
