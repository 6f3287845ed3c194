// Manufacturing deviations: ISO 1328-1:2013 tolerances, random draws, flank offsets.
#include "geometry/deviations.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gearfem::geometry
{
  namespace
  {
    constexpr double um = 1e-6, mm = 1e-3;

    /// splitmix64 (Steele, Lea & Flood 2014): a portable, seedable generator.
    struct Rng
    {
      std::uint64_t s;
      std::uint64_t next()
      {
        std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
      }
      double uniform01() { return double(next() >> 11) * 0x1.0p-53; } ///< [0, 1)
      double symmetric() { return 2 * uniform01() - 1; }              ///< [-1, 1)
      /// Standard normal truncated at +-3 (Box-Muller, redrawn beyond).
      double normal3()
      {
        for (;;)
          {
            const double u1 = 1.0 - uniform01(), u2 = uniform01();
            const double n  = std::sqrt(-2 * std::log(u1)) * std::cos(2 * units::pi * u2);
            if (std::abs(n) <= 3)
              return n;
          }
      }
      double draw(Distribution d) { return d == Distribution::uniform ? symmetric() : normal3() / 3; }
    };

    template <typename T>
    const T &per_tooth(const std::vector<T> &v, int tooth)
    {
      return v.size() == 1 ? v[0] : v[std::size_t(tooth)];
    }

    int wrap(int k, int z) { return ((k % z) + z) % z; }
  } // namespace

  double iso1328_round(double value)
  {
    const double v = value / um;
    const double a = std::abs(v);
    const double step = a > 10 ? 1.0 : (a >= 5 ? 0.5 : 0.1);
    return std::copysign(std::round(a / step) * step, v) * um;
  }

  Iso1328Tolerances iso1328_tolerances(int grade, double m_n, double d, double b, bool rounded, const std::string &entry)
  {
    if (grade < 1 || grade > 11)
      throw InputError(entry, std::to_string(grade), "1 .. 11 (ISO 1328-1:2013 flank tolerance classes)");
    const double m = m_n / mm, D = d / mm, B = b / mm;
    if (!(m >= 0.5 && m <= 70))
      throw InputError(entry, "module " + to_string_g(m) + " mm",
                       "0.5 .. 70 mm (range of application of ISO 1328-1:2013)");
    if (!(D >= 5 && D <= 15000))
      throw InputError(entry, "reference diameter " + to_string_g(D) + " mm",
                       "5 .. 15000 mm (range of application of ISO 1328-1:2013)");
    if (!(B >= 4 && B <= 1200))
      throw InputError(entry, "face width " + to_string_g(B) + " mm",
                       "4 .. 1200 mm (range of application of ISO 1328-1:2013)");
    const double s = std::pow(std::sqrt(2.0), grade - 5);
    const auto r = [&](double v_um) { return rounded ? iso1328_round(v_um * um) : v_um * um; };
    Iso1328Tolerances t;
    t.grade = grade;
    const double f_pt = (0.001 * D + 0.4 * m + 5) * s, F_p = (0.002 * D + 0.55 * std::sqrt(D) + 0.7 * m + 12) * s;
    const double f_Ha = (0.4 * m + 0.001 * D + 4) * s, f_fa = (0.55 * m + 5) * s;
    const double f_Hb = (0.05 * std::sqrt(D) + 0.35 * std::sqrt(B) + 4) * s;
    const double f_fb = (0.07 * std::sqrt(D) + 0.45 * std::sqrt(B) + 4) * s;
    t.f_pT  = r(f_pt);
    t.F_pT  = r(F_p);
    t.f_HaT = r(f_Ha);
    t.f_faT = r(f_fa);
    t.F_aT  = r(std::hypot(f_Ha, f_fa));
    t.f_HbT = r(f_Hb);
    t.f_fbT = r(f_fb);
    t.F_bT  = r(std::hypot(f_Hb, f_fb));
    t.F_rT  = r(0.9 * F_p);
    return t;
  }

  double ProfileForm::at(double u, double s) const
  {
    switch (kind)
      {
        case Kind::parabolic:
          return amplitude * (1.0 / 3.0 - 4 * u * u);
        case Kind::table:
          {
            if (trace.empty())
              return 0;
            if (s <= trace.front().first)
              return trace.front().second;
            if (s >= trace.back().first)
              return trace.back().second;
            const auto it = std::lower_bound(trace.begin(), trace.end(), s,
                                             [](const auto &p, double v) { return p.first < v; });
            const auto &[s1, v1] = *it;
            const auto &[s0, v0] = *(it - 1);
            return v0 + (v1 - v0) * (s - s0) / (s1 - s0);
          }
        default:
          return 0;
      }
  }

  std::vector<double> GearDeviations::cumulative_pitch() const
  {
    std::vector<double> F(f_pt.size(), 0.0);
    for (std::size_t k = 1; k < f_pt.size(); ++k)
      F[k] = F[k - 1] + f_pt[k];
    return F;
  }

  bool GearDeviations::empty() const
  {
    const auto zero = [](const std::vector<double> &v) {
      return std::all_of(v.begin(), v.end(), [](double x) { return x == 0; });
    };
    const bool no_form = std::all_of(form.begin(), form.end(), [](const ProfileForm &f) {
      return f.kind == ProfileForm::Kind::none || (f.kind == ProfileForm::Kind::parabolic && f.amplitude == 0);
    });
    return zero(f_pt) && zero(f_Ha) && no_form && flank_offset == 0 && eccentricity == 0;
  }

  void PairDeviations::finalise()
  {
    // The datum of the cumulative pitch deviations is the mean position of the teeth: a common
    // shift of every tooth is a rigid turn of the gear, which only moves the mean STE, and the
    // choice of tooth 0 as datum must not.
    for (int b = 0; b < 2; ++b)
      {
        cumulative[b] = gear[b].cumulative_pitch();
        if (cumulative[b].empty())
          continue;
        double mean = 0;
        for (const double F : cumulative[b])
          mean += F;
        mean /= double(cumulative[b].size());
        for (double &F : cumulative[b])
          F -= mean;
      }
  }

  double PairDeviations::rigid_plus_material(int body, int tooth) const
  {
    const auto &F = cumulative[body - 1];
    const int k   = wrap(tooth, teeth[body - 1]);
    return gear[body - 1].flank_offset + (F.empty() ? 0.0 : F[std::size_t(k)] * range[body - 1].cos_alpha);
  }

  double PairDeviations::tooth_rotation(int body, int tooth) const
  {
    return rigid_plus_material(body, tooth) / range[body - 1].base_radius;
  }

  double PairDeviations::profile_plus_material(int body, int tooth, double r) const
  {
    const auto &g = gear[body - 1];
    const auto &R = range[body - 1];
    const int k   = wrap(tooth, teeth[body - 1]);
    const double xi = std::sqrt(std::max(0.0, r * r - R.base_radius * R.base_radius));
    const double L  = R.xi_end - R.xi_start;
    const double u  = L > 0 ? (xi - 0.5 * (R.xi_start + R.xi_end)) / L : 0.0;
    double v = 0;
    if (!g.f_Ha.empty())
      v += per_tooth(g.f_Ha, k) * u;
    if (!g.form.empty())
      v += per_tooth(g.form, k).at(u, xi - R.xi_start);
    return v;
  }

  double PairDeviations::plus_material(int body, int tooth, double r) const
  {
    return rigid_plus_material(body, tooth) + profile_plus_material(body, tooth, r);
  }

  Eigen::Vector2d PairDeviations::runout(int body, double angle) const
  {
    const auto &g = gear[body - 1];
    const double a = angle + g.eccentricity_phase;
    return g.eccentricity * Eigen::Vector2d(std::cos(a), std::sin(a));
  }

  void check_deviations(const GearDeviations &d, int z, const std::string &section)
  {
    const auto sized = [&](std::size_t n, const std::string &what) {
      if (n != 0 && n != 1 && n != std::size_t(z))
        throw InputError(section + "/" + what, std::to_string(n) + " values",
                         "none, one common value, or one per tooth (" + std::to_string(z) + ")");
    };
    if (!d.f_pt.empty() && d.f_pt.size() != std::size_t(z))
      throw InputError(section + "/Single pitch deviations", std::to_string(d.f_pt.size()) + " values",
                       "none, or one per tooth (" + std::to_string(z) + ")");
    sized(d.f_Ha.size(), "Profile slope deviation");
    sized(d.form.size(), "Profile form");
    double sum = 0, big = 0;
    for (const double f : d.f_pt)
      {
        if (!std::isfinite(f) || std::abs(f) > 1e-3)
          throw InputError(section + "/Single pitch deviations", to_string_g(f / um) + " um", "|f_pt| <= 1000 um");
        sum += f, big = std::max(big, std::abs(f));
      }
    if (std::abs(sum) > std::max(1e-3 * big, 1e-12))
      throw InputError(section + "/Single pitch deviations", "sum " + to_string_g(sum / um) + " um",
                       "0 (the pitches of a gear close the circle)",
                       "subtract the mean, or let gearfem draw them (Deviations/Accuracy grade)");
    for (const double f : d.f_Ha)
      if (!std::isfinite(f) || std::abs(f) > 1e-3)
        throw InputError(section + "/Profile slope deviation", to_string_g(f / um) + " um", "|f_Ha| <= 1000 um");
    if (!std::isfinite(d.eccentricity) || d.eccentricity < 0 || d.eccentricity > 1e-3)
      throw InputError(section + "/Runout", to_string_g(2 * d.eccentricity / um) + " um", "0 .. 2000 um");
    if (!std::isfinite(d.flank_offset) || std::abs(d.flank_offset) > 1e-3)
      throw InputError(section + "/Flank offset", to_string_g(d.flank_offset / um) + " um", "-1000 .. 1000 um");
  }

  Distribution distribution_from_string(const std::string &s, const std::string &entry)
  {
    if (s == "uniform")
      return Distribution::uniform;
    if (s == "truncated normal")
      return Distribution::truncated_normal;
    throw InputError(entry, s, "{uniform, truncated normal}");
  }

  const char *to_string(Distribution d) { return d == Distribution::uniform ? "uniform" : "truncated normal"; }

  GearDeviations draw_deviations(const Iso1328Tolerances &t, int z, Distribution dist, std::uint64_t seed,
                                 std::uint64_t stream)
  {
    Rng rng{seed * 0x2545F4914F6CDD1Dull + stream * 0x9E3779B97F4A7C15ull + 1};
    GearDeviations d;
    d.f_pt.resize(std::size_t(z));
    for (auto &f : d.f_pt)
      f = t.f_pT * rng.draw(dist);
    const double mean = std::accumulate(d.f_pt.begin(), d.f_pt.end(), 0.0) / z;
    for (auto &f : d.f_pt)
      f -= mean;
    // Removing the mean can push a single pitch beyond f_pT, and the cumulative deviations
    // of a random walk usually span more than F_pT: one common scale brings both within their
    // tolerance and keeps the closure.
    const auto F = d.cumulative_pitch();
    const auto [lo, hi] = std::minmax_element(F.begin(), F.end());
    double f_max = 0;
    for (const double f : d.f_pt)
      f_max = std::max(f_max, std::abs(f));
    double scale = 1;
    if (f_max > t.f_pT)
      scale = std::min(scale, t.f_pT / f_max);
    if (*hi - *lo > t.F_pT)
      scale = std::min(scale, t.F_pT / (*hi - *lo));
    for (auto &f : d.f_pt)
      f *= scale;
    d.f_Ha.resize(std::size_t(z));
    for (auto &f : d.f_Ha)
      f = t.f_HaT * rng.draw(dist);
    d.form.resize(std::size_t(z));
    for (auto &f : d.form)
      {
        f.kind      = ProfileForm::Kind::parabolic;
        f.amplitude = t.f_faT * rng.draw(dist);
      }
    const double Fr = t.F_rT * std::abs(rng.draw(dist));
    d.eccentricity       = 0.5 * Fr;
    d.eccentricity_phase = 2 * units::pi * rng.uniform01();
    return d;
  }

  long hunting_pitches(int z1, int z2) { return long(z1) / std::gcd(z1, z2) * long(z2); }
} // namespace gearfem::geometry
