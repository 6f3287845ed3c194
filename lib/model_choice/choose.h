#pragma once
// The cheapest FE model expected to meet an accuracy target, read off the measured model
// ladder (validation/speed_vs_error, docs/model-choice.md) and the pair's own size. The
// choice is the first guess of model_choice/to_target.h, which then proves it on the run. No deal.II.
#include "analytical/elastic.h"
#include "model_choice/target.h"
#include "geometry/pair.h"
#include "mesh/gear_mesh.h"

#include <string>
#include <vector>

namespace gearfem::model_choice
{
  /// The entries the user set in the input: they override the automatic choice.
  struct FixedSettings
  {
    bool h_contact = false, h_fillet = false, h_corner = false, degree = false, model = false, tiled = false;
    bool h_body = false, h_tooth = false;
  };

  struct ModelChoice
  {
    mesh::GearMeshParameters mesh[2]; ///< sizes resolved to metres (h_contact never 0)
    unsigned int degree = 2;
    /// The largest h_contact that keeps the contact field of the tooth entering mesh out of
    /// its fillet: the smaller flank height r_SAP - r_Ff of the two gears [m] (0: none).
    double flank_height = 0;
    /// The h_contact the module alone asks for (the rung without the half-width rule) [m]: the
    /// companion is sized from it, as for a level the proof refined (to_target.h).
    double ladder_h_contact = 0;
    std::vector<std::string> reasons; ///< why each setting, in words, with the measured figures
  };

  /// The ladder of contact sizes h_contact = m/n the choice moves on: n = 8, 10, 15, 20, 30,
  /// 45, 60, 90 (m/10, m/15 and m/30 measured in validation/speed_vs_error).
  const std::vector<int> &contact_rungs();
  /// The error the measured ladder predicts at h_contact `h` [m] for module `m` [m] (relative;
  /// order 2 from the worst measured case; p-p 1 (100 %) coarser than m/20; 0 for the root stress).
  /// With the Hertz half-width `a` [m] (contact_half_width; 0: not known), the p-p STE is also
  /// at least pp_per_half_width (h / a)^2, an envelope of what the run's own p-p estimate gave
  /// on the five pairs of validation/model_choice at m/30, m/45 and m/60, 0.70-1.57 %
  /// (h / a)^2 for h / a = 0.57 to 1.35 (the node-to-segment contact resolves a patch of 2a / h
  /// elements: the lightly loaded Siasos 2010 23/69 pair at m/45 has 2.2 of them, a 1.00 % p-p
  /// estimate, and needs m/60).
  double predicted_error(Quantity q, double h, double m, double a = 0);
  /// The envelope of the p-p estimate per (h / a)^2 (predicted_error).
  inline constexpr double pp_per_half_width = 0.020;
  /// The Hertz half-width [m] of the pair's contact at the pitch point C (equivalent_curvature
  /// there) with the whole torque `torque` [N m] on one tooth pair, over the narrower face
  /// width: a = sqrt(4 w R / (pi E*)), w = torque / (r_b1 b) (analytical::hertz_line_contact).
  /// 0 (not known) for a torque <= 0 or a pair without a base circle or curvature at C.
  double contact_half_width(const geometry::GearPair &pair, const analytical::PlaneElastic &e1,
                            const analytical::PlaneElastic &e2, double torque);
  /// The resolution of a root stress read with fillet size `h_fillet` [m], module `m` [m]
  /// (relative): the envelope of the fitted fillet peak's error against h_fillet m/60, over
  /// the level-to-level scatter of the meshes. Two levels cannot resolve an error below it:
  /// that error is not ordered by h (the Parker pinion: +0.10 / +0.59 / +0.18 / +0.58 / +0.36 %
  /// at m/6 / m/6.7 / m/10 / m/12 / m/20). Measured on four pairs (Parker, FZG type C,
  /// Siasos 2010 23/69, 41/28 m 2.5), both gears, h_fillet m/5 to m/40, h_contact m/45 by
  /// tiles, one single-contact position each: at most 1.8 % at m/6, 1.1 % at m/8, 0.89 % at
  /// m/10, 0.76 % at m/12, 0.53 % at m/15, 0.36 % at m/20, 0.13 % at m/30 (3.5 % at m/5,
  /// coarser than any level it is used for). Envelope
  /// 1.82 % (6 h / m)^fillet_resolution_order (0.77 % at m/12).
  double fillet_resolution(double h_fillet, double m);
  /// The order in h of fillet_resolution.
  inline constexpr double fillet_resolution_order = 1.25;
  /// The fillet size [m] whose fillet_resolution is `resolution` (its inverse).
  double fillet_size_for_resolution(double resolution, double m);
  /// The coarsest rung at or below 1.1 h (h itself below the finest rung).
  double snap_finer(double h, double m);

