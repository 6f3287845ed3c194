#include "dynamics/ricker_law.h"
#include "base/units.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace gearfem::dynamics
{
  namespace
  {
    using units::pi;
    /// Midpoint samples per period for the mean stiffness.
    constexpr int mean_samples = 4096;
  } // namespace

  RickerLoadSharingLaw::RickerLoadSharingLaw(PairStiffness K, const RickerLawParameters &p)
    : K_(std::move(K))
    , p_(p)
  {
    if (!K_)
      throw InputError("Ricker law/pair stiffness", "(none)", "a stiffness function K(w1, x)");
    require_range("Ricker law/z1", p.z1, 5, 1000);
    period_ = 2 * pi / p.z1;
    if (!(p.omega_A < 0))
      throw InputError("Ricker law/omega_A", to_string_g(p.omega_A) + " rad", "< 0 rad");
    if (!(p.omega_B > 0))
      throw InputError("Ricker law/omega_B", to_string_g(p.omega_B) + " rad", "> 0 rad");
    const double eps = (p.omega_B - p.omega_A) / period_;
    if (!(eps > 1 && eps < 2))
      throw InputError("Ricker law/contact ratio (omega_B - omega_A) z1/(2 pi)",
                       to_string_g(eps), "(1, 2)",
                       "the load sharing of eq. 3.36 assumes one or two pairs in contact");
    if (!(p.c_x >= 0))
      throw InputError("Ricker law/c_x", to_string_g(p.c_x) + " rad/m", ">= 0 rad/m");
    if (!(p.nominal_compression >= 0))
      throw InputError("Ricker law/nominal compression", to_string_g(p.nominal_compression) + " m",
                       ">= 0 m");
    require_greater("Ricker law/min stiffness compression", p.min_stiffness_compression, 0, "m");
    wbar_ = 0.5 * (p.omega_A + p.omega_B);

    double sum = 0;
    for (int i = 0; i < mean_samples; ++i)
      sum += stiffness(wbar_ - 0.5 * period_ + period_ * (i + 0.5) / mean_samples,
                       p.nominal_compression);
    kbar_ = sum / mean_samples;
  }

  std::vector<double> RickerLoadSharingLaw::breaks() const
  {
    if (p_.second_pair == SecondPair::thesis)
      return {0.0};
    return {};
  }

  double RickerLoadSharingLaw::reduce(double theta) const
  {
    const double lo = wbar_ - 0.5 * period_;
    return theta - period_ * std::floor((theta - lo) / period_);
  }

  double RickerLoadSharingLaw::single_contact_width(double x) const
  {
    return 2 * period_ - (p_.omega_B - p_.omega_A) - p_.c_x * std::max(x, 0.0); // eq. 3.42
  }

  double RickerLoadSharingLaw::f_m(double x) const
  {
    const double L = single_contact_width(x);
    return L > 0 ? std::sqrt(3.0) / (pi * L) : std::numeric_limits<double>::infinity();
  }

  double RickerLoadSharingLaw::wavelet(double theta, double x) const
  {
    const double fm = f_m(x);
    if (!std::isfinite(fm))
      return 0.0; // the single-contact zone has closed: two pairs everywhere
    const double fc = 2 * fm;                // eq. 3.43
    const double s = reduce(theta) - wbar_;  // w1 - (w_A + w_B)/2
    return (1 - 2 * pi * pi * fm * fm * s * s) * std::exp(-pi * pi * fc * fc * s * s); // 3.37
  }

  double RickerLoadSharingLaw::second_pair_angle(double theta) const
  {
    const double w = reduce(theta);
    const double ref = p_.second_pair == SecondPair::thesis ? w : w - wbar_;
    return w - (ref >= 0 ? 1.0 : -1.0) * period_; // eq. 3.45
  }

  double RickerLoadSharingLaw::stiffness(double theta, double x) const
  {
    const double xk = std::max(std::abs(x), p_.min_stiffness_compression);
    const double w = reduce(theta);
    return K_(w, xk) + second_pair_weight(w, x) * K_(second_pair_angle(w), xk); // eq. 3.36
  }

  double RickerLoadSharingLaw::force(double theta, double delta, int) const
  {
    return stiffness(theta, delta) * delta; // eq. 3.36 (3.46: T = F R_g1)
  }

  double RickerLoadSharingLaw::load_share(double theta, double x) const
  {
    const double xk = std::max(std::abs(x), p_.min_stiffness_compression);
    const double w = reduce(theta);
    const double k1 = K_(w, xk);
    return k1 / (k1 + second_pair_weight(w, x) * K_(second_pair_angle(w), xk));
  }
} // namespace gearfem::dynamics
