// Error messages of the root-finding utility (base/roots.h).
#include "base/roots.h"

#include <sstream>

namespace gearfem::base::detail
{
  void throw_not_bracketed(const std::string &what, double lo, double hi, double f_lo, double f_hi)
  {
    std::ostringstream s;
    s.precision(17);
    s << what << ": the interval [" << lo << ", " << hi << "] does not bracket a root (f = " << f_lo
      << " and " << f_hi << " at its ends)";
    throw SolverError(s.str());
  }

  void throw_not_converged(const std::string &what, const char *method, double lo, double hi,
                           long iterations, const std::string &reason)
  {
    std::ostringstream s;
    s.precision(17);
    s << what << ": " << method << " did not converge after " << iterations
      << " iterations, bracket [" << lo << ", " << hi << "] (" << reason << ")";
    throw SolverError(s.str());
  }
} // namespace gearfem::base::detail
