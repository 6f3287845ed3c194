// Equivalent tooth mass and tooth inertia along the path of contact (tooth_mass.h).
#include "dynamics/tooth_mass.h"

#include "analytical/from_geometry.h"
#include "analytical/quadrature.h"
#include "base/errors.h"
#include "base/units.h"
#include "geometry/pair.h"

#include <algorithm>
#include <cmath>

namespace gearfem::dynamics
{
  double deflection_shape(double y, double y_load, double s)
  {
    return s + (1.0 - s) * std::min(std::max(y, 0.0) / y_load, 1.0);
  }

  double tooth_mass(const analytical::ToothBeam &tooth, double density, double face_width)
  {
    require_greater("tooth height", tooth.height, 0.0, "m");
    return density * face_width *
           analytical::integrate(tooth.thickness, 0.0, tooth.height, 1e-10, 0.0, tooth.breakpoints);
  }

  double equivalent_tooth_mass(const analytical::ToothBeam &tooth, double y_load, double s,
                               double density, double face_width, ToothMassWeighting weighting)
  {
    require_greater("tooth height", tooth.height, 0.0, "m");
    if (!(y_load > 0 && y_load <= tooth.height * (1 + 1e-12)))
      throw InputError("tooth load height", to_string_g(y_load) + " m",
                       "(0, " + to_string_g(tooth.height) + "] m (root circle to tip)");
    if (!(s >= 0 && s <= 1))
      throw InputError("tooth foundation share", to_string_g(s), "[0, 1]");
    require_greater("Dynamics/Pair/Density", density, 0.0, "kg/m^3");
    require_greater("Dynamics/Pair/Face width", face_width, 0.0, "m");
    const bool squared = weighting == ToothMassWeighting::kinetic_energy;
    auto f = [&](double y) {
      const double w = deflection_shape(y, y_load, s);
      return tooth.thickness(y) * (squared ? w * w : w);
    };
    // The shape has a kink at the load height: split there, and at the fillet/flank kinks.
    std::vector<double> br = tooth.breakpoints;
    if (y_load < tooth.height)
      br.push_back(y_load);
    std::sort(br.begin(), br.end());
    br.erase(std::remove_if(br.begin(), br.end(), [&](double b) { return !(b > 0 && b < tooth.height); }),
             br.end());
    return density * face_width * analytical::integrate(f, 0.0, tooth.height, 1e-10, 0.0, br);
  }

  ToothInertiaCurves tooth_inertia_curves(const geometry::GearPair &pair, const analytical::Material &material,
                                          double density, ToothMassWeighting weighting, int path_points,
                                          int samples)
  {
    require_range("tooth inertia path points", path_points, 3, 100001);
    require_range("tooth inertia samples", samples, 8, 1000000);
    if (path_points % 2 == 0)
      ++path_points; // Simpson needs an odd count
    const analytical::PairCompliance pc = analytical::pair_compliance(pair, material, material);
    const analytical::PairLine &L = pc.line();
    const analytical::InvoluteTooth t1 = analytical::involute_tooth(pair.gear(1));
    const analytical::InvoluteTooth t2 = analytical::involute_tooth(pair.gear(2));
    const double b = std::min(pair.gear(1).parameters().face_width, pair.gear(2).parameters().face_width);

    ToothInertiaCurves c;
    c.period = 2 * units::pi / pair.gear(1).parameters().teeth;
    c.theta_A = (L.g_A - L.g_C) / L.rb1;
    c.tooth_mass1 = tooth_mass(t1.beam, density, b);
    c.tooth_mass2 = tooth_mass(t2.beam, density, b);

    struct AtG
    {
      double r1, r2, s1, s2, y1, y2, m1, m2;
    };
    auto at = [&](double g) {
      AtG a;
      a.r1 = std::min(std::hypot(L.rb1, g), t1.r_tip);
      a.r2 = std::min(std::hypot(L.rb2, L.length - g), t2.r_tip);
      const analytical::PairCompliance::Parts p = pc.parts(g, 1.0);
      a.s1 = p.foundation1 / (p.foundation1 + p.beam1);
      a.s2 = p.foundation2 / (p.foundation2 + p.beam2);
      a.y1 = std::min(analytical::involute_load(t1, a.r1).y_contact, t1.beam.height);
      a.y2 = std::min(analytical::involute_load(t2, a.r2).y_contact, t2.beam.height);
      a.m1 = equivalent_tooth_mass(t1.beam, a.y1, a.s1, density, b, weighting);
      a.m2 = equivalent_tooth_mass(t2.beam, a.y2, a.s2, density, b, weighting);
      return a;
    };

    // Along the path A..E, and the means (1/p_b) int_A^E m r^2 dg (composite Simpson).
    const double h = (L.g_E - L.g_A) / (path_points - 1);
    double I1 = 0, I2 = 0;
    for (int i = 0; i < path_points; ++i)
      {
        const double g = L.g_A + h * i;
        const AtG a = at(g);
        c.g.push_back(g);
        c.r1.push_back(a.r1), c.r2.push_back(a.r2);
        c.share1.push_back(a.s1), c.share2.push_back(a.s2);
        c.y1.push_back(a.y1), c.y2.push_back(a.y2);
        c.m1.push_back(a.m1), c.m2.push_back(a.m2);
        const double w = (i == 0 || i == path_points - 1) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        I1 += w * a.m1 * a.r1 * a.r1, I2 += w * a.m2 * a.r2 * a.r2;
      }
    c.mean1 = I1 * h / 3 / L.base_pitch;
    c.mean2 = I2 * h / 3 / L.base_pitch;

    // J_t(theta) over one period from A: the pairs in contact at g = g_C + rb1 theta + j p_b
    // inside [g_A, g_E) (the rule of analytical::contact_positions).
    for (int k = 0; k < samples; ++k)
      {
        const double th = c.theta_A + c.period * k / samples;
        const double g0 = L.g_C + L.rb1 * th;
        double J1 = 0, J2 = 0;
        const int jlo = static_cast<int>(std::floor((L.g_A - g0) / L.base_pitch)) - 1;
        for (int j = jlo; j <= jlo + 4; ++j)
          {
            const double g = g0 + j * L.base_pitch;
            if (g < L.g_A - 1e-15 || g >= L.g_E)
              continue;
            const AtG a = at(std::max(g, L.g_A));
            J1 += a.m1 * a.r1 * a.r1, J2 += a.m2 * a.r2 * a.r2;
          }
        c.theta.push_back(th);
        c.J1.push_back(J1), c.J2.push_back(J2);
      }
    return c;
  }

