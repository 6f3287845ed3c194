// Accuracy-driven model choice (choice/). References:
// - parse_target: the grammar and the presets of `Solve/Target` (docs/model-choice.md);
// - choose_model: the rules stated in model_choice/choose.h (measured ladder, validation/speed_vs_error),
//   and the flank height r_SAP - r_Ff of the Siasos 2010 23/69 pair computed here from the
//   line of action and the form circle (0.190 mm in validation/RESULTS.md); the Hertz
//   half-width of the light-load rule in closed form (Johnson 1985);
// - fillet_resolution: the envelope of measured root-stress errors against h_fillet m/60
//   (four pairs, the table in the test);
// - estimate_relative: Richardson is exact for Q(h) = Q0 + C h^2 (closed form), with the
//   companion coarser or finer;
// - loaded_teeth: the path-of-contact kinematics (pinion tooth k at own roll phi1 + k tau,
//   loaded within A..E), and the same model with the fine sizes on teeth -3..3 (refining
//   only the loaded teeth changes no result; leaving out the early-loaded pair moves the
//   STE by 6 % at the last position of the pitch);
// - body_size, unloaded_tooth_size: their rules in closed form, and the Parker pair's ring
//   (the bore at half the root radius);
// - fixed_settings: what the input text sets;
// - swept_pp, swept_pp_estimate, abandon_sweep: the p-p and ripple of a sweep table and the
//   p-p estimate in closed form; the sweep stops only where refine_after_sweep's rules
//   (h_contact set, levels spent, cost cap) let a finer level follow;
// - run_to_target on 3-tooth sectors: the delivered estimate meets a loose target, and the
//   delivered level's samples equal a direct solve of that model (solver tolerance).
#include "model_choice/parameters.h"
#include "model_choice/to_target.h"
#include "common/fixtures.h"
#include "base/errors.h"
#include "base/units.h"
#include "solve/input.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace gearfem;
using model_choice::Quantity;

namespace
{
  solve::GearContactInput parse(const std::string &text, dealii::ParameterHandler &prm)
  {
    solve::declare_gear_contact_input(prm);
    prm.parse_input_from_string(text);
    return solve::parse_gear_contact_input(prm);
  }

  const char *seed001 = R"(
subsection Rack
  set Module = 4
end
subsection Gear 1
  set Number of teeth = 23
  set Face width      = 75
end
subsection Gear 2
  set Number of teeth = 69
  set Face width      = 70
end
)";
} // namespace

TEST(ChoiceTarget, ParsesListsPresetsAndRefusesBadText)
{
  const auto t = model_choice::parse_target("mean STE 1, p-p STE 2 %, root stress 3");
  EXPECT_DOUBLE_EQ(t[Quantity::mean_ste], 0.01);
  EXPECT_DOUBLE_EQ(t[Quantity::pp_ste], 0.02);
  EXPECT_DOUBLE_EQ(t[Quantity::root_stress], 0.03);
  EXPECT_FALSE(t.asks(Quantity::p_max));
  EXPECT_FALSE(model_choice::parse_target("none").active());
  const auto d = model_choice::parse_target("Dynamics tables");
  EXPECT_EQ(d.preset, "dynamics tables");
  EXPECT_DOUBLE_EQ(d[Quantity::mean_ste], 0.01);
  EXPECT_DOUBLE_EQ(d[Quantity::pp_ste], 0.02);
  EXPECT_DOUBLE_EQ(model_choice::parse_target("rating check")[Quantity::p_max], 0.05);
  for (const char *bad : {"mean STE", "mean STE 0", "mean STE 80", "stress 3", "mean STE 1, mean STE 2", "fast"})
    {
      try
        {
          model_choice::parse_target(bad);
          ADD_FAILURE() << bad;
        }
      catch (const InputError &e)
        {
          EXPECT_NE(std::string(e.what()).find("Solve/Target"), std::string::npos) << e.what();
        }
    }
}

