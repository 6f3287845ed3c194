#pragma once
// Performance figures of the dynamics module, printed, not asserted.
#include <ostream>

namespace gearfem::dynamics
{
  /// Prints: RHS evaluations per second of the 1-DOF table model; steps per second and wall
  /// time of one speed point of 300 mesh periods (table force); wall time of a full up/down
  /// sweep of 2 x 200 speeds x 300 periods on two threads. `scale` < 1 shortens the runs
  /// (for a smoke test); the figures are then extrapolated and marked as such.
  void benchmark(std::ostream &out, double scale = 1.0);
} // namespace gearfem::dynamics
