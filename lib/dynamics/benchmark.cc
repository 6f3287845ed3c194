#include "dynamics/benchmark.h"
#include "base/units.h"

#include "dynamics/analysis.h"
#include "dynamics/mesh_force.h"
#include "dynamics/models.h"
#include "dynamics/pair_data.h"

#include <chrono>
#include <cmath>
#include <iomanip>

namespace gearfem::dynamics
{
  namespace
  {
    double seconds_since(std::chrono::steady_clock::time_point t0)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }

    /// Parker pair (50/50, m 3, b 20 mm) with a synthetic torque table T(theta, delta) on a
    /// 64 x 16 grid: k(theta) from a Fourier series around ISO c_gamma_alpha and a mild
    /// stiffening in delta, the shape the calibration tables will have.
    DteModel parker_table_model(double torque)
    {
      const PairData pair = standard_pair(50, 50, 3e-3, 20 * units::deg, 1.0, 0.5, 0.5, 0.0);
      const double b = 0.02, ks = 14e9 * b, kbar = ks * (0.75 * pair.contact_ratio + 0.25);
      const FourierStiffnessLaw k(kbar, 50, {-0.12, 0.04, -0.02});
      MeshTable t;
      t.period = 2 * units::pi / 50;
      t.base_radius = pair.r_b1;
      const int nt = 64, nd = 16;
      for (int i = 0; i < nt; ++i)
        t.theta.push_back(t.period * i / nt);
      for (int j = 0; j < nd; ++j)
        t.second.push_back(60e-6 * j / (nd - 1));
      for (int i = 0; i < nt; ++i)
        for (int j = 0; j < nd; ++j)
          t.values.push_back(pair.r_b1 * k.force(t.theta[i], t.second[j], 0) *
                             (1 + 0.1 * t.second[j] / 60e-6));
      const double rho = 7850, r = 0.075;
      const double J = 0.5 * units::pi * rho * b * std::pow(r, 4);
      DteModel::Parameters p;
      p.mass = J * J / (J * pair.r_b1 * pair.r_b1 + J * pair.r_b2 * pair.r_b2);
      p.static_force = torque / pair.r_b1;
      p.zeta = 0.02;
      p.speed = 3000 * 2 * units::pi / 50;
      ContactLogic c;
      c.backlash = pair.backlash > 0 ? pair.backlash : 100e-6;
      return DteModel(std::make_unique<TableLaw>(t, ThetaInterpolation::linear), c, p);
    }
  } // namespace

  void benchmark(std::ostream &out, double scale)
  {
    out << "== dynamics benchmark" << (scale < 1 ? " (scaled runs, extrapolated)" : "") << "\n";
    DteModel model = parker_table_model(200);
    // 1. RHS evaluations per second.
    {
      State x = model.initial_state(), dx(2);
      const long n = std::max<long>(100000, static_cast<long>(2e7 * scale));
      double acc = 0;
      const auto t0 = std::chrono::steady_clock::now();
      for (long i = 0; i < n; ++i)
        {
          x[0] = 1e-5 * (1.0 + 1e-3 * (i & 1023));
          model(x, dx, 1e-7 * i);
          acc += dx[1];
        }
      const double dt = seconds_since(t0);
      out << "1-DOF table model RHS evaluations: " << std::scientific << std::setprecision(3)
          << n / dt << " per second (target >= 5e6)" << (acc == 0.12345 ? " " : "") << "\n";
    }
    IntegratorOptions io;
    io.method = Method::rk4;
    ResponseOptions ro;
    ro.max_periods = 300;
    ro.record_periods = 32;
    ro.steps_per_period = 128;
    ro.steady_tolerance = 1e-300; // never "settled": always integrate all 300 periods
    // 2. One speed point of 300 mesh periods.
    {
      DteModel m = parker_table_model(200);
      State x = m.initial_state();
      double t = 0;
      const auto t0 = std::chrono::steady_clock::now();
      const Response r = run_response(m, io, ro, x, t);
      const double dt = seconds_since(t0);
      out << "one speed point, 300 mesh periods (RK4, 128 steps/period, table force): "
          << std::fixed << std::setprecision(4) << dt << " s, " << std::scientific
          << std::setprecision(3) << r.steps / dt << " steps/s, " << r.rhs_evaluations / dt
          << " RHS/s, " << r.contact_events << " contact events in the record\n";
    }
    // 3. Full up/down sweep, 2 x 200 speeds x 300 periods, two threads.
    {
      const int n = std::max(4, static_cast<int>(std::lround(200 * scale)));
      const double w0 = 1000 * 2 * units::pi / 50, w1 = 5000 * 2 * units::pi / 50; // f_mesh 1-5 kHz
      const auto t0 = std::chrono::steady_clock::now();
      const auto pts = sweep_up_down(model, io, ro, w0, w1, n, nullptr, 2);
      const double dt = seconds_since(t0);
      long loss = 0;
      for (const auto &p : pts)
        loss += p.response.contact_loss_fraction > 0;
      out << "up/down sweep 2 x " << n << " speeds x 300 periods (2 threads): " << std::fixed
          << std::setprecision(3) << dt << " s";
      if (n != 200)
        out << " (extrapolated to 2 x 200: " << dt * 200.0 / n << " s)";
      out << " (target <= 10 s); " << loss << " points with contact loss\n";
    }
  }
} // namespace gearfem::dynamics