TEST(ChoiceRules, FilletResolutionBoundsTheMeasuredRootStressErrors)
{
  // Reference: the measured errors of the fitted fillet peak against h_fillet m/60 (largest
  // of pinion and gear; h_contact m/45 by tiles, one single-contact position; Parker 50/50
  // m 3 at 200 N m, FZG type C at 183.4 N m, Siasos 2010 23/69 at 350 N m, 41/28 m 2.5 at
  // 150.5 N m), m/n for n = 6 ... 40. The resolution must cover every one of them (it is their
  // envelope) and fall with h, and it must not exceed the largest by more than 1.6 times
  // where the scatter is resolved (n >= 10): a bound, not a blanket.
  const double m = 4e-3;
  const std::vector<std::pair<int, double>> worst = {{6, 0.0180}, {7, 0.0087}, {8, 0.0112}, {10, 0.0089},
                                                     {12, 0.0076}, {15, 0.0053}, {20, 0.0036}, {30, 0.0013},
                                                     {40, 0.0010}};
  double before = 1;
  for (const auto &[n, e] : worst)
    {
      const double r = model_choice::fillet_resolution(m / n, m);
      EXPECT_GE(r, e * 0.999) << "m/" << n;
      if (n >= 10 && n <= 20)
        EXPECT_LE(r, 1.6 * e) << "m/" << n;
      EXPECT_LT(r, before);
      before = r;
    }
  // The first guess for a tight root-stress tolerance: the size whose resolution is within
  // tolerance / 1.1; m/12 (never coarser) for 3 %.
  dealii::ParameterHandler prm;
  auto in        = parse(test::parker_pair(), prm);
  const double mp = 3e-3;
  const auto c   = model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("root stress 0.5"), {});
  EXPECT_NEAR(model_choice::fillet_resolution(c.mesh[0].h_fillet, mp), 0.005 / 1.1, 1e-9);
  // fillet_size_for_resolution is its inverse.
  EXPECT_NEAR(model_choice::fillet_size_for_resolution(model_choice::fillet_resolution(mp / 20, mp), mp), mp / 20, 1e-15);
  EXPECT_LT(c.mesh[0].h_fillet, mp / 15);
  EXPECT_NEAR(model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("root stress 3"), {}).mesh[0].h_fillet,
              mp / 12, 1e-12);
}

TEST(ChoiceRules, FollowTheLadderAndCatchTheFlankHeight)
{
  dealii::ParameterHandler prm;
  auto in = parse(test::parker_pair(), prm);
  const double m = 3e-3;
  // The coarsest rung predicted within 1.1 x the tolerance (p-p: the run's own estimate, 1.3 %
  // at m/30, order 2): p-p 1 % -> m/45 (0.58 %); p-p 2 % -> m/30; p-p 0.5 % -> m/60 (0.33 %);
  // mean STE 1 % -> m/15 (0.86 %); root stress 3 %: h_fillet m/12.
  auto c = model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("p-p STE 1, root stress 3"), {});
  EXPECT_NEAR(c.mesh[0].h_contact, m / 45, 1e-12);
  EXPECT_NEAR(model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("p-p STE 2"), {}).mesh[0].h_contact,
              m / 30, 1e-12);
  EXPECT_NEAR(model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("p-p STE 0.5"), {}).mesh[0].h_contact,
              m / 60, 1e-12);
  EXPECT_NEAR(model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("mean STE 1"), {}).mesh[0].h_contact,
              m / 15, 1e-12);
  EXPECT_NEAR(model_choice::snap_finer(m / 25, m), m / 30, 1e-12);
  EXPECT_NEAR(model_choice::snap_finer(m / 47, m), m / 45, 1e-12); // within 10 %
  EXPECT_NEAR(c.mesh[0].h_fillet, m / 12, 1e-12);
  EXPECT_EQ(c.degree, 2u);
  // Loose STE only: Q1, the coarsest rung m/8 (predicted 3.0 %), coarse fillet.
  c = model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("mean STE 5"), {});
  EXPECT_EQ(c.degree, 1u);
  EXPECT_NEAR(c.mesh[0].h_contact, m / 8, 1e-12);
  EXPECT_NEAR(c.mesh[0].h_fillet, m / 8, 1e-12);
  // A set entry is kept.
  model_choice::FixedSettings fixed;
  fixed.h_contact = fixed.degree = true;
  in.mesh[0].h_contact = in.mesh[1].h_contact = 0.3e-3;
  c = model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("mean STE 5"), fixed);
  EXPECT_DOUBLE_EQ(c.mesh[0].h_contact, 0.3e-3);
  EXPECT_EQ(c.degree, 2u);

  // Siasos 2010 23/69: a root-stress target caps h_contact at the flank height.
  dealii::ParameterHandler prm2;
  const auto s = parse(seed001, prm2);
  const auto &pair = *s.pair;
  const double flank = std::min(pair.point("A").r1 - pair.gear(1).radii().form,
                                pair.point("E").r2 - pair.gear(2).radii().form);
  EXPECT_NEAR(flank, 0.190e-3, 0.005e-3);
  c = model_choice::choose_model(pair, s.mesh, 2, model_choice::parse_target("mean STE 2, root stress 3"), {});
  EXPECT_NEAR(c.flank_height, flank, 1e-12);
  EXPECT_LE(c.mesh[0].h_contact, flank * (1 + 1e-12));
  // Without a stress target the mean-STE rule alone (m/10 sqrt(2/1.94)) is coarser.
  c = model_choice::choose_model(pair, s.mesh, 2, model_choice::parse_target("mean STE 2"), {});
  EXPECT_GT(c.mesh[0].h_contact, flank);
}

