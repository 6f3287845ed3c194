#pragma once
// Speed figures of the analytical models, printed by `gearfem bench
// analytical`: mesh stiffness over one pitch at 1000 positions (target <= 10 ms) and
// stiffness/torque tables of 200 x 50 (target <= 1 s). Timings are printed, never asserted.
#include <ostream>

namespace gearfem::analytical
{
  /// Runs the benchmark on the Siasos 2010 23/69 m 4 pair (Weber/Cornell, load-dependent Hertz)
  /// and the 62/62 m 2 pair (potential energy) and prints one line per figure.
  void benchmark(std::ostream &out);
} // namespace gearfem::analytical
