#pragma once
// Analyses of a MeshModel: time response with automatic steady-state detection, dynamic
// factor, RMS / peak-to-peak DTE, contact-loss fraction, up/down speed sweeps with
// continuation (threads across independent sweeps), FFTW spectra, and a harmonic-balance
// solver for the linear time-varying (no-impact) regime as an independent reference.
#include "dynamics/models.h"
#include "dynamics/ode.h"

#include <complex>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace gearfem::dynamics
{
  struct ResponseOptions
  {
    int max_periods = 300;        ///< transient + recorded mesh periods, at most
    int record_periods = 32;      ///< mesh periods recorded in steady state (rounded up to a multiple of the detected period)
    int min_transient_periods = 8; ///< never record before this
    int samples_per_period = 64;  ///< uniform output samples per mesh period
    int steps_per_period = 128;   ///< fixed-step methods: h = T_mesh / steps_per_period (0: use IntegratorOptions::step)
    double steady_tolerance = 1e-5; ///< Poincare-sample change, relative to the response scale
    bool keep_history = false;    ///< store the recorded samples (time response output)
    /// Throws InputError naming "Analysis/..." parameters.
    void check() const;
  };

  /// Result of one speed point.
  struct Response
  {
    double pinion_speed = 0, mesh_frequency = 0; ///< [rad/s], [Hz]
    double mean = 0, rms = 0, peak_to_peak = 0;  ///< DTE statistics over the record [m]
    double dynamic_factor = 0;                   ///< K_v = F_max / F_static [-]
    double contact_loss_fraction = 0;            ///< fraction of record time with s != 1
    double back_contact_fraction = 0;            ///< fraction of record time with s == -1
    int impact_regime = 0;     ///< 0 no impact, 1 single-sided, 2 double-sided
    int period_multiplicity = 0; ///< detected period in mesh periods (1, 2, 3, 4); 0: none
    bool settled = false;       ///< steady state detected before the record started
    int transient_periods = 0;  ///< periods integrated before recording
    long contact_events = 0;    ///< located contact-state changes during the record
    long out_of_range = 0;      ///< table evaluations outside the validity range
    /// Half the peak-to-peak of the gears' vibratory angles over the record (angle minus the
    /// nominal rotation; MeshModel::angle_deviations) [rad]; NaN for models without angles.
    double angle_amplitude1 = std::numeric_limits<double>::quiet_NaN();
    double angle_amplitude2 = std::numeric_limits<double>::quiet_NaN();
    /// Energy balance of a conservative model over the whole run (MeshModel::conservative()):
    /// (change of kinetic + elastic energy - work of the torques) / initial kinetic energy [-];
    /// NaN when the model is not conservative.
    double energy_balance = std::numeric_limits<double>::quiet_NaN();
    long steps = 0, rhs_evaluations = 0; ///< integrator work for this point
    // History of the record (keep_history): time [s], delta [m], rate [m/s], force [N], s.
    std::vector<double> t, delta, rate, force;
    std::vector<int> state;
    /// Vibratory angles of pinion and gear [rad] (models with angles; MeshModel::angle_deviations).
    std::vector<double> angle1, angle2;
    std::vector<double> poincare_delta, poincare_rate; ///< one per mesh period (whole run)
  };

  /// Integrate `model` from (t, x) at its current speed until steady state (or the transient
  /// limit) and record. On return (t, x) is the final state (t a multiple of T_mesh).
  Response run_response(MeshModel &model, const IntegratorOptions &integrator,
                        const ResponseOptions &options, State &x, double &t);

  struct SweepPoint
  {
    int direction = 1; ///< +1 up, -1 down
    Response response;
  };

  /// One sweep over `speeds` (pinion speeds [rad/s], in the order given), continuing the
  /// final state of each speed as the initial state of the next. `progress(i)` is called
  /// after each point (may be empty).
  std::vector<SweepPoint> sweep(const MeshModel &prototype, const IntegratorOptions &integrator,
                                const ResponseOptions &options, const std::vector<double> &speeds,
                                int direction, const std::function<void(std::size_t)> &progress);

  /// Up and down sweeps over [w_min, w_max] with n speeds each, run in parallel threads
  /// (the two directions are independent). Returns up points then down points.
  std::vector<SweepPoint> sweep_up_down(const MeshModel &prototype,
                                        const IntegratorOptions &integrator,
                                        const ResponseOptions &options, double w_min,
                                        double w_max, int n, std::ostream *progress_out,
                                        int threads = 2);

  /// Run independent tasks on up to `threads` std::threads.
  void run_parallel(const std::vector<std::function<void()>> &tasks, int threads);

  /// Single-sided amplitude spectrum (FFTW r2c) of uniformly sampled data with the mean
  /// removed: amplitude[k] at frequency[k] = k / (N dt).
  struct Spectrum
  {
    std::vector<double> frequency, amplitude;
  };
  Spectrum amplitude_spectrum(const std::vector<double> &samples, double dt);

  /// Harmonic balance for m d'' + c d' + k(theta) d = F0 with theta = W t and the Fourier
  /// stiffness of FourierStiffnessLaw (no impacts, i.e. d > 0 throughout). Solves for the
  /// complex harmonics D_n, n = -N..N, of exp(i n z W t).
  struct HarmonicBalance
  {
    std::vector<std::complex<double>> D; ///< D[n + N]
    int N = 0;
    double omega = 0; ///< mesh circular frequency z W [rad/s]
    double value(double t) const;
    double rms() const; ///< RMS of d - mean
    double minimum(int samples = 2048) const;
  };
  HarmonicBalance harmonic_balance(const FourierStiffnessLaw &law, double mass, double damping,
                                   double static_force, double pinion_speed, int harmonics);
} // namespace gearfem::dynamics