TEST(ChoiceRules, ALightLoadRefinesTheFirstGuessAndKeepsTheModulesCompanion)
{
  // Siasos 2010 23/69 m 4 (75 / 70 mm) at 200 N m, the lightest of its torques: the Hertz
  // half-width at C in closed form (Johnson 1985, eq. 4.45, plane stress: 1/E* = 2/E), the
  // line load on the common 70 mm, w = T / (r_b1 b).
  dealii::ParameterHandler prm;
  const auto in = parse(std::string(seed001) + "subsection Solve\n  set Torques = 500, 200, 350\nend\n", prm);
  const double m = 4e-3, alpha = 20 * units::deg, rb1 = 46e-3 * std::cos(alpha), rb2 = 138e-3 * std::cos(alpha);
  const double R = rb1 * std::tan(alpha) * rb2 * std::tan(alpha) / ((rb1 + rb2) * std::tan(alpha));
  const double E = in.material[0].youngs_modulus, w = 200 / (rb1 * 70e-3);
  const double a = std::sqrt(4 * w * R / (units::pi * E / 2));
  EXPECT_NEAR(model_choice::lowest_torque_half_width(in), a, 1e-9 * a);
  EXPECT_NEAR(a, 0.0984e-3, 0.0005e-3); // docs/model-choice.md
  // p-p 1 %: the module's rung is m/45 (0.58 % predicted); with the half-width the p-p is at
  // least 2 % (h/a)^2: 1.63 % at m/45 (h/a 0.90), 0.92 % at m/60 -> m/60, and the companion is
  // sized from m/45 (ladder_h_contact).
  const auto target = model_choice::parse_target("p-p STE 1, root stress 3");
  auto c = model_choice::choose_model(*in.pair, in.mesh, 2, target, {}, a);
  EXPECT_NEAR(c.mesh[0].h_contact, m / 60, 1e-12);
  EXPECT_NEAR(c.ladder_h_contact, m / 45, 1e-12);
  EXPECT_NEAR(model_choice::predicted_error(Quantity::pp_ste, m / 45, m, a), 0.02 * std::pow(m / 45 / a, 2), 1e-12);
  EXPECT_NEAR(model_choice::predicted_error(Quantity::pp_ste, m / 45, m, 0), 0.013 * std::pow(30.0 / 45, 2), 1e-12);
  // A twice heavier patch (four times the load) or no half-width: the module's rung, one guess.
  for (const double aa : {2 * a, 0.0})
    {
      c = model_choice::choose_model(*in.pair, in.mesh, 2, target, {}, aa);
      EXPECT_NEAR(c.mesh[0].h_contact, m / 45, 1e-12);
      EXPECT_NEAR(c.ladder_h_contact, m / 45, 1e-12);
    }
  // The other quantities do not take the half-width.
  EXPECT_NEAR(model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("mean STE 1"), {}, a).mesh[0].h_contact,
              m / 15, 1e-12);
}