  /// The body size of a full gear the choice takes [m]: `given` (Mesh/h_body), coarsened to
  /// 1.5 m but to no more than a sixth of the ring between the root circle and the inner
  /// boundary (`ring`: at least six elements through it); never finer than `given`. The body
  /// carries no contact and no fillet peak: on the five pairs of validation/model_choice, with
  /// h_tooth 0.8 m (unloaded_tooth_size), the true errors of the runs delivered at the same
  /// level moved by at most +0.009 % (mean STE), +0.014 % (p-p) and +0.005 % (root stress),
  /// for 4-33 % fewer DoFs (42/76 m 4: 167 000 to 134 000, the run 3.9 to 3.3 s CPU). A sixth,
  /// not a third: with the Siasos 2010 23/69 pinion's ring of 20.5 mm at 6 mm, the companion's
  /// STE at the middle of double contact fell 0.76 % below the candidate's (0.11 % at 3 mm)
  /// and the mean STE estimate rose to five times the true error.
  double body_size(double given, double m, double ring);
  /// The size of the unloaded teeth the choice takes with body_size [m]: 0.8 m (the default
  /// min(h_body, 0.4 m) doubled), at most the body size. Not m: on the 69-tooth Siasos 2010
  /// gear h_tooth = m = 4 mm made gmsh return 72 000 DoFs instead of 40 000 at 3.2 mm.
  double unloaded_tooth_size(double h_body, double m);

  /// The flank height bound of ModelChoice::flank_height.
  double flank_height_bound(const geometry::GearPair &pair);

  /// The first guess for `target`. `given`/`degree`: the parsed Mesh sections and FE degree,
  /// whose entries named in `fixed` are kept. Rules (errors are the worst measured over three
  /// pairs and three torques, validation/speed_vs_error):
  ///  - h_contact: the coarsest rung (contact_rungs) whose predicted errors (predicted_error:
  ///    mean STE 1.94 % at about m/10 (an earlier study's meshes; 1.26 % now, the larger
  ///    kept), p-p 1.3 % at m/30 and never coarser than m/20, where the tip-corner contact is
  ///    unresolved (p-p 10.6 % at m/12 to m/18), p_max 8.1 % at m/30 (FZG type C); all order 2) are within
  ///    1.1 times the tolerances. The p-p figure is an envelope of what the run's own
  ///    estimate, which includes twice the swept mesh ripple, gives at m/30 (0.76-0.90 % on
  ///    four pairs of validation/model_choice; 2.9 % on the lightly loaded one; 0.28-0.60 % at
  ///    m/45), not the true error (at most 1.1 %): the guess aims at a level the proof accepts
  ///    with a margin over the mesh-to-mesh scatter of the estimate, so that one sweep
  ///    suffices; with
  ///    `half_width` (contact_half_width at the lowest torque; 0: not known), also at least
  ///    pp_per_half_width (h / a)^2, so that a lightly loaded pair starts fine enough;
  ///  - from the root stress: h_fillet m/12, finer where its fillet_resolution exceeds the
  ///    tolerance / 1.1 (0.77 % at m/12); and h_contact at most
  ///    the flank height, which catches the Siasos 2010 23/69 pair (root stress 25-36 % off at
  ///    h_contact 0.25-0.4 mm, above its 0.19 mm flank height);
  ///  - Q1 only when neither the root stress nor p_max is asked, the mean STE tolerance is 3 %
  ///    or looser and the p-p one 5 % or looser (Q1 at m/30: mean 1.9 %, p-p 3.5 %, root
  ///    stress 1.9 %);
  ///  - full gears: sectors are 20-36 % stiff on the mean STE and gain at most 20 % of cost;
  ///  - the body and the unloaded teeth of a full gear sized for the target, not for every
  ///    question (body_size, unloaded_tooth_size).
  ModelChoice choose_model(const geometry::GearPair &pair, const mesh::GearMeshParameters given[2],
                           unsigned int degree, const AccuracyTarget &target, const FixedSettings &fixed,
                           double half_width = 0);
} // namespace gearfem::model_choice