  // ---------------------------------------------------------------- PeriodicInertia
  PeriodicInertia::PeriodicInertia(double theta0, double period, std::vector<double> values)
    : theta0_(theta0)
    , period_(period)
    , v_(std::move(values))
  {
    require_greater("inertia period", period, 0.0, "rad");
    require_range("inertia nodes", static_cast<int>(v_.size()), 4, 100000000);
    for (const double v : v_)
      if (!(v > 0 && std::isfinite(v)))
        throw InputError("inertia node value", to_string_g(v) + " kg m^2", "> 0 and finite");
    const std::size_t n = v_.size();
    h_ = period / n;
    // Fritsch-Carlson slopes on the periodic node sequence.
    std::vector<double> delta(n);
    for (std::size_t i = 0; i < n; ++i)
      delta[i] = (v_[(i + 1) % n] - v_[i]) / h_;
    d_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      {
        const double a = delta[(i + n - 1) % n], b = delta[i];
        d_[i] = (a * b <= 0) ? 0.0 : 2.0 / (1.0 / a + 1.0 / b); // harmonic mean (monotone)
      }
  }

  double PeriodicInertia::locate(double theta, std::size_t &i) const
  {
    double s = (theta - theta0_) / period_;
    s -= std::floor(s);
    const double x = s * v_.size();
    i = std::min(static_cast<std::size_t>(x), v_.size() - 1);
    return x - i;
  }

  double PeriodicInertia::value(double theta) const
  {
    std::size_t i;
    const double u = locate(theta, i);
    const std::size_t j = (i + 1) % v_.size();
    const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
    const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
    return h00 * v_[i] + h10 * h_ * d_[i] + h01 * v_[j] + h11 * h_ * d_[j];
  }

  double PeriodicInertia::derivative(double theta) const
  {
    std::size_t i;
    const double u = locate(theta, i);
    const std::size_t j = (i + 1) % v_.size();
    const double d00 = 6 * u * u - 6 * u, d10 = 3 * u * u - 4 * u + 1;
    const double d01 = -6 * u * u + 6 * u, d11 = 3 * u * u - 2 * u;
    return (d00 * v_[i] + d01 * v_[j]) / h_ + d10 * d_[i] + d11 * d_[j];
  }

  double PeriodicInertia::mean() const
  {
    // Cell integrals h (v_i + v_j)/2 + h^2 (d_i - d_j)/12: the slope terms cancel over a period.
    double s = 0;
    for (const double v : v_)
      s += v;
    return s / v_.size();
  }
} // namespace gearfem::dynamics
