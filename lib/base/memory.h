#pragma once
// Peak resident memory and CPU time of this process, for the benchmarks that print figures.
#include <sys/resource.h>

namespace gearfem
{
  /// Peak resident set size [MB] (getrusage; ru_maxrss is in kB on Linux).
  inline double peak_memory_mb()
  {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;
  }

  /// CPU time (user + system) of this process so far [s] (getrusage): on a shared machine a
  /// truer cost than the wall time.
  inline double process_cpu_seconds()
  {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
} // namespace gearfem