TEST(ChoiceEstimate, RichardsonIsExactForOrderTwo)
{
  // Two torques x four positions; Q(h) = Q0 + C h^2 per sample and quantity.
  const double h = 0.1e-3;
  auto level = [](double hh) {
    std::vector<solve::EstimatedQuantities> v;
    for (int t = 0; t < 2; ++t)
      for (int i = 0; i < 4; ++i)
        {
          solve::EstimatedQuantities q;
          q.ste                = (10 + i + t) * 1e-6 + (0.5 + 0.1 * i) * 1e-6 * std::pow(hh / 1e-4, 2);
          q.root_stress_pinion = (100 + 10 * i) * 1e6 * (1 - 0.01 * std::pow(hh / 1e-4, 2));
          q.root_stress_gear   = 80e6 * (1 + 0.02 * std::pow(hh / 1e-4, 2));
          q.p_max              = 600e6 * (1 + 0.03 * std::pow(hh / 1e-4, 2));
          v.push_back(q);
        }
    return v;
  };
  const auto a = level(h);
  for (const double rho : {2.0, 0.5, 1.6})
    {
      const auto b = level(rho * h);
      const auto e = model_choice::estimate_relative(a, b, 4, rho, rho, 2);
      // Exact relative errors of level a against Q0.
      double mean = 0, pp = 0, root = 0, p = 0;
      for (int t = 0; t < 2; ++t)
        {
          for (int i = 0; i < 4; ++i)
            {
              const auto &q = a[4 * t + i];
              mean = std::max(mean, (0.5 + 0.1 * i) * 1e-6 / q.ste);
              p    = std::max(p, 0.03 * 600e6 / q.p_max);
            }
          // STE highest at i = 3, lowest at i = 0: p-p error (0.8 - 0.5) um.
          pp   = std::max(pp, 0.3e-6 / (a[4 * t + 3].ste - a[4 * t].ste));
          root = std::max({root, 0.01 * 130e6 / a[4 * t + 3].root_stress_pinion, 0.02 * 80e6 / a[4 * t].root_stress_gear});
        }
      EXPECT_NEAR(e[0], mean, 1e-9 * mean) << rho;
      EXPECT_NEAR(e[1], pp, 1e-9 * pp) << rho;
      EXPECT_NEAR(e[2], root, 1e-9 * root) << rho;
      EXPECT_NEAR(e[3], p, 1e-9 * p) << rho;
    }
  // The zone middles only: STE errors (0.5 + 0.1 i) h^2 at i = 0, 2; p-p from their range.
  {
    const auto e = model_choice::estimate_relative(a, level(2 * h), 4, 2, 2, 2, nullptr, model_choice::zone_samples);
    double mean = 0, pp = 0;
    for (int t = 0; t < 2; ++t)
      {
        for (int i : {0, 2})
          mean = std::max(mean, (0.5 + 0.1 * i) * 1e-6 / a[4 * t + i].ste);
        pp = std::max(pp, 0.2e-6 / (a[4 * t + 2].ste - a[4 * t].ste));
      }
    EXPECT_NEAR(e[0], mean, 1e-9 * mean);
    EXPECT_NEAR(e[1], pp, 1e-9 * pp);
  }
  // With cycle weights, the mean STE's error is that of the weighted mean of the zone middles:
  // (0.6 x 0.5 + 0.4 x 0.7) h^2 over (0.6 Q_0 + 0.4 Q_2); the p-p is unchanged.
  {
    const auto e = model_choice::estimate_relative(a, level(2 * h), 4, 2, 2, 2, nullptr, model_choice::zone_samples, {0.6, 0.4});
    double mean = 0;
    for (int t = 0; t < 2; ++t)
      mean = std::max(mean, (0.6 * 0.5 + 0.4 * 0.7) * 1e-6 / (0.6 * a[4 * t].ste + 0.4 * a[4 * t + 2].ste));
    EXPECT_NEAR(e[0], mean, 1e-9 * mean);
    EXPECT_NEAR(e[1], model_choice::estimate_relative(a, level(2 * h), 4, 2, 2, 2, nullptr, model_choice::zone_samples)[1], 1e-15);
  }
  // A group that did not change has no estimate.
  const auto e = model_choice::estimate_relative(a, level(2 * h), 4, 1, 2, 2);
  EXPECT_TRUE(std::isnan(e[0]) && std::isnan(e[1]) && std::isnan(e[3]));
  EXPECT_TRUE(std::isfinite(e[2]));
}

TEST(ChoiceEstimate, ZoneWeightsAreTheShareOfEachZoneInAPitch)
{
  // Within one pitch from A, double contact lasts eps_alpha - 1 of it (A to B), single contact
  // the rest (B to D): the transverse contact ratio of the involute geometry.
  dealii::ParameterHandler prm;
  const auto in = parse(test::parker_pair(), prm);
  const auto w  = model_choice::zone_weights(*in.pair);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NEAR(w[0], in.pair->contact_ratio() - 1, 1e-9);
  EXPECT_NEAR(w[1], 2 - in.pair->contact_ratio(), 1e-9);
}

