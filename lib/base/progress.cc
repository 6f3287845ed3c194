#include "base/progress.h"

#include <cstdio>

namespace gearfem
{
  Progress::Progress(std::ostream *out, std::size_t total, std::string label, std::size_t done)
    : out_(out)
    , total_(total)
    , done_(done)
    , label_(std::move(label))
    , start_(std::chrono::steady_clock::now())
  {}

  double Progress::elapsed_seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  void Progress::step(std::size_t i, const std::string &detail)
  {
    if (out_ == nullptr)
      return;
    const double t   = elapsed_seconds();
    const double eta = i > done_ && i <= total_ ? t / double(i - done_) * double(total_ - i) : 0.0;
    char buf[128];
    std::snprintf(buf, sizeof(buf), "%s %zu/%zu  elapsed %.1f s  ETA %.1f s", label_.c_str(), i,
                  total_, t, eta);
    (*out_) << buf;
    if (!detail.empty())
      (*out_) << "  " << detail;
    (*out_) << std::endl;
  }
} // namespace gearfem
