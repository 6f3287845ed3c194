#pragma once
// FE-backed stresses of the gearbox rating: the meshes of a gearbox (sun-planet and
// planet-ring of a planetary stage, the pair of a parallel stage) solved with the
// `gearfem solve` chain (solve::run_solve: sweep over one mesh cycle, tables, progress) on
// sector models, at a few gearbox-input torques; the contact and root stresses over the
// cycle, interpolated in torque, replace the standard formulas in the damage sum
// (gearbox::use_stress_table).
//
// Layering: this module sits above solve (it calls solve::run_solve) and below commands; the
// analytical gearbox code only receives a StressTable, so it stays free of deal.II.
//
// What is taken from each FE sweep (one mesh cycle, `positions` roll angles from A):
//  - sigma_H: the largest Hertz pressure p_Hertz of a flank-to-flank tooth pair over the
//    cycle, i.e. Hertz (plane strain, E' of both gears) on the local involute radii at the
//    FE peak-pressure point, with the pair's FE load share. It is what AGMA/ISO sigma_H
//    approximates (Hertz at the critical single-contact point), and is insensitive to the
//    element size on the flank, unlike the recovered nodal peak p_max, which needs >= 5
//    nodes across a Hertz patch of ~0.2 mm (h ~ 0.03 mm). p_max is reported beside it.
//  - sigma_F1, sigma_F2: the largest fillet sigma_1 of pinion and gear over the cycle.
// Load: the FE pinion torque is F_t r_w1 K_o K_v K_s K_H (the AGMA W of the same mesh,
// Siasos 2010 eq. 7.2-3 F_t): the 2-D model carries neither the dynamic nor the face load
// distribution, so those factors load it as they load the formulas. The rim factor K_B is
// not applied (the FE sector has its own rim).
// Torque interpolation: sigma_H/sqrt(T) and sigma_F/T are interpolated linearly in T between
// the solved torques (exact for Hertz and for linear bending at fixed load share) and held
// constant beyond them.
#include "gearbox/life.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace gearfem::gearbox::fe
{
  namespace gb = gearfem::gearbox;

  /// The `FE stresses` section of `gearfem gearbox` (SI units).
  struct FeStressOptions
  {
    std::vector<int> stages;  ///< 1-based stages whose meshes are solved; empty: all
    int sector_teeth = 3;     ///< teeth of each sector model [3, 7]
    double h_contact = 0;     ///< flank element size [m]; 0: m/30
    double h_fillet = 0;      ///< fillet element size [m]; 0: m/14
    double h_body = 0;        ///< body element size [m]; 0: m
    int positions = 12;       ///< roll angles over one mesh cycle [4, 200]
    int torque_points = 3;    ///< torques solved, evenly over the spectrum; 0: every bin
    std::filesystem::path output_dir; ///< each mesh's solve results in <dir>/stage<k>_<mesh>/
    std::ostream *out = nullptr;      ///< progress lines; null: silent
  };
  /// The `Pair` and `Ring` sections (and the ring's rim thickness) of the `gearfem solve` case
  /// of a planet-ring mesh: Pair/Type = internal at the zero-backlash centre distance (the
  /// thesis' a = r_w2 - r_w1 leaves negative backlash for the nominal tooth thicknesses), the
  /// ring cut by a shaper with the planet's tooth count and the AGMA tool's addendum and tip
  /// radius, its rim from the ring's outside diameter (m_B 1.2 when not given).
  std::string internal_case(const gb::MeshGeometry &g, const gb::StageInput &s, const rating::agma::Tool &tool);
  /// Throws InputError naming "FE stresses/<entry>", its value and the allowed range.
  void validate(const FeStressOptions &o, std::size_t n_stages);

  /// The `gearfem solve` case (parameter file text) of one mesh: both gears as
  /// sector models, plane strain, the mesh's centre distance (thesis convention a = r_w1 +
  /// r_w2, so the operating pressure angle is that of the AGMA rating), the pinion torques.
  std::string contact_case(const gb::MeshGeometry &g, const gb::StageInput &s, const gb::StageMaterial &m,
                           const rating::agma::Tool &tool, const FeStressOptions &o,
                           const std::vector<double> &pinion_torques);

  /// FE pinion torque of mesh j of stage k at the gearbox-input torque M [N m]:
  /// F_t r_w1 K_o K_v K_s K_H.
  double fe_pinion_torque(const gb::Train &t, std::size_t k, std::size_t j, double M, const gb::AgmaFactors &f);

  /// The gearbox-input torques to solve: `points` evenly from the smallest to the largest
  /// bin torque (one point: the largest); 0: every distinct bin torque. Ascending.
  std::vector<double> solve_torques(const gearbox::fatigue::Spectrum &s, int points);

  /// y(x0) from samples (x ascending): y/x^e interpolated linearly in x, constant beyond.
  double interpolate(const std::vector<double> &x, const std::vector<double> &y, double x0, double e);

  /// One mesh after its FE sweeps.
  struct MeshFeStress
  {
    std::size_t stage = 0, mesh = 0; ///< 0-based
    std::string name;                ///< "Stage 2 sun-planet"
    std::filesystem::path dir;       ///< its solve results
    std::vector<double> input_torques, pinion_torques; ///< solved [N m]
    /// Per solved torque, maxima over the cycle [Pa]: Hertz from the FE load share, the
    /// recovered nodal peak (flank-to-flank pairs), fillet sigma_1 of pinion and gear.
    std::vector<double> sigma_H, p_max, sigma_F1, sigma_F2;
    unsigned int dofs = 0;
    double seconds = 0;    ///< set-up and sweep
    std::string failure;   ///< SolverError message; empty on success
  };

  /// Solve one mesh at the gearbox-input torques M (ascending) through solve::run_solve.
  MeshFeStress solve_mesh(const gb::GearboxInput &in, const gb::Train &t, std::size_t k, std::size_t j,
                          const std::vector<double> &M, const FeStressOptions &o);

  struct FeStressResult
  {
    std::vector<MeshFeStress> meshes;
    /// The damage-sum stresses: `base` with sigma_H, sigma_F1, sigma_F2 of every solved mesh
    /// replaced by the interpolated FE values (the ISO columns are kept).
    gb::StressTable stress;
    std::string failure; ///< first solver failure; the meshes before it are complete
  };
  /// Solve the meshes of the selected stages (progress "FE mesh i/N") and build the table. A
  /// solver failure stops the loop and is returned in `failure` (the caller exits 3).
  FeStressResult fe_stress_table(const gb::GearboxInput &in, const gb::Train &t, const gb::StressTable &base,
                                 const FeStressOptions &o);

  /// fe_stresses.csv: one row per solved mesh and torque (input and pinion torque, sigma_H,
  /// p_max, sigma_F1, sigma_F2 in MPa, DoFs), written atomically; never NaN.
  void write_fe_stresses(const FeStressResult &r, const std::filesystem::path &file);
  /// The markdown paragraph of gearbox.md describing the FE source and its numbers.
  std::string fe_markdown(const FeStressResult &r, const FeStressOptions &o);
} // namespace gearfem::gearbox::fe
