#include "dynamics/analysis.h"
#include "base/units.h"

#include "base/errors.h"
#include "base/progress.h"

#include <Eigen/Dense>
#include <fftw3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <sstream>
#include <thread>

namespace gearfem::dynamics
{
  void ResponseOptions::check() const
  {
    // Bounds of the work of one speed: 1e5 mesh periods settle any damping ratio >= 1e-4
    // (a transient decays as exp(-2 pi zeta n)); 1e4 samples resolve any tooth-pass harmonic
    // that matters; the record holds at most 1e7 samples (80 MB per channel).
    require_range("Dynamics/Analysis/Periods per speed", max_periods, 1, 100000);
    require_range("Dynamics/Analysis/Recorded periods", record_periods, 1, 100000);
    if (record_periods > max_periods)
      throw InputError("Dynamics/Analysis/Recorded periods", std::to_string(record_periods),
                       "<= Periods per speed (" + std::to_string(max_periods) + ")");
    require_range("Dynamics/Analysis/Samples per period", samples_per_period, 4, 10000);
    if (double(record_periods) * samples_per_period > 1e7)
      throw InputError("Dynamics/Analysis/Recorded periods", std::to_string(record_periods) + " (x Samples per period " +
                         std::to_string(samples_per_period) + ")",
                       "a record of at most 1e7 samples");
    if (steps_per_period > 1000000)
      throw InputError("Dynamics/Integrator/Steps per period", std::to_string(steps_per_period), "0 to 1e6");
    if (steps_per_period < 0)
      throw InputError("Dynamics/Analysis/Steps per period", std::to_string(steps_per_period),
                       ">= 0 (0: use Integrator/Time step)");
    require_greater("Dynamics/Analysis/Steady-state tolerance", steady_tolerance, 0.0);
  }

  namespace
  {
    /// Smallest p in 1..4 such that the last `window` Poincare samples repeat with period p.
    int periodicity(const std::vector<double> &pd, const std::vector<double> &pr, double scale_d,
                    double scale_r, double tol)
    {
      const int window = 3;
      for (int p = 1; p <= 4; ++p)
        {
          const int n = static_cast<int>(pd.size());
          if (n < p + window + 1)
            return 0;
          bool ok = true;
          for (int k = n - window; k < n && ok; ++k)
            ok = std::abs(pd[k] - pd[k - p]) <= tol * scale_d &&
                 std::abs(pr[k] - pr[k - p]) <= tol * scale_r;
          if (ok && p > 1)
            {
              // A period-p response (p > 1) must differ visibly from period 1; otherwise a
              // decaying transient aliased by the sampling could pass as a subharmonic.
              double d1 = 0;
              for (int k = n - p; k < n; ++k)
                d1 = std::max(d1, std::abs(pd[k] - pd[k - 1]) / scale_d);
              ok = d1 >= 1e-3;
            }
          if (ok)
            return p;
        }
      return 0;
    }
  } // namespace

