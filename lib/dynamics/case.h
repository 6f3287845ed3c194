#pragma once
// A complete dynamics case in SI units (filled from the `Dynamics` parameter section by
// parameters.h, or directly in code) and the factory that builds its model.
#include "dynamics/analysis.h"
#include "base/units.h"
#include "dynamics/models.h"
#include "dynamics/pair_data.h"

#include <memory>
#include <string>
#include <vector>

namespace gearfem::dynamics
{
  enum class ModelKind
  {
    dte,            ///< 1-DOF DTE model with a speed source
    torsional,      ///< 2-DOF torsional model (or speed source on gear 1)
    kahraman_singh  ///< dimensionless Kahraman & Singh (1990) form of the 1-DOF model
  };
  enum class LawKind
  {
    fourier,
    piecewise_constant,
    ste,
    external ///< a law built outside this module (e.g. the analytical torque table)
  };

  /// Where a LawKind::external law comes from (built by the caller, e.g. the CLI command,
  /// because these laws need the geometry, analytical or HDF5 modules).
  enum class ExternalSource
  {
    analytical_table, ///< torque table of the Weber/Cornell model (Gkimisis 2019)
    table_file,       ///< HDF5 mesh table (docs/mesh-tables.md)
    ricker            ///< semi-analytical law with Ricker load sharing (Gkimisis 2019)
  };

  struct DynamicsCase
  {
    ModelKind model = ModelKind::torsional;
    bool run_response = true, run_sweep = false;
    // Pair (standard involute pair until geometry::GearPair is wired in).
    int z1 = 20, z2 = 40;
    double module = 2.5e-3, alpha = 0.3490658503988659, addendum = 1.0, face_width = 0.03;
    double thickness1 = 0.5, thickness2 = 0.5, delta_a = 0.0;
    double backlash = -1;    ///< [m]; < 0: from the pair
    double density = 7850;   ///< [kg/m^3]
    double inertia1 = 0, inertia2 = 0; ///< [kg m^2]; 0: solid cylinders of pitch diameter
    // Mesh force law.
    LawKind law = LawKind::piecewise_constant;
    double single_pair_stiffness = 14e9; ///< per face width [N/m^2] (c' = 14 N/(mm um))
    double double_pair_factor = 1.75;    ///< k_double / k_single [-]
    std::vector<double> fourier_cos = {-0.1}, fourier_sin;
    bool reverse_mapping = true;
    std::vector<double> ste_theta, ste_values; ///< [rad], [m] (STE excitation law)
    double ste_stiffness = 0; ///< kbar of the STE law [N/m]; 0: ISO c_gamma_alpha b
    ThetaInterpolation theta_interpolation = ThetaInterpolation::linear; ///< table laws
    double youngs_modulus = 206e9, poisson_ratio = 0.3; ///< [Pa], [-] (analytical tables)
    /// LawKind::external: the law to use (cloned); its backlash comes from `backlash`
    /// (>= 0) or from the standard pair.
    std::shared_ptr<const MeshForceLaw> external_law;
    ExternalSource external_source = ExternalSource::analytical_table;
    std::string table_file; ///< table_file: resolved path of the HDF5 mesh table
    std::string table_hash; ///< table_file: expected geometry hash; empty: not checked
    double ricker_widening = 2.0 * units::pi / 180.0 / 1e-3; ///< c_x [rad/m]
    bool ricker_centred = false; ///< SecondPair::centred instead of the thesis' eq. 3.45
    // Operating point.
    double input_torque = 100, output_torque = -1; ///< [N m]
    double speed = 160;                            ///< pinion speed [rad/s]
    double ramp_time = 0;                          ///< [s]
    bool speed_source = false;
    double zeta = 0.02;
    bool damping_only_in_contact = false;
    bool tooth_mass = false, tooth_mass_energy_weighting = false;
    /// Tooth inertia as the mean over a mesh period (false) or as J_t(theta) in the
    /// equations of motion (true; torsional model only).
    bool tooth_inertia_position_dependent = false;
    bool start_at_rest_deflection = false; ///< delta(0) = 0 (zero initial conditions) instead of F/kbar
    // Kahraman-Singh mode (dimensionless).
    double ks_zeta = 0.05, ks_force = 0.1, ks_frequency = 0.9;
    std::vector<double> ks_cos = {-0.2, -0.1, -0.05};
    // Integration and analysis.
    IntegratorOptions integrator;
    ResponseOptions response;
    double sweep_min = 100, sweep_max = 1000; ///< pinion speeds [rad/s] (Omega in KS mode)
    int sweep_points = 50;
    int threads = 2;
    std::vector<double> portrait_speeds; ///< extra responses [rad/s] (Omega in KS mode)

    /// Throws InputError for inconsistent settings (speed range, tolerances, ...).
    void check() const;
    /// The pair quantities (radii, contact ratio, backlash) for this case.
    PairData pair() const;
  };

  /// Build the model of a case. `notes` receives human-readable derived quantities.
  std::unique_ptr<MeshModel> build_model(const DynamicsCase &c, std::vector<std::string> *notes);
} // namespace gearfem::dynamics
