#include "gearbox/fatigue.h"

#include "base/errors.h"

#include <cmath>

namespace gearfem::gearbox::fatigue
{
  SNCurve iso_curve(const std::string &mode, const std::string &group, double sigma_lim)
  {
    SNCurve c;
    c.kind = SNCurve::Kind::iso;
    c.sigma_n = sigma_lim;
    if (mode == "contact" && group == "Eh")
      c.N_static = 1e5, c.Y_static = 1.6, c.N_ref = 5e7;
    else if (mode == "contact" && group == "NT")
      c.N_static = 1e5, c.Y_static = 1.3, c.N_ref = 2e6;
    else if (mode == "bending" && group == "Eh")
      c.N_static = 1e3, c.Y_static = 2.5, c.N_ref = 3e6;
    else if (mode == "bending" && group == "NT")
      c.N_static = 1e3, c.Y_static = 1.6, c.N_ref = 3e6;
    else
      throw InputError("ISO life factor material group (" + mode + ")", group, "Eh|NT");
    return c;
  }

  void check_curve(const SNCurve &c, const std::string &p)
  {
    require_greater(p + " endurance stress", c.sigma_n / 1e6, 0.0, "MPa");
    require_greater(p + " reference cycles", c.N_ref, 1.0);
    if (c.kind == SNCurve::Kind::semi_log)
      {
        if (!(c.B < 0.0))
          throw InputError(p + " S-N slope B", to_string_g(c.B / 1e6) + " MPa/decade", "< 0 MPa/decade");
      }
    else
      {
        require_range(p + " static cycles", c.N_static, 1.0, c.N_ref);
        require_greater(p + " static life factor", c.Y_static, 1.0);
      }
  }

  double life_factor(const SNCurve &c, double N)
  {
    if (N >= c.N_ref)
      return 1.0;
    if (N <= c.N_static)
      return c.Y_static;
    const double t = std::log10(N / c.N_ref) / std::log10(c.N_static / c.N_ref);
    return std::pow(c.Y_static, t);
  }

  double cycles_to_failure(const SNCurve &c, double sigma)
  {
    if (!(sigma > c.sigma_n))
      return infinite_life;
    if (c.kind == SNCurve::Kind::semi_log)
      return c.N_ref * std::pow(10.0, (sigma - c.sigma_n) / c.B);
    const double Y = sigma / c.sigma_n;
    if (Y >= c.Y_static)
      return c.N_static;
    // Y = Y_static^(log(N/N_ref)/log(N_static/N_ref))  =>  N = N_ref (N_static/N_ref)^(ln Y/ln Y_static)
    return c.N_ref * std::pow(c.N_static / c.N_ref, std::log(Y) / std::log(c.Y_static));
  }

  Damage miner(const SNCurve &c, const std::vector<double> &sigma, const std::vector<double> &cycles)
  {
    if (sigma.size() != cycles.size())
      throw InputError("Miner: stresses per bin", std::to_string(sigma.size()) + " values",
                       std::to_string(cycles.size()) + " values (one per spectrum bin)");
    Damage d;
    for (std::size_t i = 0; i < sigma.size(); ++i)
      {
        if (!(cycles[i] >= 0.0))
          throw InputError("Miner: load cycles of bin " + std::to_string(i + 1), to_string_g(cycles[i]), ">= 0");
        const double N = cycles_to_failure(c, sigma[i]);
        d.per_bin.push_back(std::isinf(N) ? 0.0 : cycles[i] / N);
        d.D += d.per_bin.back();
      }
    d.life_spectra = d.D > 0.0 ? 1.0 / d.D : infinite_life;
    return d;
  }

  void Spectrum::check() const
  {
    if (torques.empty())
      throw InputError("Spectrum/Torques", "(empty)", "one or more torque bins > 0 N m");
    if (revolutions.size() != torques.size())
      throw InputError("Spectrum/Revolutions", std::to_string(revolutions.size()) + " values",
                       std::to_string(torques.size()) + " values (one per torque bin)");
    double total = 0.0;
    for (std::size_t i = 0; i < torques.size(); ++i)
      {
        require_greater("Spectrum/Torques", torques[i], 0.0, "N m");
        if (!(revolutions[i] >= 0.0))
          throw InputError("Spectrum/Revolutions", to_string_g(revolutions[i]) + " (bin " + std::to_string(i + 1) + ")",
                           ">= 0");
        total += revolutions[i];
      }
    if (!(total > 0.0))
      throw InputError("Spectrum/Revolutions", "all zero", "a total > 0");
    require_greater("Spectrum/Duration", duration_years, 0.0, "years");
  }

  double Spectrum::total_revolutions() const
  {
    double t = 0.0;
    for (double r : revolutions)
      t += r;
    return t;
  }

  std::vector<double> revolutions_from_hours(const std::vector<double> &hours, double speed)
  {
    require_greater("Gearbox/Input speed", speed, 0.0, "rpm");
    std::vector<double> r;
    for (double h : hours)
      {
        if (!(h >= 0.0))
          throw InputError("Spectrum/Hours", to_string_g(h), ">= 0 h");
        r.push_back(60.0 * speed * h);
      }
    return r;
  }
} // namespace gearfem::gearbox::fatigue
