#pragma once
// Peak resident memory of this process, for the benchmarks that print figures.
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
} // namespace gearfem