TEST(ChoiceRules, LoadedTeethAreThoseWhosePathOfContactCoversAPosition)
{
  // Pinion tooth k is at own roll phi1 + k tau; it carries load within [A, E]. Over one pitch
  // from A (eps_alpha 1.75 < 2): pairs 0 and 1 only; the 0.2-pitch margin adds pair -1, which
  // the FE loads early at the last positions of the pitch (Parker, 340 N m, 0.03 pitch
  // before A, validation/model_choice). At C alone: pair 0, and pairs 1 and -1 within the
  // margin (0.12 pitch beyond E and before A: the 50/50 pair is symmetric about C).
  dealii::ParameterHandler prm;
  const auto in     = parse(test::parker_pair(), prm);
  const double A    = in.pair->point("A").roll_angle;
  const double tau  = 2 * M_PI / 50;
  std::vector<double> pitch;
  for (int i = 0; i < 40; ++i)
    pitch.push_back(A + i * tau / 40);
  EXPECT_EQ(geometry::loaded_teeth(*in.pair, pitch, 0), (std::vector<int>{0, 1}));
  EXPECT_EQ(geometry::loaded_teeth(*in.pair, pitch), (std::vector<int>{-1, 0, 1}));
  EXPECT_EQ(geometry::loaded_teeth(*in.pair, {0.0}, 0), (std::vector<int>{0}));
  EXPECT_EQ(geometry::loaded_teeth(*in.pair, {0.0}), (std::vector<int>{-1, 0, 1}));
  EXPECT_EQ(mesh::fine_teeth_list({-1, 0, 2}, -1), "-2,0,1");
}

TEST(ChoiceRules, RefiningOnlyTheLoadedTeethChangesNoResult)
{
  // Conservation of the modelled physics: over a pitch from A at 1.5 times Parker's highest
  // torque (pairs load early under it), the fine sizes on the loaded teeth only (-1, 0, 1)
  // give the STE and root stresses of the same sizes on teeth -3..3. Coarse (m/10) so that
  // the teeth left coarse would show: a loaded coarse tooth moves the STE by percents.
  dealii::ParameterHandler prm;
  auto in = parse(test::parker_pair(R"(
subsection Mesh
  set h_contact = 0.3
  set h_fillet  = 0.5
  set Tiled teeth = true
end
)"),
                  prm);
  const double A   = in.pair->point("A").roll_angle;
  const double tau = 2 * M_PI / 50;
  std::vector<double> roll;
  for (int i = 0; i < 8; ++i)
    roll.push_back(A + i * tau / 8 + (i == 7 ? 0.1 * tau / 8 : 0)); // the last one close to A + tau
  const auto k = geometry::loaded_teeth(*in.pair, roll);
  ASSERT_EQ(k, (std::vector<int>{-1, 0, 1}));
  std::vector<solve::EstimatedQuantities> q[2];
  for (int wide = 0; wide < 2; ++wide)
    {
      mesh::GearMeshParameters g[2] = {in.mesh[0], in.mesh[1]};
      g[0].fine_teeth = wide ? "-3,-2,-1,0,1,2,3" : mesh::fine_teeth_list(k, 1);
      g[1].fine_teeth = wide ? "-3,-2,-1,0,1,2,3" : mesh::fine_teeth_list(k, -1);
      contact::GearContactModel model(*in.pair, g, in.material, in.fe, in.contact);
      model.observe_root_stress();
      q[wide] = solve::solve_samples(model, roll, {510.0}, post::PostOptions{});
    }
  for (std::size_t i = 0; i < roll.size(); ++i)
    {
      EXPECT_NEAR(q[0][i].ste, q[1][i].ste, 5e-4 * q[1][i].ste) << "position " << i;
      EXPECT_NEAR(q[0][i].root_stress_pinion, q[1][i].root_stress_pinion, 2e-3 * q[1][i].root_stress_pinion);
      EXPECT_NEAR(q[0][i].root_stress_gear, q[1][i].root_stress_gear, 2e-3 * q[1][i].root_stress_gear);
    }
}