  Response run_response(MeshModel &model, const IntegratorOptions &integrator_options,
                        const ResponseOptions &o, State &x, double &t)
  {
    o.check();
    IntegratorOptions io = integrator_options.with_deadline();
    const double T = model.mesh_period_time();
    const bool fixed = !(io.method == Method::dopri5 && io.adaptive);
    if (fixed && o.steps_per_period > 0)
      io.step = T / o.steps_per_period;
    else if (!fixed)
      io.step = std::min(io.step, T / 8);
    Integrator integ(io);
    model.update_mode(t, x);

    Response r;
    r.pinion_speed = model.pinion_speed();
    r.mesh_frequency = 1.0 / T;
    const long oor0 = model.law().out_of_range_count();
    const double t_start = t;
    const double Fs = model.static_force();
    const double kbar = model.law().mean_stiffness();
    const double scale_d0 = std::abs(Fs / kbar) > 0 ? std::abs(Fs / kbar) : 1.0;
    const bool conservative = model.conservative();
    const State x_start = x;
    const double E_start = conservative ? model.kinetic_energy(t, x) + model.elastic_energy(t, x) : 0.0;

    // Transient: one period at a time, Poincare samples, steady-state check.
    int k = 0, p = 0;
    double amp = 0; // peak-to-peak over the last period
    const int transient_limit = o.max_periods - o.record_periods;
    while (k < transient_limit)
      {
        double dmin = 1e300, dmax = -1e300;
        const int n_sub = 8;
        for (int j = 1; j <= n_sub; ++j)
          {
            integ.advance(model, x, t, t_start + (k + double(j) / n_sub) * T);
            const double d = model.compression(t, x);
            dmin = std::min(dmin, d), dmax = std::max(dmax, d);
          }
        ++k;
        amp = dmax - dmin;
        r.poincare_delta.push_back(model.compression(t, x));
        r.poincare_rate.push_back(model.compression_rate(t, x));
        if (k >= o.min_transient_periods)
          {
            const double sd = std::max(scale_d0, amp);
            p = periodicity(r.poincare_delta, r.poincare_rate, sd, sd * 2 * units::pi / T,
                            o.steady_tolerance);
            if (p > 0)
              {
                r.settled = true;
                break;
              }
          }
      }
    r.transient_periods = k;
    r.period_multiplicity = p;

    // Record.
    int nrec = o.record_periods;
    if (p > 1)
      nrec = ((nrec + p - 1) / p) * p;
    const int ns = o.samples_per_period;
    const double dt = T / ns;
    const double t_rec = t;
    double sum = 0, sum2 = 0, dmin = 1e300, dmax = -1e300, fmax = -1e300;
    double amin[2] = {1e300, 1e300}, amax[2] = {-1e300, -1e300};
    long n_loss = 0, n_back = 0, n = 0;
    bool any_back = false, any_loss = false;
    long events = 0;
    auto on_event = [&](const Event &e, const State &) {
      if (e.which <= 1)
        ++events;
    };
    for (int q = 0; q < nrec; ++q)
      {
        for (int j = 1; j <= ns; ++j)
          {
            integ.advance(model, x, t, t_rec + (q * ns + j) * dt, on_event);
            const double d = model.compression(t, x);
            const double F = model.mesh_force(t, x);
            const int s = model.contact_state(t, x);
            sum += d, sum2 += d * d, ++n;
            dmin = std::min(dmin, d), dmax = std::max(dmax, d), fmax = std::max(fmax, F);
            const std::vector<double> a = model.angle_deviations(t, x);
            for (std::size_t i = 0; i < a.size() && i < 2; ++i)
              amin[i] = std::min(amin[i], a[i]), amax[i] = std::max(amax[i], a[i]);
            if (s != 1)
              ++n_loss, any_loss = true;
            if (s == -1)
              ++n_back, any_back = true;
            if (o.keep_history)
              {
                r.t.push_back(t);
                r.delta.push_back(d);
                r.rate.push_back(model.compression_rate(t, x));
                r.force.push_back(F);
                r.state.push_back(s);
                if (a.size() == 2)
                  r.angle1.push_back(a[0]), r.angle2.push_back(a[1]);
              }
          }
        r.poincare_delta.push_back(model.compression(t, x));
        r.poincare_rate.push_back(model.compression_rate(t, x));
      }
    r.mean = sum / n;
    r.rms = std::sqrt(std::max(0.0, sum2 / n - r.mean * r.mean));
    r.peak_to_peak = dmax - dmin;
    r.dynamic_factor = Fs != 0 ? fmax / Fs : 0.0;
    r.contact_loss_fraction = double(n_loss) / n;
    r.back_contact_fraction = double(n_back) / n;
    r.impact_regime = any_back ? 2 : (any_loss || events > 0 ? 1 : 0);
    r.contact_events = events;
    r.out_of_range = model.law().out_of_range_count() - oor0;
    r.steps = integ.stats().accepted;
    r.rhs_evaluations = integ.stats().rhs_evaluations;
    if (amax[0] >= amin[0])
      r.angle_amplitude1 = 0.5 * (amax[0] - amin[0]), r.angle_amplitude2 = 0.5 * (amax[1] - amin[1]);
    if (conservative)
      {
        const double E = model.kinetic_energy(t, x) + model.elastic_energy(t, x);
        const double K0 = model.kinetic_energy(t_start, x_start);
        r.energy_balance = (E - E_start - model.torque_work(x_start, x)) / (K0 > 0 ? K0 : 1.0);
      }
    if (!std::isfinite(r.rms) || !std::isfinite(r.dynamic_factor))
      throw SolverError("non-finite response at pinion speed " + to_string_g(r.pinion_speed) +
                        " rad/s");
    return r;
  }

