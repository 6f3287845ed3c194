#pragma once
// Fatigue life under a load spectrum (Siasos 2010, sec. 8.4): S-N curves for
// contact and bending, Palmgren-Miner damage and life in spectra and years. SI units
// (stresses in Pa). No deal.II.
#include <limits>
#include <string>
#include <vector>

namespace gearfem::gearbox::fatigue
{
  constexpr double infinite_life = std::numeric_limits<double>::infinity();

  /// S-N model of one material and mode.
  ///  - semi_log (Siasos 2010 eqs. 8.4-3, -4): sigma = A + B log10 N, so
  ///    N = N_ref 10^((sigma - sigma_n)/B); B < 0 [Pa per decade]; no damage for
  ///    sigma <= sigma_n (the thesis' "+inf" lives).
  ///  - iso (ISO 6336-2:2006 table 2 / 6336-3:2006 table 3): the permissible stress is
  ///    sigma_lim Y_N(N) with the life factor Z_NT or Y_NT interpolated log-log between
  ///    (N_static, Y_static) and (N_ref, 1); no damage for sigma <= sigma_lim; sigma above
  ///    sigma_lim Y_static fails in N_static cycles.
  struct SNCurve
  {
    enum class Kind
    {
      semi_log,
      iso
    } kind = Kind::semi_log;
    double sigma_n = 0;  ///< endurance stress sigma_n (semi_log) or sigma_lim (iso) [Pa]
    double N_ref = 1e8;  ///< cycles at sigma_n (the knee)
    double B = -10e6;    ///< semi_log slope [Pa per decade], < 0
    double N_static = 1e5; ///< iso: cycles of the static limit
    double Y_static = 1.6; ///< iso: life factor at N_static
  };

  /// The ISO 6336 life-factor curves (2006 editions) by material group:
  /// contact "Eh" (case hardened, no pitting: 1e5 -> 1.6, 5e7 -> 1.0),
  /// contact "NT" (nitrided: 1e5 -> 1.3, 2e6 -> 1.0),
  /// bending "Eh" (1e3 -> 2.5, 3e6 -> 1.0), bending "NT" (1e3 -> 1.6, 3e6 -> 1.0).
  /// Throws InputError for another group.
  SNCurve iso_curve(const std::string &mode, const std::string &group, double sigma_lim);

  /// Throws InputError naming `parameter` for a curve that is not usable.
  void check_curve(const SNCurve &c, const std::string &parameter);

  /// Cycles to failure at stress sigma [Pa]; infinite_life when no damage.
  double cycles_to_failure(const SNCurve &c, double sigma);
  /// The life factor Z_NT/Y_NT of an iso curve at N cycles (1 beyond N_ref).
  double life_factor(const SNCurve &c, double N);

  /// Palmgren-Miner damage D = sum n_i/N_i (Siasos 2010 eq. 8.4-1) and life 1/D in spectra
  /// (8.4-2); bins with sigma_i <= the endurance stress contribute nothing.
  struct Damage
  {
    double D = 0.0;
    double life_spectra = infinite_life;
    std::vector<double> per_bin; ///< n_i/N_i
  };
  /// @param sigma stresses per bin [Pa]; @param cycles load cycles per bin (>= 0).
  Damage miner(const SNCurve &c, const std::vector<double> &sigma, const std::vector<double> &cycles);

  /// A load spectrum at the gearbox input: torque bins and the input revolutions spent in
  /// each over `duration_years` (Siasos 2010 table 9.2-1: 10 years).
  struct Spectrum
  {
    std::vector<double> torques;     ///< [N m], > 0
    std::vector<double> revolutions; ///< input-shaft revolutions, >= 0
    double duration_years = 10.0;
    /// Throws InputError: empty spectrum, sizes differ, torque <= 0, revolutions < 0,
    /// all revolutions zero, duration <= 0.
    void check() const;
    double total_revolutions() const;
  };
  /// Spectrum bins from hours at the input speed n [rpm]: revolutions = 60 n h.
  std::vector<double> revolutions_from_hours(const std::vector<double> &hours, double speed);
} // namespace gearfem::gearbox::fatigue