TEST(ChoiceRules, SizeTheBodyAndTheUnloadedTeethForTheTarget)
{
  // The rules of model_choice/choose.h in closed form: h_body = max(given, min(1.5 m, ring / 6)),
  // h_tooth = min(h_body, 0.8 m); a set entry is kept.
  EXPECT_DOUBLE_EQ(model_choice::body_size(3e-3, 4e-3, 20.5e-3), 20.5e-3 / 6); // a 23-tooth pinion's ring
  EXPECT_DOUBLE_EQ(model_choice::body_size(3e-3, 4e-3, 66e-3), 6e-3);          // 1.5 m
  EXPECT_DOUBLE_EQ(model_choice::body_size(3e-3, 1e-3, 66e-3), 3e-3);          // never finer than given
  EXPECT_DOUBLE_EQ(model_choice::unloaded_tooth_size(6e-3, 4e-3), 3.2e-3);
  EXPECT_DOUBLE_EQ(model_choice::unloaded_tooth_size(3e-3, 4.5e-3), 3e-3);

  dealii::ParameterHandler prm;
  auto in = parse(test::parker_pair(), prm);
  const double m = 3e-3;
  // Parker 50/50 m 3, bore at half the root radius: ring r_f / 2 = 35.6 mm, so 1.5 m = 4.5 mm.
  const double r_f = in.pair->gear(1).radii().root;
  EXPECT_NEAR(r_f - mesh::inner_radius(in.mesh[0], in.pair->gear(1)), r_f / 2, 1e-12);
  auto c = model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("mean STE 1"), {});
  for (const auto &g : c.mesh)
    {
      EXPECT_NEAR(g.h_body, 1.5 * m, 1e-12);
      EXPECT_NEAR(mesh::tooth_size(g, m), 0.8 * m, 1e-12);
    }
  model_choice::FixedSettings fixed;
  fixed.h_body = fixed.h_tooth = true;
  in.mesh[0].h_body = in.mesh[1].h_body = 2.5e-3;
  c = model_choice::choose_model(*in.pair, in.mesh, 2, model_choice::parse_target("mean STE 1"), fixed);
  EXPECT_DOUBLE_EQ(c.mesh[0].h_body, 2.5e-3);
  EXPECT_DOUBLE_EQ(c.mesh[0].h_tooth, in.mesh[0].h_tooth);
}

TEST(ChoiceParameters, TellSetEntriesFromDefaults)
{
  dealii::ParameterHandler prm;
  parse(test::parker_pair("subsection Mesh\n  set h_fillet = 0.25\nend\nsubsection Finite elements\n  set Degree = 2\nend\n"),
        prm);
  const auto f = model_choice::fixed_settings(prm);
  EXPECT_TRUE(f.h_fillet);   // set, even to its default value
  EXPECT_TRUE(f.degree);
  EXPECT_FALSE(f.h_contact);
  EXPECT_FALSE(f.h_corner);
  EXPECT_FALSE(f.model);
  EXPECT_FALSE(f.h_body);
  EXPECT_FALSE(f.h_tooth);
  dealii::ParameterHandler prm2;
  parse(test::parker_pair("subsection Mesh\n  set h_body = 3\n  set h_tooth = 0\nend\n"), prm2);
  const auto g = model_choice::fixed_settings(prm2);
  EXPECT_TRUE(g.h_body);
  EXPECT_TRUE(g.h_tooth);
}

TEST(ChoiceRun, ProvesALooseTargetOnSectors)
{
  dealii::ParameterHandler prm;
  auto in = parse(test::parker_pair(R"(
subsection Mesh
  set Model = sector
  set Sector teeth = 3
end
subsection Solve
  set Torques = 200
end
)"),
                  prm);
  const auto fixed = model_choice::fixed_settings(prm);
  EXPECT_TRUE(fixed.model);
  model_choice::TargetOptions options;
  const auto o = model_choice::run_to_target(in, model_choice::parse_target("mean STE 3, root stress 10"), fixed, options);
  ASSERT_GE(o.levels.size(), 2u);
  EXPECT_EQ(o.levels.front().role, "companion");
  EXPECT_EQ(o.delivered_level().role, "delivered");
  EXPECT_TRUE(o.met);
  const auto &d = o.delivered_level();
  EXPECT_LE(d.estimate[0], 0.03);
  EXPECT_LE(d.estimate[2], 0.10);
  EXPECT_DOUBLE_EQ(in.mesh[0].h_contact, d.h_contact);
  EXPECT_EQ(in.fe.degree, d.degree);
  ASSERT_TRUE(o.model);
  // The delivered model is the one sampled: a direct solve at the first sample agrees.
  const auto q = solve::solve_samples(*o.model, {o.positions[0]}, {200.0}, options.post);
  EXPECT_NEAR(q[0].ste, d.samples[0].ste, 1e-7 * d.samples[0].ste);
  EXPECT_NE(model_choice::model_choice_json(o).find("\"met\": true"), std::string::npos);
}