  std::vector<SweepPoint> sweep(const MeshModel &prototype, const IntegratorOptions &integrator,
                                const ResponseOptions &options, const std::vector<double> &speeds,
                                int direction, const std::function<void(std::size_t)> &progress)
  {
    auto model = prototype.clone();
    std::vector<SweepPoint> out;
    if (speeds.empty())
      return out;
    model->set_pinion_speed(speeds.front());
    State x = model->initial_state();
    double t = 0;
    for (std::size_t i = 0; i < speeds.size(); ++i)
      {
        x = model->continue_at_speed(t, x, speeds[i]);
        t = 0;
        SweepPoint sp;
        sp.direction = direction;
        sp.response = run_response(*model, integrator, options, x, t);
        out.push_back(std::move(sp));
        if (progress)
          progress(i + 1);
      }
    return out;
  }

  void run_parallel(const std::vector<std::function<void()>> &tasks, int threads)
  {
    threads = std::max(1, threads);
    std::atomic<std::size_t> next{0};
    std::vector<std::exception_ptr> errors(tasks.size());
    auto worker = [&]() {
      for (std::size_t i; (i = next.fetch_add(1)) < tasks.size();)
        try
          {
            tasks[i]();
          }
        catch (...)
          {
            errors[i] = std::current_exception();
          }
    };
    std::vector<std::thread> pool;
    for (int k = 1; k < std::min<int>(threads, tasks.size()); ++k)
      pool.emplace_back(worker);
    worker();
    for (auto &th : pool)
      th.join();
    for (auto &e : errors)
      if (e)
        std::rethrow_exception(e);
  }

  std::vector<SweepPoint> sweep_up_down(const MeshModel &prototype,
                                        const IntegratorOptions &integrator,
                                        const ResponseOptions &options, double w_min,
                                        double w_max, int n, std::ostream *progress_out,
                                        int threads)
  {
    if (!(w_min < w_max))
      throw InputError("Dynamics/Analysis/Speed range", "[" + to_string_g(w_min) + ", " +
                                                   to_string_g(w_max) + "]",
                       "minimum < maximum");
    require_greater("Dynamics/Analysis/Minimum speed", w_min, 0.0);
    require_greater("Dynamics/Analysis/Number of speeds", n, 1.0);
    options.check();
    integrator.check();
    std::vector<double> up(n), down(n);
    for (int i = 0; i < n; ++i)
      up[i] = w_min + (w_max - w_min) * i / (n - 1);
    std::reverse_copy(up.begin(), up.end(), down.begin());
    std::vector<SweepPoint> a, b;
    Progress bar(progress_out, 2 * n, "sweep");
    std::mutex m;
    std::size_t done_a = 0, done_b = 0;
    const std::size_t every = std::max<std::size_t>(1, n / 10);
    auto report = [&](std::size_t &mine, std::size_t i) {
      std::lock_guard<std::mutex> lock(m);
      mine = i;
      const std::size_t done = done_a + done_b;
      if (done % every == 0 || done == std::size_t(2 * n))
        bar.step(done);
    };
    const IntegratorOptions io = integrator.with_deadline(); // one wall-time cap for the whole sweep
    run_parallel({[&]() { a = sweep(prototype, io, options, up, 1,
                                    [&](std::size_t i) { report(done_a, i); }); },
                  [&]() { b = sweep(prototype, io, options, down, -1,
                                    [&](std::size_t i) { report(done_b, i); }); }},
                 threads);
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }

