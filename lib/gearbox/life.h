#pragma once
// The gearbox under a load spectrum (Siasos 2010, ch. 8): every bin through
// F_t -> sigma_H, sigma_F (AGMA 2101-D04), AGMA 925 scuffing -> Miner damage per member
// and mode, and life in spectra and years. SI units. No deal.II.
#include "gearbox/fatigue.h"
#include "gearbox/stages.h"
#include "gearbox/scuffing.h"

#include <string>
#include <vector>

namespace gearfem::gearbox
{
  /// Material of all members of one stage (Siasos 2010 table 9.1-2 gives one per stage).
  struct StageMaterial
  {
    std::string name = "steel";
    double E = 206e9, nu = 0.3;  ///< [Pa, -]
    double Ra = 0.5e-6;          ///< roughness of the flanks [m]
    fatigue::SNCurve contact, bending;
  };

  /// Stresses per stage, mesh and bin: stress[stage][mesh][bin].
  using StressTable = std::vector<std::vector<std::vector<MeshStress>>>;

  /// AGMA 2101-D04 stresses of every mesh at every spectrum torque (F_t from 7.2-3).
  StressTable agma_stresses(const Train &t, const fatigue::Spectrum &s, const AgmaFactors &f);

  /// The ISO columns of a stress table as the damage-sum stresses: sigma_H = max(sigma_H1,
  /// sigma_H2) of ISO 6336-2 (Z_B/Z_D; the larger rates both members of the mesh, as the
  /// AGMA sigma_H does), sigma_F1/F2 = ISO 6336-3 method B. The ISO columns are kept.
  StressTable iso_stresses(const StressTable &agma);

  /// Stresses known at one gearbox-input torque M_ref [N m] (e.g. the thesis' tables at
  /// 45 000 N m), scaled to every bin: sigma_H ~ sqrt(M/M_ref), sigma_F ~ M/M_ref (Siasos 2010
  /// tables 9.4-1..3 follow these laws exactly). at_ref[stage][mesh].
  StressTable scaled_stresses(const Train &t, const fatigue::Spectrum &s,
                              const std::vector<std::vector<MeshStress>> &at_ref, double M_ref);

  /// Miner damage of one member in one mode.
  struct MemberLife
  {
    std::string stage, member, mode; ///< mode: "contact" or "bending"
    std::string detail;              ///< which mesh/flank, and how the planet's meshes combine
    double cycles_per_revolution = 0; ///< load cycles per gearbox-input revolution (per mesh)
    fatigue::Damage damage;
    double life_years = fatigue::infinite_life;
    /// Per load (mesh or flank whose damages add up), per bin: the stress [Pa] and the load
    /// cycles per spectrum (for the S-N plot, gearbox_sn.csv).
    std::vector<std::vector<double>> stress, cycles;
    std::size_t stage_index = 0;
  };

  /// Damage of every member and mode (Siasos 2010 table 8.2-1 cycles, eqs. 8.4-1..4).
  /// The planet's two meshes load opposite flanks: contact is rated per flank (sun side,
  /// ring side) and the member's contact life is the shorter; bending damage of the two
  /// meshes is summed (the tooth root sees both, reversed bending ignored as in the
  /// thesis). The ring is not rated in bending. materials: one per stage.
  std::vector<MemberLife> member_lives(const Train &t, const fatigue::Spectrum &s,
                                       const StressTable &stress,
                                       const std::vector<StageMaterial> &materials);

  /// Scuffing of every mesh in every bin: scuff[stage][mesh][bin]. The mesh speeds are
  /// those relative to the carrier (Siasos 2010 does not say which it uses).
  using ScuffingTable = std::vector<std::vector<std::vector<scuffing::Result>>>;
  ScuffingTable scuffing_table(const Train &t, const fatigue::Spectrum &s, const AgmaFactors &f,
                               const std::vector<StageMaterial> &materials,
                               const scuffing::Lubricant &oil, const scuffing::Conditions &c);

  /// Everything `gearfem gearbox` needs.
  struct GearboxInput
  {
    std::vector<StageInput> stages;
    std::vector<StageMaterial> materials; ///< one per stage
    double input_speed = 61.0;            ///< [rpm]
    AgmaFactors agma;
    fatigue::Spectrum spectrum;
    scuffing::Lubricant oil;
    scuffing::Conditions conditions;
  };
  /// The train with each stage's elastic constants (Z_E) from its material. Throws
  /// InputError for a material count that differs from the stage count.
  Train build_train(const GearboxInput &in);

  struct GearboxResult
  {
    Train train;
    StressTable stress;
    ScuffingTable scuff;
    std::vector<MemberLife> lives;
    /// Index into lives of the shortest life (the member that fails first); -1 if none.
    int first_failure = -1;
  };
  /// Throws InputError (named entry) for any bad input, before computing anything.
  GearboxResult analyse(const GearboxInput &in);

  /// Replace the AGMA stresses of the damage sum by stresses given at M_ref (scaled_stresses)
  /// and redo the lives and the first failure; the ISO columns and the scuffing results
  /// keep the computed values.
  void use_reference_stresses(GearboxResult &r, const GearboxInput &in,
                              const std::vector<std::vector<MeshStress>> &at_ref, double M_ref);

  /// Replace the stresses of the damage sum by `s` (e.g. FE stresses per mesh and bin, from
  /// lib/gearbox_fe) and redo the lives and the first failure; the ISO columns and the
  /// scuffing results keep the computed values. Throws InputError for a table whose shape
  /// differs from the train and spectrum, or a stress that is not finite and >= 0.
  void use_stress_table(GearboxResult &r, const GearboxInput &in, StressTable s);
} // namespace gearfem::gearbox