TEST(ChoiceRipple, ZeroOnACubicAndEightThirdsOfAnAlternatingRipple)
{
  // The leave-one-out quadratic through two neighbours on each side reproduces a cubic exactly
  // (its odd part is fitted by the linear term); an alternating +-d on top gives |r| = 8 d / 3
  // at every interior position (closed form of the symmetric least-squares fit).
  std::vector<double> x, smooth, rippled;
  const double d = 0.01e-6;
  for (int i = 0; i < 40; ++i)
    {
      x.push_back(-6.3 + 0.18 * i);
      const double s = 4e-6 + 0.02e-6 * x.back() - 0.003e-6 * x.back() * x.back() + 1e-10 * std::pow(x.back(), 3);
      smooth.push_back(s);
      rippled.push_back(s + (i % 2 ? d : -d));
    }
  EXPECT_NEAR(model_choice::ste_ripple(x, smooth), 0, 1e-18);
  EXPECT_NEAR(model_choice::ste_ripple(x, rippled), 8 * d / 3, 1e-6 * d);
  EXPECT_EQ(model_choice::ste_ripple({0, 1, 2}, {1, 2, 3}), 0);
  // An even count takes the mean of the two middle residuals: a spike s at position 2 of 8
  // (weights 2/3 at +-1, -1/6 at +-2) leaves residuals s, 2/3 s, 1/6 s, 0 at positions 2-5;
  // the median is (2/3 + 1/6) s / 2 = 5 s / 12.
  EXPECT_NEAR(model_choice::ste_ripple({0, 1, 2, 3, 4, 5, 6, 7}, {0, 0, 1e-6, 0, 0, 0, 0, 0}), 5e-6 / 12, 1e-18);
}

TEST(ChoiceSweep, SweptPpIsEachTorquesRangeUpToTheFirstTorqueNotSwept)
{
  // sweep.csv units: deg, um; SweptPp in m. Torque 200 has rows, 300 none (a stopped sweep).
  Table t;
  t.add_column("torque", "N m");
  t.add_column("roll angle", "deg");
  t.add_column("STE", "um");
  for (const double T : {100.0, 200.0})
    for (int i = 0; i < 8; ++i)
      t.add_row({T, -3.0 + i, T / 100 * (4 + (i == 5 ? 1.5 : 0.0) - 0.1 * i)});
  const auto s = model_choice::swept_pp(t, {100, 200, 300});
  ASSERT_EQ(s.pp.size(), 2u);
  ASSERT_EQ(s.ripple.size(), 2u);
  // max 4 + 1.5 - 0.5 = 5.0 at i = 5, min 4 - 0.7 = 3.3 at i = 7 (times T/100).
  EXPECT_NEAR(s.pp[0], 1.7e-6, 1e-15);
  EXPECT_NEAR(s.pp[1], 3.4e-6, 1e-15);
  std::vector<double> x, y;
  for (int i = 0; i < 8; ++i)
    x.push_back(-3.0 + i), y.push_back(2 * (4 + (i == 5 ? 1.5 : 0.0) - 0.1 * i) * 1e-6);
  EXPECT_NEAR(s.ripple[1], model_choice::ste_ripple(x, y), 1e-18);
  EXPECT_TRUE(model_choice::swept_pp(t, {300, 100}).pp.empty());
}

