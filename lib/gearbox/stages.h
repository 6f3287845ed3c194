#pragma once
// Gearbox-level rating (Siasos 2010, ch. 7-9): a train of parallel (external)
// and planetary stages, their kinematics, torques and load cycles, the internal-gear
// geometry and design checks, and the AGMA 2101-D04 / 908-B89 rating of every mesh with
// the internal-mesh signs. SI units inside (m, N, N m, Pa, rpm for speeds). The fatigue
// and scuffing models are in fatigue.h and scuffing.h; analyse() in gearbox_run.h ties
// them to a load spectrum.
#include "rating/agma.h"
#include "rating/iso6336.h"

#include <string>
#include <vector>

namespace gearfem::gearbox
{
  namespace agma    = rating::agma;    // AGMA 2101-D04 / 908-B89 (lib/rating)
  namespace iso6336 = rating::iso6336; // ISO 6336-2/-3 (lib/rating)

  enum class StageType
  {
    parallel,  ///< one external pair, gear 1 drives gear 2
    planetary  ///< sun, N planets, ring, carrier; the sun is always the output
  };
  /// Planetary layouts: ring fixed, carrier in, sun out (Siasos 2010, the thesis' only type);
  /// or carrier fixed (star), ring in, sun out.
  enum class Fixed
  {
    ring,
    carrier
  };

  /// One stage. Profile shifts are coefficients (x m is the shift in mm of Siasos 2010
  /// eq. 2.1.1-9); for the ring, positive x moves the tool towards the centre (eq. 2.1.2-4).
  struct StageInput
  {
    std::string name = "stage";
    StageType type = StageType::planetary;
    Fixed fixed = Fixed::ring;
    /// Planetary: sun, planet, ring. Parallel: gear 1 (input), gear 2 (output), unused.
    int z_sun = 16, z_planet = 28, z_ring = 74;
    double x_sun = 0, x_planet = 0, x_ring = 0;
    double module = 6e-3;            ///< m_n [m]
    double pressure_angle = 0.349066; ///< alpha_n [rad]
    double face_width = 0.11;        ///< b [m]
    double addendum = 1.0;           ///< h_k/m_n (Siasos 2010 does not state it; 1.0 assumed)
    double tip_shortening = 0.0;     ///< K/m_n (eq. 2.1.1-9)
    int planets = 3;                 ///< N
    double K_gamma = 0.0;            ///< load-sharing factor; 0: Siasos 2010 table 7.2-1
    /// Holding diameters for K_B: bore of the sun (gear 1), bore of the planet (gear 2),
    /// outside diameter of the ring [m]; 0: solid (K_B = 1).
    double bore_sun = 0, bore_planet = 0, ring_outer = 0;
    double coaxiality_tolerance = 1e-5; ///< |a_sun-planet - a_planet-ring| allowed [m]
    /// The member that drives the next stage: "sun" (planetary) or "gear 2" (parallel).
    /// The fixed member, or any other, cannot feed the next stage (InputError).
    std::string output = "sun";
  };

  /// AGMA 2101-D04 factors common to every mesh (Siasos 2010 sec. 4.1 choices).
  struct AgmaFactors
  {
    double K_o = 1.0, K_v = 1.05, K_s = 1.0, Z_R = 1.0;
    agma::Enclosure enclosure = agma::Enclosure::precision;
    double E1 = 206e9, nu1 = 0.3, E2 = 206e9, nu2 = 0.3;
    agma::Tool tool;
    /// ISO 6336-1 factors of the ISO contact stress (reported beside AGMA; the same
    /// inputs as `gearfem rate`); K_Halpha = 1.
    double K_A = 1.0, K_v_iso = 1.05, K_Hbeta = 1.0;
  };

  /// Siasos 2010 table 7.2-1: K_gamma for 2..9 planets (1.00 1.00 1.15 1.19 1.23 1.27 1.30 1.33).
  double K_gamma_table(int planets);

