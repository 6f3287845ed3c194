#pragma once
// ODE integration in the odeint shape: a system functor, interchangeable steppers and an
// observer. Systems may be piecewise smooth ("hybrid"): the right-hand side depends on a
// discrete mode (contact state, stiffness zone) that is frozen during a step. Switching
// functions g_i(t, x) mark where the mode changes; the integrator locates their sign
// changes, stops there, lets the system re-classify its mode and restarts the step.
//
// References: Hairer, Norsett & Wanner (1993) "Solving ODEs I", sec. II.4-II.6
// (Dormand-Prince 5(4) with dense output, eq. 6.12, and step control II.4);
// Alexander (1977) SIAM J. Numer. Anal. 14(6), 1006-1021 (3-stage L-stable SDIRK, order 3);
// Shampine & Thompson (2000) "Event location for ordinary differential equations".
#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace gearfem::dynamics
{
  /// State vector: dynamic size, at most 8 entries, never heap-allocated.
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 8, 1>;

  /// A (piecewise) smooth first-order system x' = f(t, x; mode).
  class HybridSystem
  {
  public:
    virtual ~HybridSystem() = default;
    virtual int dimension() const = 0;
    /// odeint-style right-hand side with the current (frozen) mode.
    virtual void operator()(const State &x, State &dxdt, double t) const = 0;
    /// Number of switching functions of the current mode.
    virtual int n_switches() const { return 0; }
    /// Switching functions g[0..n_switches()) at (t, x); a sign change means a mode change.
    virtual void switching_functions(double t, const State &x, double *g) const {}
    /// Re-classify the mode from (t, x). Returns true if it changed.
    virtual bool update_mode(double t, const State &x) { return false; }
  };

  enum class Method
  {
    rk4,    ///< classical fixed-step Runge-Kutta, order 4
    dopri5, ///< Dormand-Prince 5(4), adaptive (or fixed step when adaptive = false)
    sdirk3  ///< implicit L-stable SDIRK, order 3 (Alexander 1977), fixed step, Newton
  };

  Method method_from_string(const std::string &name); ///< "RK4", "DOPRI5", "SDIRK3"
  std::string to_string(Method m);
  int order(Method m);

  struct IntegratorOptions
  {
    Method method = Method::dopri5;
    bool adaptive = true;        ///< only for dopri5
    double step = 1e-3;          ///< fixed step, or the first trial step when adaptive [time unit]
    double rtol = 1e-8;          ///< relative tolerance (adaptive)
    double atol = 1e-12;         ///< absolute tolerance (adaptive) [state units]
    double max_step = 0.0;       ///< upper bound of the adaptive step (0: none)
    double event_tolerance = 1e-12; ///< bracket width of located events [time unit]
    bool locate_events = true;   ///< false: let the mode switch at step ends (chatters)
    /// Wall-time cap of a run [s] (`Dynamics/Integrator/Wall time limit`; 0: none): the first
    /// run_response or sweep_up_down of a run turns it into `deadline`, and advance() ends with
    /// a SolverError naming the entry once the deadline has passed.
    double wall_limit = 0.0;
    double deadline   = 0.0; ///< monotonic_seconds() at which the run stops (0: none)
    /// Throws InputError (names "Integrator/...") for step <= 0 and tolerances out of range:
    /// rtol in [1e-14, 1e-2], atol in (0, max_absolute_tolerance], event tolerance in (0, 1e-3].
    void check() const;
    /// The deadline of a run starting now: `deadline` if set, else now + wall_limit (if > 0).
    IntegratorOptions with_deadline() const;
  };
  /// Seconds of a monotonic clock (std::chrono::steady_clock).
  double monotonic_seconds();
  inline constexpr double max_absolute_tolerance = 1e-3;
  /// The caps of Integrator::advance, beyond which a call ends with a named SolverError
  /// instead of running on: the steps (accepted, rejected and event steps) of one call, and
  /// the consecutive accepted steps that each advance less than 1e-8 of the call's interval
  /// (events piling up: a Zeno-like chatter).
  inline constexpr long max_steps_per_advance = 100000000;
  inline constexpr long max_stalled_steps     = 100000;

  /// A located mode change.
  struct Event
  {
    double t;       ///< time of the sign change (right end of the bracket) [time unit]
    int which;      ///< index of the switching function
  };

  /// Counters of one integrator.
  struct IntegratorStats
  {
    long accepted = 0, rejected = 0, rhs_evaluations = 0, events = 0;
  };

  /// Integrates a HybridSystem with the chosen method; keeps the adaptive step between
  /// calls so that advance() can be called once per output sample.
  class Integrator
  {
  public:
    explicit Integrator(const IntegratorOptions &options);
    /// Integrate x from t to t_end exactly (the last step is shortened). `on_event` is
    /// called after each located mode change with the state at the event.
    void advance(HybridSystem &system, State &x, double &t, double t_end,
                 const std::function<void(const Event &, const State &)> &on_event = nullptr);
    const IntegratorStats &stats() const { return stats_; }
    const IntegratorOptions &options() const { return opt_; }
    /// Reset the adaptive trial step to options().step.
    void reset_step() { h_ = opt_.step; }

  private:
    /// One step of size h from (t, x) with the frozen mode; returns false if the error
    /// estimate rejects it (adaptive only), with h_new the proposed next step.
    bool try_step(const HybridSystem &s, double t, const State &x, double h, State &x_new,
                  double &h_new);
    /// Dense output (dopri5 after a successful try_step) or re-integration (others).
    void state_at(const HybridSystem &s, double t0, const State &x0, double h, double tau,
                  State &out);
    void rk4_step(const HybridSystem &s, double t, const State &x, double h, State &out);
    void sdirk3_step(const HybridSystem &s, double t, const State &x, double h, State &out);

    IntegratorOptions opt_;
    IntegratorStats stats_;
    double h_;
    State k_[7];    ///< dopri5 stages of the last try_step
    bool have_k_ = false;
  };
} // namespace gearfem::dynamics