TEST(ChoiceSweep, AbandonsASweepOnlyWhereTheRefinementFollows)
{
  // A delivered level against its companion (rho 2, order 2: e = (b - a) / (1 - 4)), three
  // torques, four samples each. At the zone samples 0 and 2 the companion differs by 0 and
  // 0.108 um: the Richardson part of the p-p error is 0.036 um; with a swept p-p of 4 um and a
  // ripple r, the estimate is sqrt(0.036^2 + (2 r)^2) um / 4 um (closed form of
  // swept_pp_estimate: independent parts, root sum of squares).
  dealii::ParameterHandler prm;
  auto in = parse(test::parker_pair("subsection Solve\n  set Torques = 100, 200, 300\nend\n"), prm);
  model_choice::TargetOutcome o;
  o.target    = model_choice::parse_target("p-p STE 1");
  o.torques   = {100, 200, 300};
  o.positions = {0, 0.01, 0.02, 0.03};
  model_choice::Level companion, delivered;
  for (int t = 0; t < 3; ++t)
    for (int i = 0; i < 4; ++i)
      {
        solve::EstimatedQuantities q;
        q.ste = (4 + (i == 2 ? 3.0 : 0.0)) * 1e-6;
        delivered.samples.push_back(q);
        q.ste += i == 2 ? 0.108e-6 : 0;
        companion.samples.push_back(q);
      }
  companion.role = "companion";
  delivered.role = "delivered";
  delivered.rho_contact = 2;
  delivered.estimate.fill(std::nan(""));
  delivered.seconds_setup = 0.5;
  o.levels    = {companion, delivered};
  o.delivered = 1;
  in.mesh[0].h_contact = in.mesh[1].h_contact = 0.1e-3;
  const model_choice::FixedSettings fixed{};
  model_choice::TargetOptions options;

  const model_choice::SweptPp small{{4e-6}, {0.005e-6}}, large{{4e-6}, {0.024e-6}};
  EXPECT_NEAR(model_choice::swept_pp_estimate(o, small), std::hypot(0.036, 0.01) / 4, 1e-9);
  EXPECT_NEAR(model_choice::swept_pp_estimate(o, large), std::hypot(0.036, 0.048) / 4, 1e-9);
  // Never below either part: the ripple part is the p-p's resolution.
  model_choice::PpParts parts;
  model_choice::swept_pp_estimate(o, large, &parts);
  EXPECT_NEAR(parts.richardson, 0.009, 1e-9);
  EXPECT_NEAR(parts.twice_ripple, 0.012, 1e-9);
  EXPECT_NEAR(parts.resolution, 0.012, 1e-9);
  // 0.93 % meets the 1 % target: the sweep goes on; 1.5 % does not: it stops.
  EXPECT_FALSE(model_choice::abandon_sweep(o, in, fixed, options, small, 1, 0.3));
  EXPECT_TRUE(model_choice::abandon_sweep(o, in, fixed, options, large, 1, 0.3));
  // Where the refinement would not follow, the sweep is not stopped: h_contact set in the
  // input, the levels spent, the cost cap exceeded: 1.5 % asks for h / 1.47, the rung m/45
  // (h / 1.5), whose run takes about (0.5 s + 3 x 0.3 s) x 1.5^1.5 = 2.57 s after 0.3 s spent.
  model_choice::FixedSettings set_h = fixed;
  set_h.h_contact = true;
  EXPECT_FALSE(model_choice::abandon_sweep(o, in, set_h, options, large, 1, 0.3));
  model_choice::TargetOptions spent = options;
  spent.max_levels = 1;
  EXPECT_FALSE(model_choice::abandon_sweep(o, in, fixed, spent, large, 1, 0.3));
  model_choice::TargetOptions capped = options;
  capped.cost_cap = 2.0;
  EXPECT_FALSE(model_choice::abandon_sweep(o, in, fixed, capped, large, 1, 0.3));
  capped.cost_cap = 3.5;
  EXPECT_TRUE(model_choice::abandon_sweep(o, in, fixed, capped, large, 1, 0.3));
  // A torque not yet swept gives no verdict.
  EXPECT_FALSE(model_choice::abandon_sweep(o, in, fixed, options, large, 2, 0.3));
  // rescale_pp takes the same estimate and updates `met`.
  model_choice::rescale_pp(o, large);
  EXPECT_NEAR(o.delivered_level().estimate[1], 0.015, 1e-9);
  EXPECT_FALSE(o.met);
  // ... and keeps its parts: 0.036 / 4 Richardson, 2 x 0.024 / 4 ripple, at the first torque.
  EXPECT_NEAR(o.delivered_level().pp_richardson, 0.009, 1e-9);
  EXPECT_NEAR(o.delivered_level().pp_ripple, 0.012, 1e-9);
  EXPECT_NEAR(o.delivered_level().pp_resolution, 0.012, 1e-9);
  EXPECT_DOUBLE_EQ(o.delivered_level().pp_torque, 100);
  model_choice::rescale_pp(o, small);
  EXPECT_TRUE(o.met);
}