  /// One mesh of a stage, in the reducer form of Siasos 2010 sec. 4.1: gear 1 (the pinion) is
  /// the member with fewer teeth; gear 2 is external or the ring (internal).
  struct MeshGeometry
  {
    std::string name, pinion, gear; ///< e.g. "sun-planet", "sun", "planet"
    bool internal = false;
    int z1 = 0, z2 = 0;
    double x1 = 0, x2 = 0;          ///< coefficients (x2 of the ring with its own sign)
    double module = 0, alpha = 0, b = 0;
    double r_w1 = 0, r_w2 = 0;      ///< working radii r_o +- x m [m] (eqs. 2.1.1-9, 2.1.2-4)
    double r_a1 = 0, r_a2 = 0;      ///< tip radii [m] (internal: inner tip radius)
    double r_f1 = 0, r_f2 = 0;      ///< root radii with dedendum 1.25 m [m]
    double a = 0;                   ///< centre distance r_w1 +- r_w2 [m] (eqs. 2.2.1-1, 2.2.2-1)
    double d_w1 = 0;                ///< 2a/(u +- 1) [m]
    agma::LineOfAction loa;
    double Z_I = 0, K_Hma = 0, K_Hpf = 0, K_H = 0, Z_E = 0; ///< Z_E [sqrt(Pa)]
    double m_B1 = 0, m_B2 = 0, K_B1 = 1, K_B2 = 1;
    double Y_J1 = 0, Y_J2 = 0;      ///< Y_J2 = 0: not rated in bending (ring)
    agma::BendingGeometry J1, J2;
    /// ISO 6336-2 factors at F_t = 1 N (internal: z2, d_a2, d_b2 negative, as the
    /// standard's sign convention; Z_D = 1 for the internal gear).
    iso6336::ContactFactors iso;
    /// ISO 6336-3 method B form and stress-correction factors (load at the outer point of
    /// single contact, critical section from the standard's rack-fillet closed form, eqs.
    /// 25-33, with the tool of AgmaFactors) of pinion and (external) gear; the ring is not
    /// rated in bending (Y_F = 0), as in AGMA.
    iso6336::RootFactors F1_iso, F2_iso;
    double K_Fbeta = 1;             ///< K_Hbeta^N_F (ISO 6336-1 eq. 41)
  };
  /// Geometry, line of action and AGMA factors of a mesh. hold1, hold2: holding diameters
  /// for K_B [m] (bore, or the ring's outside diameter); 0: K_B = 1.
  MeshGeometry mesh_geometry(const std::string &name, const std::string &pinion,
                             const std::string &gear, bool internal, int z1, int z2, double x1,
                             double x2, const StageInput &s, double hold1, double hold2,
                             const AgmaFactors &f);

  /// AGMA stresses of a mesh at the tangential load F_t [N] (Siasos 2010 eqs. 4.1-1, 4.2-1) [Pa].
  struct MeshStress
  {
    double sigma_H = 0, sigma_F1 = 0, sigma_F2 = 0; ///< sigma_F2 = 0 for the ring
    /// ISO 6336-2 contact stress of pinion (Z_B) and gear (Z_D), for comparison; the
    /// damage sum uses the AGMA sigma_H as the thesis does. F_t,ISO = F_t r_w1/r_1.
    double sigma_H1_iso = 0, sigma_H2_iso = 0;
    /// ISO 6336-3 method B root stress of pinion and gear (0: ring), F_t,ISO/(b m_n) Y_F Y_S
    /// Y_beta K_A K_v K_Fbeta K_Falpha with Y_beta = K_Falpha = 1 (spur, K_Halpha = 1).
    double sigma_F1_iso = 0, sigma_F2_iso = 0;
  };
  MeshStress mesh_stress(const MeshGeometry &g, double Ft, const AgmaFactors &f);

  /// A stage after the design checks: meshes, kinematics per input speed and torque.
  struct Stage
  {
    StageInput in;
    std::vector<MeshGeometry> meshes; ///< planetary: sun-planet, planet-ring; parallel: one
    double K_gamma = 1.0;
    double ratio = 1.0;           ///< i = n_in/n_out (Siasos 2010 eq. 7.2-1: Z_S/(Z_S + Z_R))
    double torque_ratio = 1.0;    ///< M_out/M_in = i (7.2-9)
    double sun_working_radius = 0; ///< r_ws [m]
    /// Member speeds relative to the carrier per unit input speed (0 for parallel).
    double n_sun_rel = 0, n_planet_rel = 0, n_ring_rel = 0;
    /// Load cycles of each member per stage-input revolution (Siasos 2010 table 8.2-1):
    /// planetary: sun, planet (per mesh, one flank each), ring; parallel: gear 1, gear 2.
    double cycles_sun = 0, cycles_planet = 0, cycles_ring = 0;
    /// F_t of every mesh at the stage input torque M_in [N m] (7.2-3: K_gamma M_out/(N r_ws)).
    double tangential_load(double M_in) const;
  };

  /// Check the stage and build it. Throws InputError naming "<stage name>/<entry>" for:
  /// teeth < 5, equal spacing (Z_S + Z_R)/N not an integer (7.2-13), Z_R < Z_P + 10
  /// (2.2.2-2), involute interference on the generated line of action (C1 <= 0), meshes
  /// not coaxial (|a_SP - a_PR| > tolerance), planets touching (d_aP >= 2 a sin(pi/N)),
  /// N < 2, and a contact ratio < 1.
  Stage build_stage(const StageInput &s, const AgmaFactors &f);

  /// The train: stage k's output drives stage k+1's input.
  struct Train
  {
    std::vector<Stage> stages;
    double input_speed = 0; ///< [rpm]
    /// Speed at the input of each stage and at the output [rpm] (size stages + 1).
    std::vector<double> speeds() const;
    /// Input torque of each stage and the output torque for the gearbox input M [N m].
    std::vector<double> torques(double M) const;
    /// Revolutions of stage k's input per gearbox-input revolution (1/prod of earlier i).
    double input_revolutions(std::size_t k) const;
  };
  /// Throws InputError for an empty stage list or a non-positive input speed.
  Train build_train(const std::vector<StageInput> &stages, double input_speed,
                    const AgmaFactors &f);
} // namespace gearfem::gearbox
