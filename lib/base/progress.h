#pragma once
// Progress lines for long runs: "label i/N ... ETA".
#include <chrono>
#include <ostream>
#include <string>

namespace gearfem
{
  /// Wall seconds since t0 on the steady clock.
  inline double since(std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  class Progress
  {
  public:
    /// @param out    where to print (rank-0 stream); nullptr silences it
    /// @param total  number of steps N
    /// @param done   steps already done before this run (a resumed run): the ETA is
    ///               estimated from the steps of this run only
    Progress(std::ostream *out, std::size_t total, std::string label, std::size_t done = 0);
    /// Report that step i (1-based) has finished; `detail` is appended to the line.
    void step(std::size_t i, const std::string &detail = "");
    double elapsed_seconds() const;

  private:
    std::ostream *out_;
    std::size_t total_, done_;
    std::string label_;
    std::chrono::steady_clock::time_point start_;
  };
} // namespace gearfem
