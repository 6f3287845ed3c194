#include "dynamics/ode.h"

#include "base/errors.h"

#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gearfem::dynamics
{
  namespace
  {
    // Dormand-Prince 5(4) tableau and Hairer's dense-output coefficients (HNW 1993, II.5
    // table 5.2 and II.6 eq. 6.12; the same as in Hairer's dopri5.f).
    constexpr double a21 = 1.0 / 5.0;
    constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
    constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
    constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                     a54 = -212.0 / 729.0;
    constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                     a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
    constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0,
                     a75 = -2187.0 / 6784.0, a76 = 11.0 / 84.0;
    constexpr double c2 = 0.2, c3 = 0.3, c4 = 0.8, c5 = 8.0 / 9.0;
    constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                     e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
    constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                     d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                     d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

    // Alexander (1977) 3-stage SDIRK, order 3, L-stable.
    constexpr double sg = 0.4358665215084590;
    const double sb1 = -(6.0 * sg * sg - 16.0 * sg + 1.0) / 4.0;
    const double sb2 = (6.0 * sg * sg - 20.0 * sg + 5.0) / 4.0;

    int sign_of(double v) { return (v > 0) - (v < 0); }
  } // namespace

  Method method_from_string(const std::string &name)
  {
    if (name == "RK4")
      return Method::rk4;
    if (name == "DOPRI5")
      return Method::dopri5;
    if (name == "SDIRK3")
      return Method::sdirk3;
    throw InputError("Dynamics/Integrator/Method", name, "{RK4, DOPRI5, SDIRK3}");
  }

  std::string to_string(Method m)
  {
    switch (m)
      {
        case Method::rk4:
          return "RK4";
        case Method::dopri5:
          return "DOPRI5";
        default:
          return "SDIRK3";
      }
  }

  int order(Method m) { return m == Method::rk4 ? 4 : (m == Method::dopri5 ? 5 : 3); }

  void IntegratorOptions::check() const
  {
    require_greater("Dynamics/Integrator/Time step", step, 0.0);
    if (method == Method::dopri5 && adaptive)
      {
        // Below 1e-14 the error estimate is round-off; above 1e-2 (relative) or 1e-3 (absolute,
        // in state units: the deflections are micrometres) the steps grow until the contact
        // events chatter and the run no longer represents the mesh.
        require_range("Dynamics/Integrator/Relative tolerance", rtol, 1e-14, 1e-2);
        if (!(atol > 0 && atol <= max_absolute_tolerance))
          throw InputError("Dynamics/Integrator/Absolute tolerance", to_string_g(atol),
                           "(0, " + to_string_g(max_absolute_tolerance) + "]");
      }
    if (!(event_tolerance > 0 && event_tolerance <= 1e-3))
      throw InputError("Dynamics/Integrator/Event tolerance", to_string_g(event_tolerance), "(0, 0.001]");
    if (max_step < 0)
      throw InputError("Dynamics/Integrator/Maximum step", to_string_g(max_step), ">= 0 (0: none)");
    if (!(wall_limit >= 0 && wall_limit <= 1e7))
      throw InputError("Dynamics/Integrator/Wall time limit", to_string_g(wall_limit) + " s",
                       "0 (none) to 1e7 s");
  }

  double monotonic_seconds()
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }

  IntegratorOptions IntegratorOptions::with_deadline() const
  {
    IntegratorOptions o = *this;
    if (o.deadline == 0 && o.wall_limit > 0)
      o.deadline = monotonic_seconds() + o.wall_limit;
    return o;
  }

  Integrator::Integrator(const IntegratorOptions &options)
    : opt_(options)
    , h_(options.step)
  {
    opt_.check();
  }

  void Integrator::rk4_step(const HybridSystem &s, double t, const State &x, double h, State &out)
  {
    State k1(x.size()), k2(x.size()), k3(x.size()), k4(x.size());
    s(x, k1, t);
    s(x + 0.5 * h * k1, k2, t + 0.5 * h);
    s(x + 0.5 * h * k2, k3, t + 0.5 * h);
    s(x + h * k3, k4, t + h);
    stats_.rhs_evaluations += 4;
    out = x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }

  void Integrator::sdirk3_step(const HybridSystem &s, double t, const State &x, double h,
                               State &out)
  {
    const int n = x.size();
    // Finite-difference Jacobian at the step start, reused by all stages (simplified Newton).
    Eigen::MatrixXd J(n, n);
    State f0(n), f1(n);
    s(x, f0, t);
    for (int j = 0; j < n; ++j)
      {
        State xp = x;
        const double d = 1e-7 * std::max(1.0, std::abs(x[j]));
        xp[j] += d;
        s(xp, f1, t);
        J.col(j) = (f1 - f0) / d;
      }
    stats_.rhs_evaluations += n + 1;
    const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(n, n) - h * sg * J;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(M);
    const double c[3] = {sg, 0.5 * (1.0 + sg), 1.0};
    const double A[3][3] = {{sg, 0, 0}, {0.5 * (1.0 - sg), sg, 0}, {sb1, sb2, sg}};
    State K[3];
    for (int i = 0; i < 3; ++i)
      {
        State base = x;
        for (int j = 0; j < i; ++j)
          base += h * A[i][j] * K[j];
        State y = base + h * sg * f0; // predictor
        State fy(n);
        for (int it = 0; it < 50; ++it)
          {
            s(y, fy, t + c[i] * h);
            ++stats_.rhs_evaluations;
            const Eigen::VectorXd r = y - base - h * sg * fy;
            const Eigen::VectorXd dy = lu.solve(-r);
            y += dy;
            if (dy.norm() <= 1e-14 * (1.0 + y.norm()))
              break;
          }
        s(y, fy, t + c[i] * h);
        ++stats_.rhs_evaluations;
        K[i] = fy;
      }
    out = x + h * (sb1 * K[0] + sb2 * K[1] + sg * K[2]);
  }

  bool Integrator::try_step(const HybridSystem &s, double t, const State &x, double h,
                            State &x_new, double &h_new)
  {
    h_new = h;
    if (opt_.method == Method::rk4)
      {
        rk4_step(s, t, x, h, x_new);
        return true;
      }
    if (opt_.method == Method::sdirk3)
      {
        sdirk3_step(s, t, x, h, x_new);
        return true;
      }
    const int n = x.size();
    for (auto &k : k_)
      k.resize(n);
    s(x, k_[0], t);
    s(x + h * a21 * k_[0], k_[1], t + c2 * h);
    s(x + h * (a31 * k_[0] + a32 * k_[1]), k_[2], t + c3 * h);
    s(x + h * (a41 * k_[0] + a42 * k_[1] + a43 * k_[2]), k_[3], t + c4 * h);
    s(x + h * (a51 * k_[0] + a52 * k_[1] + a53 * k_[2] + a54 * k_[3]), k_[4], t + c5 * h);
    s(x + h * (a61 * k_[0] + a62 * k_[1] + a63 * k_[2] + a64 * k_[3] + a65 * k_[4]), k_[5],
      t + h);
    x_new = x + h * (a71 * k_[0] + a73 * k_[2] + a74 * k_[3] + a75 * k_[4] + a76 * k_[5]);
    s(x_new, k_[6], t + h);
    stats_.rhs_evaluations += 7;
    have_k_ = true;
    if (!opt_.adaptive)
      return true;
    const State e =
      h * (e1 * k_[0] + e3 * k_[2] + e4 * k_[3] + e5 * k_[4] + e6 * k_[5] + e7 * k_[6]);
    double err = 0;
    for (int i = 0; i < n; ++i)
      {
        const double sc = opt_.atol + opt_.rtol * std::max(std::abs(x[i]), std::abs(x_new[i]));
        err += (e[i] / sc) * (e[i] / sc);
      }
    err = std::sqrt(err / n);
    if (!std::isfinite(err))
      {
        h_new = 0.1 * h;
        return false;
      }
    const double fac = std::clamp(0.9 * std::pow(std::max(err, 1e-16), -0.2), 0.2, 10.0);
    h_new = h * fac;
    if (opt_.max_step > 0)
      h_new = std::min(h_new, opt_.max_step);
    return err <= 1.0;
  }

  void Integrator::state_at(const HybridSystem &s, double t0, const State &x0, double h,
                            double tau, State &out)
  {
    if (opt_.method == Method::dopri5 && have_k_)
      {
        // Dense output of order 4 from the stages of the last step [t0, t0 + h].
        const double th = tau / h, th1 = 1.0 - th;
        const State x1 = x0 + h * (a71 * k_[0] + a73 * k_[2] + a74 * k_[3] + a75 * k_[4] +
                                   a76 * k_[5]);
        const State ydiff = x1 - x0;
        const State bspl = h * k_[0] - ydiff;
        const State r4 = ydiff - h * k_[6] - bspl;
        const State r5 =
          h * (d1 * k_[0] + d3 * k_[2] + d4 * k_[3] + d5 * k_[4] + d6 * k_[5] + d7 * k_[6]);
        out = x0 + th * (ydiff + th1 * (bspl + th * (r4 + th1 * r5)));
        return;
      }
    if (opt_.method == Method::rk4)
      rk4_step(s, t0, x0, tau, out);
    else
      sdirk3_step(s, t0, x0, tau, out);
  }

  void Integrator::advance(HybridSystem &system, State &x, double &t, double t_end,
                           const std::function<void(const Event &, const State &)> &on_event)
  {
    const int ns = system.n_switches();
    std::vector<double> g0(std::max(ns, 1)), g1(std::max(ns, 1)), gm(std::max(ns, 1));
    const bool fixed = !(opt_.method == Method::dopri5 && opt_.adaptive);
    State x_new(x.size()), x_mid(x.size());
    int guard = 0;
    long steps = 0, stalled = 0;
    const double t_start = t, tiny = 1e-8 * (t_end - t);
    auto stop = [&](const std::string &why) {
      throw SolverError(why + " between t = " + to_string_g(t_start) + " and the output time " + to_string_g(t_end) +
                        " (now at t = " + to_string_g(t) + "; contact events chattering or a vanishing step: "
                        "tighten Integrator/Relative and Absolute tolerance, or raise Steps per period)");
    };
    while (t_end - t > 1e-14 * std::max(1.0, std::abs(t_end)))
      {
        if (++steps > max_steps_per_advance)
          stop("more than " + std::to_string(max_steps_per_advance) + " integration steps");
        if (opt_.deadline > 0 && steps % 1024 == 0 && monotonic_seconds() > opt_.deadline)
          throw SolverError("the run reached its wall-time limit, Dynamics/Integrator/Wall time limit = " +
                            to_string_g(opt_.wall_limit) + " s, at t = " + to_string_g(t) +
                            " (raise the limit, or shorten the run: Periods per speed, Number of speeds)");
        if (stalled > max_stalled_steps)
          stop(std::to_string(max_stalled_steps) + " consecutive steps each shorter than 1e-8 of the interval");
        const double t_before = t;
        double h = fixed ? opt_.step : h_;
        const bool last = h >= t_end - t;
        if (last)
          h = t_end - t;
        double h_next = h;
        if (!try_step(system, t, x, h, x_new, h_next))
          {
            ++stats_.rejected;
            h_ = h_next;
            if (++guard > 100000 || h_ < 1e-14 * std::max(1.0, std::abs(t)))
              throw SolverError("adaptive step size underflow at t = " + to_string_g(t) +
                                " (tolerance too tight or state not finite)");
            continue;
          }
        guard = 0;
        if (!x_new.allFinite())
          throw SolverError("the state became non-finite at t = " + to_string_g(t + h) +
                            " (step too large for this stiffness?)");
        // Event detection with the frozen mode.
        const int n_sw = system.n_switches();
        double tau_event = -1;
        int which = -1;
        if (opt_.locate_events && n_sw > 0)
          {
            g0.resize(n_sw), g1.resize(n_sw), gm.resize(n_sw);
            system.switching_functions(t, x, g0.data());
            system.switching_functions(t + h, x_new, g1.data());
            for (int i = 0; i < n_sw; ++i)
              {
                if (sign_of(g0[i]) * sign_of(g1[i]) >= 0 && !(g0[i] != 0 && g1[i] == 0))
                  continue;
                // Illinois (modified regula falsi) on the step interpolant.
                double lo = 0, hi = h, flo = g0[i], fhi = g1[i];
                int side = 0;
                for (int it = 0; it < 200 && hi - lo > opt_.event_tolerance; ++it)
                  {
                    double c = (it % 8 == 7) ? 0.5 * (lo + hi) :
                                               hi - fhi * (hi - lo) / (fhi - flo);
                    const double m = 0.25 * opt_.event_tolerance;
                    c = std::clamp(c, lo + m, hi - m);
                    state_at(system, t, x, h, c, x_mid);
                    system.switching_functions(t + c, x_mid, gm.data());
                    const double fc = gm[i];
                    if (sign_of(fc) * sign_of(flo) > 0 || fc == 0)
                      {
                        lo = c, flo = fc;
                        if (side == -1)
                          fhi *= 0.5;
                        side = -1;
                      }
                    else
                      {
                        hi = c, fhi = fc;
                        if (side == 1)
                          flo *= 0.5;
                        side = 1;
                      }
                  }
                if (tau_event < 0 || hi < tau_event)
                  tau_event = hi, which = i;
              }
          }
        if (tau_event >= 0 && tau_event < h)
          {
            // Re-take the step exactly to the event (full order), then switch the mode.
            double dummy;
            const bool adaptive = opt_.adaptive;
            opt_.adaptive = false;
            try_step(system, t, x, tau_event, x_new, dummy);
            opt_.adaptive = adaptive;
            t += tau_event;
          }
        else
          t = last ? t_end : t + h;
        x = x_new;
        ++stats_.accepted;
        stalled = t - t_before < tiny ? stalled + 1 : 0;
        if (!fixed)
          h_ = last ? std::max(h_, h_next) : h_next;
        if (tau_event >= 0)
          {
            system.update_mode(t, x);
            ++stats_.events;
            if (on_event)
              on_event(Event{t, which}, x);
          }
        else
          system.update_mode(t, x); // consistency (a state exactly on a switching surface);
                                    // without event location the mode switches here
      }
    t = t_end;
  }
} // namespace gearfem::dynamics