  Spectrum amplitude_spectrum(const std::vector<double> &samples, double dt)
  {
    static std::mutex plan_mutex; // FFTW planning is not thread-safe
    const int N = static_cast<int>(samples.size());
    Spectrum s;
    if (N < 2)
      return s;
    double mean = 0;
    for (double v : samples)
      mean += v;
    mean /= N;
    std::vector<double> in(N);
    for (int i = 0; i < N; ++i)
      in[i] = samples[i] - mean;
    std::vector<fftw_complex> out(N / 2 + 1);
    fftw_plan plan;
    {
      std::lock_guard<std::mutex> lock(plan_mutex);
      plan = fftw_plan_dft_r2c_1d(N, in.data(), out.data(), FFTW_ESTIMATE);
    }
    fftw_execute(plan);
    {
      std::lock_guard<std::mutex> lock(plan_mutex);
      fftw_destroy_plan(plan);
    }
    for (int k = 0; k <= N / 2; ++k)
      {
        const double a = std::hypot(out[k][0], out[k][1]) / N;
        s.frequency.push_back(k / (N * dt));
        s.amplitude.push_back((k == 0 || 2 * k == N) ? a : 2 * a);
      }
    return s;
  }

  double HarmonicBalance::value(double t) const
  {
    double v = 0;
    for (int n = -N; n <= N; ++n)
      v += (D[n + N] * std::exp(std::complex<double>(0, n * omega * t))).real();
    return v;
  }

  double HarmonicBalance::rms() const
  {
    double s = 0;
    for (int n = 1; n <= N; ++n)
      s += 2 * std::norm(D[n + N]);
    return std::sqrt(s);
  }

  double HarmonicBalance::minimum(int samples) const
  {
    double m = 1e300;
    for (int i = 0; i < samples; ++i)
      m = std::min(m, value(2 * units::pi / omega * i / samples));
    return m;
  }

  HarmonicBalance harmonic_balance(const FourierStiffnessLaw &law, double mass, double c,
                                   double F0, double W, int N)
  {
    using C = std::complex<double>;
    HarmonicBalance hb;
    hb.N = N;
    const int z = static_cast<int>(std::lround(2 * units::pi / law.period()));
    hb.omega = z * W;
    const double kbar = law.mean_stiffness();
    const auto &a = law.cos_coefficients();
    const auto &b = law.sin_coefficients();
    auto K = [&](int j) -> C {
      if (j == 0)
        return kbar;
      const int aj = std::abs(j);
      const double ca = aj <= int(a.size()) ? a[aj - 1] : 0.0;
      const double cb = aj <= int(b.size()) ? b[aj - 1] : 0.0;
      return j > 0 ? kbar * C(ca, -cb) / 2.0 : kbar * C(ca, cb) / 2.0;
    };
    const int M = 2 * N + 1;
    Eigen::MatrixXcd A = Eigen::MatrixXcd::Zero(M, M);
    Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(M);
    for (int n = -N; n <= N; ++n)
      {
        const double w = n * hb.omega;
        A(n + N, n + N) += C(-mass * w * w, c * w);
        for (int m = -N; m <= N; ++m)
          A(n + N, m + N) += K(n - m);
      }
    rhs(N) = F0;
    const Eigen::VectorXcd D = A.partialPivLu().solve(rhs);
    hb.D.assign(D.data(), D.data() + M);
    return hb;
  }
} // namespace gearfem::dynamics
