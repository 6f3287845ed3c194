#include "model_choice/to_target.h"

#include "mesh/gear_mesh.h"

#include "base/errors.h"
#include "base/progress.h"
#include "base/units.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace gearfem::model_choice
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();


    /// The sizes of one level.
    struct Sizes
    {
      mesh::GearMeshParameters mesh[2];
      unsigned int degree = 2;
    };

    /// Scale the contact group (h_contact; h_corner follows it) and the fillet group
    /// (h_fillet; h_coast follows it when 0) of both gears.
    Sizes scaled(const Sizes &s, double contact, double fillet)
    {
      Sizes o = s;
      for (auto &g : o.mesh)
        {
          g.h_contact *= contact;
          if (g.h_corner > 0)
            g.h_corner *= contact;
          g.h_fillet = std::min(g.h_fillet * fillet, g.h_body);
          g.h_contact = std::min(g.h_contact, g.h_body);
        }
      return o;
    }

    std::string mm_3(double v)
    {
      std::ostringstream o;
      o << std::setprecision(3) << v * 1e3;
      return o.str();
    }

    std::string pc(double v)
    {
      if (!std::isfinite(v))
        return "-";
      std::ostringstream o;
      o << std::fixed << std::setprecision(v < 0.001 ? 3 : 2) << v * 100 << " %";
      return o.str();
    }

    std::string json(double v)
    {
      if (!std::isfinite(v))
        return "null";
      std::ostringstream o;
      o << std::setprecision(8) << v;
      return o.str();
    }

    /// Build `sizes` on `in`'s pair and solve the samples: one Level.
    /// Build `sizes` on `in`'s pair and solve the samples: one Level. Where gmsh's first quad
    /// recombination fails (or gmsh returns a mesh with an inverted cell), the fillets and the
    /// other teeth are made 15 % finer and meshed again, now with gmsh's slow retries and subdivision fallback
    /// allowed, at most twice: a slightly finer fillet keeps the
    /// accuracy asked for and avoids the retries and the subdivision fallback (FZG type C: 18-33 s
    /// of set-up instead of 3.5 s). `sizes` returns the sizes built.
    Level solve_level(const solve::GearContactInput &in, Sizes &sizes, const std::string &role,
                      const TargetOutcome &o, const TargetOptions &options,
                      std::unique_ptr<contact::GearContactModel> &model)
    {
      Level l;
      l.role      = role;
      l.degree    = sizes.degree;
      fem::FeOptions fe = in.fe;
      fe.degree         = sizes.degree;
      const auto t0     = Clock::now();
      if (options.out)
        *options.out << "model choice: " << role << " level " << o.levels.size() + 1 << ", h_contact "
                     << mm_3(sizes.mesh[0].h_contact) << " mm, h_fillet " << mm_3(sizes.mesh[0].h_fillet) << " mm, Q"
                     << l.degree << std::endl;
      for (int attempt = 0;; ++attempt)
        {
          for (auto &g : sizes.mesh)
            g.quad_fallbacks = attempt >= 1;
          try
            {
              model = std::make_unique<contact::GearContactModel>(*in.pair, sizes.mesh, in.material, fe, in.contact,
                                                                  in.unmodified_pair.get());
              break;
            }
          catch (const InputError &e)
            {
              // gmsh's first recombination failed (fallbacks off), or a mesh it produced is
              // unusable (an inverted cell: rand2 of validation/model_choice at m/45): the sizes
              // are ours to nudge. Anything else, or a third failure, is the input's.
              const bool recombination = dynamic_cast<const mesh::RecombinationFailed *>(&e) != nullptr;
              if (e.parameter() != "Mesh" || attempt >= 2)
                throw;
              for (int i = 0; i < 2; ++i)
                {
                  auto &g = sizes.mesh[i];
                  // The other teeth too, where an inverted cell also appears.
                  g.h_tooth = 0.85 * mesh::tooth_size(g, in.pair->gear(i + 1).parameters().rack.module);
                  g.h_fillet *= 0.85;
                }
              ++l.remeshed;
              if (options.out)
                *options.out << "model choice: " << (recombination ? "quad recombination failed" : "gmsh mesh refused")
                             << "; h_fillet " << mm_3(sizes.mesh[0].h_fillet) << " mm" << std::endl;
            }
        }
      for (auto &g : sizes.mesh)
        g.quad_fallbacks = true;
      l.h_contact     = sizes.mesh[0].h_contact;
      l.h_fillet      = sizes.mesh[0].h_fillet;
      l.seconds_setup = since(t0);
      l.dofs          = model->n_dofs();
      // Root stresses and reactions from influence coefficients, as the sweep takes them: no
      // displacement field per sample, and the columns the samples compute stay cached for
      // the sweep of the delivered level.
      model->observe_root_stress();
      l.subdivided    = model->body(1).mesh().subdivided || model->body(2).mesh().subdivided;
      const auto t1   = Clock::now();
      Progress progress(options.out, o.positions.size() * o.torques.size(), "model-choice sample");
      l.samples         = solve::solve_samples(*model, o.positions, o.torques, options.post, &progress, 0, role);
      l.seconds_samples = since(t1);
      l.estimate.fill(nan);
      return l;
    }

    /// The factor by which a group must shrink for its worst ratio estimate / tolerance
    /// (order p, safety 1.2), within [1.3, 3]. At least 1.3, so that h_contact, snapped to the
    /// rung within 10 %, moves at least to the next rung (m/45 to m/60); at least 1.5 took
    /// m/45 to m/90, and the Siasos 2010 23/69 pair, 10 % above a 1 % p-p target at m/45, paid
    /// a level with 1.4 times the DoFs of m/60.
    double refinement(double worst, double p)
    {
      return std::clamp(1.2 * std::pow(worst, 1.0 / p), 1.3, 3.0);
    }
  } // namespace

  const std::vector<std::size_t> zone_samples = {0, 2};

  std::vector<double> zone_weights(const geometry::GearPair &pair)
  {
    const double A = pair.point("A").roll_angle, B = pair.point("B").roll_angle, D = pair.point("D").roll_angle;
    const double w = (B - A) / (D - A);
    if (!(w > 0 && w < 1))
      return {};
    return {w, 1 - w};
  }

  std::vector<double> target_sample_positions(const geometry::GearPair &pair)
  {
    const double A = pair.point("A").roll_angle, B = pair.point("B").roll_angle, D = pair.point("D").roll_angle;
    return {0.5 * (A + B), B, 0.5 * (B + D), D};
  }

  std::array<double, n_quantities> estimate_relative(const std::vector<solve::EstimatedQuantities> &a,
                                                     const std::vector<solve::EstimatedQuantities> &b,
                                                     std::size_t n_positions, double rho_contact,
                                                     double rho_fillet, double p, const std::vector<double> *pp_sweep,
                                                     const std::vector<std::size_t> &ste_samples,
                                                     const std::vector<double> &mean_weights)
  {
    auto ste_sample = [&](std::size_t i) {
      return ste_samples.empty() || std::find(ste_samples.begin(), ste_samples.end(), i) != ste_samples.end();
    };
    // The weight of sample i in the cycle mean; NaN: the mean STE takes the largest |e|/Q.
    const bool weighted = !ste_samples.empty() && mean_weights.size() == ste_samples.size();
    auto weight = [&](std::size_t i) {
      return mean_weights[std::size_t(std::find(ste_samples.begin(), ste_samples.end(), i) - ste_samples.begin())];
    };
    std::array<double, n_quantities> r{};
    // A group whose size changed by less than 20 % gives no estimate: 1/(1 - rho^p) would
    // amplify the noise of non-nested meshes (a 15 % nudge: factor 2.6).
    const bool contact = std::abs(rho_contact - 1) > 0.2, fillet = std::abs(rho_fillet - 1) > 0.2;
    const double fc = contact ? 1 / (1 - std::pow(rho_contact, p)) : 0;
    const double ff = fillet ? 1 / (1 - std::pow(rho_fillet, p)) : 0;
    const std::size_t n_t = n_positions ? a.size() / n_positions : 0;
    for (std::size_t t = 0; t < n_t; ++t)
      {
        const std::size_t k0 = t * n_positions;
        std::size_t hi = n_positions, lo = n_positions; // none yet
        double sum_we = 0, sum_wq = 0;                 // the cycle mean's error and value
        for (std::size_t k = k0; k < k0 + n_positions; ++k)
          {
            if (a[k].p_max > 0)
              r[3] = std::max(r[3], std::abs((b[k].p_max - a[k].p_max) * fc / a[k].p_max));
            if (!ste_sample(k - k0))
              continue;
            const double e = (b[k].ste - a[k].ste) * fc;
            if (weighted)
              sum_we += weight(k - k0) * e, sum_wq += weight(k - k0) * a[k].ste;
            else if (a[k].ste != 0)
              r[0] = std::max(r[0], std::abs(e / a[k].ste));
            hi = hi == n_positions || a[k].ste > a[hi].ste ? k : hi;
            lo = lo == n_positions || a[k].ste < a[lo].ste ? k : lo;
          }
        if (weighted && sum_wq != 0)
          r[0] = std::max(r[0], std::abs(sum_we / sum_wq));
        if (hi == n_positions)
          continue;
        const double pp = pp_sweep && t < pp_sweep->size() ? (*pp_sweep)[t] : a[hi].ste - a[lo].ste;
        if (pp > 0)
          r[1] = std::max(r[1], std::abs(((b[hi].ste - a[hi].ste) - (b[lo].ste - a[lo].ste)) * fc / pp));
        for (int g = 1; g <= 2; ++g)
          {
            auto stress = [g](const solve::EstimatedQuantities &q) {
              return g == 1 ? q.root_stress_pinion : q.root_stress_gear;
            };
            std::size_t m = k0;
            for (std::size_t k = k0; k < k0 + n_positions; ++k)
              m = stress(a[k]) > stress(a[m]) ? k : m;
            if (stress(a[m]) > 0)
              r[2] = std::max(r[2], std::abs((stress(b[m]) - stress(a[m])) * ff / stress(a[m])));
          }
      }
    if (!contact)
      r[0] = r[1] = r[3] = nan;
    if (!fillet)
      r[2] = nan;
    return r;
  }

  namespace
  {
    /// The candidate loop of run_to_target from `cand` on (its companion: the last level of
    /// `o`), `spent` seconds already spent; sets the delivered level, `in`'s sizes and o.model.
    void iterate(TargetOutcome &o, solve::GearContactInput &in, const FixedSettings &fixed,
                 const TargetOptions &options, Sizes cand, std::array<double, n_quantities> carried,
                 std::unique_ptr<contact::GearContactModel> model, double spent)
    {
      const auto t0 = Clock::now();
      const AccuracyTarget &target = o.target;
      const double m = in.pair->gear(1).parameters().rack.module;
      const std::size_t sweep_positions = in.positions().size() * o.torques.size();
      for (;;)
        {
          Level l = solve_level(in, cand, "candidate", o, options, model);
          // Richardson against the companion, the coarsest level, from the sizes built: the
          // largest ratio rho amplifies the level-to-level scatter of non-nested meshes least,
          // by 1/(rho^2 - 1): 0.33 at rho = 2, 0.16 at 2.7 (a refined level against the
          // companion), 1.29 at 4/3 (a refined level against the one before it: Siasos 2010
          // 23/69 with its bodies at h_body 3.4 / 6 mm, m/60 against m/45 estimated the p-p at
          // 1.14 % where m/90 showed m/60 converged, and a fourth level followed).
          const Level &ref   = o.levels.front();
          const double rho_c = ref.h_contact / l.h_contact;
          const double rho_f = ref.h_fillet / l.h_fillet;
          l.rho_contact = rho_c;
          l.rho_fillet  = rho_f;
          l.estimate  = estimate_relative(l.samples, ref.samples, o.positions.size(), rho_c, rho_f, options.order,
                                          nullptr, zone_samples, o.mean_weights);
          for (int q = 0; q < n_quantities; ++q)
            if (!std::isfinite(l.estimate[q]))
              l.estimate[q] = carried[q];
          // Two levels cannot resolve a root-stress error below the fillet mesh's resolution:
          // the estimate is never smaller (fillet_resolution).
          constexpr int root = static_cast<int>(Quantity::root_stress);
          l.fillet_resolution = fillet_resolution(l.h_fillet, m);
          if (std::isfinite(l.estimate[root]))
            l.estimate[root] = std::max(l.estimate[root], l.fillet_resolution);
          double worst_c = 0, worst_f = 0;
          for (int q = 0; q < n_quantities; ++q)
            if (target.tolerance[q] > 0)
              {
                const double ratio = std::isfinite(l.estimate[q]) ? l.estimate[q] / target.tolerance[q] : 2.0;
                if (ratio > 1)
                  (q == root ? worst_f : worst_c) =
                    std::max(q == root ? worst_f : worst_c, ratio);
              }
          o.levels.push_back(l);
          if (worst_c == 0 && worst_f == 0)
            {
              o.met = true;
              break;
            }
          if (fixed.h_contact)
            worst_c = 0;
          if (fixed.h_fillet)
            worst_f = 0;
          if (worst_c == 0 && worst_f == 0)
            {
              o.stop_reason = "the sizes the failing quantities need are set in the input";
              break;
            }
          if (o.levels.size() - 1 >= static_cast<std::size_t>(options.max_levels))
            {
              o.stop_reason = "Solve/Target: " + std::to_string(options.max_levels) + " candidate levels tried";
              break;
            }
          // The contact group moves to the rung at or below h / factor.
          const double h_now = cand.mesh[0].h_contact;
          const double fc = worst_c > 0 ? h_now / snap_finer(h_now / refinement(worst_c, options.order), m) : 1;
          // Where the resolution is the estimate, it falls with fillet_resolution_order, not p.
          const bool at_resolution = l.estimate[root] <= l.fillet_resolution;
          const double ff =
            worst_f > 0 ? refinement(worst_f, at_resolution ? fillet_resolution_order : options.order) : 1;
          const double per_position = l.seconds_samples / std::max<std::size_t>(1, l.samples.size());
          const double next = (l.seconds_setup + per_position * sweep_positions) * std::pow(std::max(fc, ff), 1.5);
          if (options.cost_cap > 0 && spent + since(t0) + next > options.cost_cap)
            {
              std::ostringstream s;
              s << std::setprecision(3) << "the next level (refined " << fc << " x on the contact, " << ff
                << " x on the fillet) would take about " << next << " s, beyond Solve/Cost cap " << options.cost_cap
                << " s";
              o.stop_reason = s.str();
              break;
            }
          // The mesh limit of one machine: stop before a level that meshing would refuse, with
          // an entry (Mesh/h_body, Mesh/Model) the input may never have set.
          const Sizes finer = scaled(cand, 1 / fc, 1 / ff);
          std::string beyond;
          if (!in.pair->is_internal())
            for (int i = 0; i < 2 && beyond.empty(); ++i)
              {
                const double cells = mesh::estimated_cells(finer.mesh[i], in.pair->gear(i + 1));
                if (!(cells <= mesh::max_cells))
                  {
                    std::ostringstream s;
                    s << std::setprecision(3) << "the next level (refined " << fc << " x on the contact, " << ff
                      << " x on the fillet) would mesh gear " << i + 1 << " with about " << cells
                      << " cells, beyond the " << mesh::max_cells << " of one machine";
                    beyond = s.str();
                  }
              }
          if (!beyond.empty())
            {
              o.stop_reason = beyond;
              break;
            }
          if (options.out)
            *options.out << "model choice: estimate above the target; refining h_contact by " << fc << ", h_fillet by "
                         << ff << std::endl;
          model.reset();
          carried = l.estimate;
          cand    = finer;
        }
      o.delivered          = o.levels.size() - 1;
      o.levels.back().role = "delivered";
      in.mesh[0]           = cand.mesh[0];
      in.mesh[1]           = cand.mesh[1];
      in.fe.degree         = cand.degree;
      o.model              = std::move(model);
      o.seconds            = spent + since(t0);
    }
  } // namespace

  namespace
  {
    /// Full gears, Mesh/Fine teeth left at auto: the fine sizes go
    /// to the teeth the swept and sampled positions load (geometry::loaded_teeth), not to the five
    /// teeth around tooth 0 that `auto` refines for any position.
    void restrict_fine_teeth(const solve::GearContactInput &in, TargetOutcome &o, Sizes &cand)
    {
      for (const auto &g : cand.mesh)
        if (g.model != mesh::GearMeshParameters::Model::full_gear || g.fine_teeth != "auto")
          return;
      const std::vector<int> k = in.loaded_teeth(o.positions);
      if (k.size() >= 5)
        return;
      cand.mesh[0].fine_teeth = mesh::fine_teeth_list(k, 1);
      cand.mesh[1].fine_teeth = mesh::fine_teeth_list(k, -1);
      o.choice.reasons.push_back("fine teeth " + cand.mesh[0].fine_teeth + " (pinion) and " + cand.mesh[1].fine_teeth +
                                 " (gear): the teeth the swept positions load, with a margin of 0.2 pitch beyond A "
                                 "and E for the contact a loaded pair makes early; the other teeth keep the coarse "
                                 "size (Parker 50/50 at m/45: 157 000 to 122 000 DoFs, 16 % less CPU, errors "
                                 "against the reference mean STE 0.032 / p-p 0.19 / root stress 0.62 % instead of "
                                 "0.026 / 0.20 / 0.63 %)");
    }
  } // namespace

  double lowest_torque_half_width(const solve::GearContactInput &in)
  {
    if (in.solve.torques.empty())
      return 0;
    analytical::PlaneElastic e[2];
    for (int i = 0; i < 2; ++i)
      {
        const auto &m = in.material[i];
        e[i]          = analytical::plane_elastic({m.youngs_modulus, m.poisson_ratio},
                                         m.model == fem::PlaneModel::plane_stress ?
                                                    analytical::PlaneCondition::plane_stress :
                                                    analytical::PlaneCondition::plane_strain);
      }
    double T = 0; // the smallest non-zero |torque|: a zero torque has no contact to resolve
    for (const double t : in.solve.torques)
      if (t != 0 && (T == 0 || std::abs(t) < T))
        T = std::abs(t);
    return contact_half_width(*in.pair, e[0], e[1], T);
  }

  TargetOutcome run_to_target(solve::GearContactInput &in, const AccuracyTarget &target, const FixedSettings &fixed,
                              const TargetOptions &options)
  {
    in.require_external("Solve/Target");
    if (!target.active())
      throw InputError("Solve/Target", "none", "at least one tolerance");
    const auto t0 = Clock::now();
    TargetOutcome o;
    o.target    = target;
    o.order     = options.order;
    o.choice    = choose_model(*in.pair, in.mesh, in.fe.degree, target, fixed, lowest_torque_half_width(in));
    o.positions = target_sample_positions(*in.pair);
    o.mean_weights = zone_weights(*in.pair);
    o.torques   = in.solve.torques;
    Sizes cand;
    cand.mesh[0] = o.choice.mesh[0];
    cand.mesh[1] = o.choice.mesh[1];
    cand.degree  = o.choice.degree;
    // Full gears by tiles: gmsh's time no longer grows with the teeth, so a level costs its
    // solves (validation/model_choice); `Mesh/Tiled teeth`, when set, decides.
    if (!fixed.tiled)
      for (auto &g : cand.mesh)
        g.tiled = true;
    restrict_fine_teeth(in, o, cand);
    const double m = in.pair->gear(1).parameters().rack.module;
    const bool asks_contact = target.asks(Quantity::mean_ste) || target.asks(Quantity::pp_ste) ||
                              target.asks(Quantity::p_max);
    const bool asks_fillet = target.asks(Quantity::root_stress);

    // The companion: coarser by 2 where the asked quantities live, but inside the range where
    // the error is asymptotic (p-p STE: m/20; root stress and p_max: the flank height); where
    // that leaves less than a factor 1.4, finer by 2 instead. Where the light load made the
    // first guess finer than the module's rung (ModelChoice::ladder_h_contact), the companion
    // is that rung's, as for a level the proof refined (step 4): Richardson amplifies the
    // level-to-level scatter by 1/(rho^2 - 1), 0.16 at the 2.67 of m/60 against m/22.5 and
    // 0.33 at 2 (the Siasos 2010 23/69 pair at m/60: p-p estimate 0.83 % against m/22.5, 1.01 %
    // against m/30).
    const double h_cand  = cand.mesh[0].h_contact;
    const double h_rung  = fixed.h_contact ? h_cand : std::max(h_cand, o.choice.ladder_h_contact);
    double rc = asks_contact ? 2 * h_rung / h_cand : 1, rf = asks_fillet ? 2 : 1;
    if (asks_contact || asks_fillet)
      {
        double h_max = target.asks(Quantity::pp_ste) ? m / 20 : m / 8;
        if ((asks_fillet || target.asks(Quantity::p_max)) && o.choice.flank_height > 0)
          h_max = std::min(h_max, o.choice.flank_height);
        const double h = cand.mesh[0].h_contact;
        if (rc == 1 && asks_fillet)
          rc = 1; // the root stress alone: the contact group stays
        else
          rc = std::min(rc, h_max / h);
        if (rc < 1.4 && asks_contact)
          rc = 0.5;
        else if (rc < 1.4)
          rc = 1;
      }
    std::unique_ptr<contact::GearContactModel> model;
    Sizes companion = scaled(cand, rc, rf);
    // A coarser companion also has coarser unloaded teeth (h_tooth, by the larger factor, up
    // to unloaded_tooth_size, never finer than the candidate's): they carry no load, and
    // h_tooth 0.8 m instead of 0.4 m moves the mean STE by 0.003 %, the p-p and the root
    // stress by 0.001 % (Parker 50/50, Siasos 2010 23/69), while the set-up falls by a fifth
    // (Siasos: 108 000 to 90 000 DoFs, 1.32 to 1.06 s). Where the choice sized the unloaded
    // teeth (0.8 m), they are the candidate's. The body keeps its size: at 2 h_body the Siasos
    // mean STE moved by 0.05 % and the mean STE estimate of the delivered level rose from 0.07
    // to 0.17 % for a true 0.035 %.
    if (rc >= 1 && rf >= 1 && std::max(rc, rf) >= 1.4)
      for (int i = 0; i < 2; ++i)
        {
          auto &g         = companion.mesh[i];
          const double mi = in.pair->gear(i + 1).parameters().rack.module;
          const double h  = mesh::tooth_size(g, mi);
          g.h_tooth       = std::max(h, std::min(unloaded_tooth_size(g.h_body, mi), std::max(rc, rf) * h));
        }
    o.levels.push_back(solve_level(in, companion, "companion", o, options, model));
    model.reset();

    std::array<double, n_quantities> carried;
    carried.fill(nan);
    iterate(o, in, fixed, options, cand, carried, std::move(model), since(t0));
    return o;
  }

  double ste_ripple(const std::vector<double> &roll, const std::vector<double> &ste)
  {
    std::vector<double> r;
    for (std::size_t i = 2; i + 2 < ste.size(); ++i)
      {
        // Least-squares quadratic through i-2, i-1, i+1, i+2 (x from roll[i]), its value at i.
        double S[5] = {0, 0, 0, 0, 0}, T[3] = {0, 0, 0};
        for (const std::size_t j : {i - 2, i - 1, i + 1, i + 2})
          {
            const double x = roll[j] - roll[i];
            double xk      = 1;
            for (int k = 0; k < 5; ++k, xk *= x)
              {
                S[k] += xk;
                if (k < 3)
                  T[k] += xk * ste[j];
              }
          }
        // Normal equations [S0 S1 S2; S1 S2 S3; S2 S3 S4] c = T; c0 by Cramer's rule.
        auto det = [](double a, double b, double c, double d, double e, double f, double g, double h, double k) {
          return a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g);
        };
        const double D = det(S[0], S[1], S[2], S[1], S[2], S[3], S[2], S[3], S[4]);
        if (D == 0)
          continue;
        const double c0 = det(T[0], S[1], S[2], T[1], S[2], S[3], T[2], S[3], S[4]) / D;
        r.push_back(std::abs(ste[i] - c0));
      }
    if (r.size() < 4)
      return 0;
    // The median: the middle value, or the mean of the two middle ones.
    const std::size_t k = r.size() / 2;
    std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(k), r.end());
    const double upper = r[k];
    if (r.size() % 2)
      return upper;
    return 0.5 * (upper + *std::max_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(k)));
  }

  SweptPp swept_pp(const Table &sweep, const std::vector<double> &torques)
  {
    SweptPp r;
    const auto T_col = sweep.column("torque"), roll = sweep.column("roll angle"), ste = sweep.column("STE");
    for (const double T : torques)
      {
        std::vector<double> x, y;
        for (std::size_t i = 0; i < T_col.size(); ++i)
          if (T_col[i] == T)
            x.push_back(roll[i]), y.push_back(ste[i] * 1e-6); // sweep.csv: deg, um
        if (y.empty())
          break;
        r.pp.push_back(*std::max_element(y.begin(), y.end()) - *std::min_element(y.begin(), y.end()));
        r.ripple.push_back(ste_ripple(x, y));
      }
    return r;
  }

  double swept_pp_estimate(const TargetOutcome &o, const SweptPp &swept, PpParts *parts)
  {
    const Level &l = o.levels[o.delivered];
    const std::size_t n = o.positions.size();
    const bool estimated = std::abs(l.rho_contact - 1) > 0.2;
    double worst = 0, resolution = 0;
    for (std::size_t t = 0; t < swept.pp.size() && swept.pp[t] > 0; ++t)
      {
        double richardson = std::isfinite(l.estimate[1]) ? l.estimate[1] : 0; // carried: as it was
        if (estimated && (t + 1) * n <= l.samples.size())
          {
            const std::vector<solve::EstimatedQuantities> a(l.samples.begin() + t * n, l.samples.begin() + (t + 1) * n),
              b(o.levels.front().samples.begin() + t * n, o.levels.front().samples.begin() + (t + 1) * n);
            const std::vector<double> pp = {swept.pp[t]};
            richardson = estimate_relative(a, b, n, l.rho_contact, 1, o.order, &pp, zone_samples)[1];
          }
        const double rip = t < swept.ripple.size() ? 2 * swept.ripple[t] / swept.pp[t] : 0;
        // Independent parts: the smooth discretisation error that the zone middles see, and
        // the scatter that the swept extremes pick up.
        const double e = std::hypot(richardson, rip);
        if (e >= worst && parts)
          {
            parts->richardson   = richardson;
            parts->twice_ripple = rip;
            parts->torque       = t < o.torques.size() ? o.torques[t] : std::nan("");
          }
        worst      = std::max(worst, e);
        resolution = std::max(resolution, rip);
      }
    if (parts)
      parts->resolution = resolution;
    return worst;
  }

  void rescale_pp(TargetOutcome &o, const SweptPp &swept)
  {
    if (o.delivered == 0)
      return;
    Level &l = o.levels[o.delivered];
    PpParts parts;
    l.estimate[1]   = swept_pp_estimate(o, swept, &parts);
    l.pp_richardson = parts.richardson, l.pp_ripple = parts.twice_ripple, l.pp_torque = parts.torque;
    l.pp_resolution = parts.resolution;
    update_met(o);
  }

  void update_met(TargetOutcome &o)
  {
    const Level &l = o.levels[o.delivered];
    o.met          = true;
    for (int q = 0; q < n_quantities; ++q)
      if (o.target.tolerance[q] > 0 && !(l.estimate[q] <= o.target.tolerance[q]))
        o.met = false;
  }

  namespace
  {
    /// The factor by which refine_after_sweep refines h_contact for the p-p estimate
    /// `estimate` after a sweep whose torques take `sweep_seconds` (`spent` of them spent);
    /// 0 when it would not refine (`why`).
    double pp_refinement(const TargetOutcome &o, const solve::GearContactInput &in, const FixedSettings &fixed,
                         const TargetOptions &options, double estimate, double sweep_seconds, std::string &why,
                         double spent)
    {
      const double tol = o.target[Quantity::pp_ste];
      if (!(tol > 0) || estimate <= tol || o.delivered == 0)
        return 0;
      if (fixed.h_contact)
        {
          why = "the swept p-p STE needs a finer Mesh/h_contact than the one set in the input";
          return 0;
        }
      if (o.levels.size() - 1 >= static_cast<std::size_t>(options.max_levels))
        {
          why = "Solve/Target: " + std::to_string(options.max_levels) + " candidate levels tried";
          return 0;
        }
      const double m    = in.pair->gear(1).parameters().rack.module;
      const double h    = in.mesh[0].h_contact;
      const double fc   = h / snap_finer(h / refinement(estimate / tol, o.order), m);
      const double next = (o.delivered_level().seconds_setup + sweep_seconds) * std::pow(fc, 1.5);
      if (options.cost_cap > 0 && o.seconds + spent + next > options.cost_cap)
        {
          std::ostringstream s;
          s << std::setprecision(3) << "the swept p-p STE asks for h_contact / " << fc
            << ", whose run would take about " << next << " s, beyond Solve/Cost cap " << options.cost_cap << " s";
          why = s.str();
          return 0;
        }
      return fc;
    }
  } // namespace

  bool abandon_sweep(const TargetOutcome &o, const solve::GearContactInput &in, const FixedSettings &fixed,
                     const TargetOptions &options, const SweptPp &swept, std::size_t torques_done,
                     double contact_seconds)
  {
    if (torques_done == 0 || swept.pp.size() < torques_done)
      return false;
    const double full = contact_seconds * double(o.torques.size()) / double(torques_done);
    std::string why;
    return pp_refinement(o, in, fixed, options, swept_pp_estimate(o, swept), full, why, contact_seconds) > 0;
  }

  bool refine_after_sweep(TargetOutcome &o, solve::GearContactInput &in, const FixedSettings &fixed,
                          const TargetOptions &options, double sweep_seconds, std::size_t torques_swept)
  {
    Level &d = o.levels[o.delivered];
    std::string why;
    const std::size_t n_t = o.torques.size();
    const double full =
      torques_swept > 0 && torques_swept < n_t ? sweep_seconds * double(n_t) / double(torques_swept) : sweep_seconds;
    const double fc = pp_refinement(o, in, fixed, options, d.estimate[1], full, why, sweep_seconds);
    o.seconds += sweep_seconds;
    if (fc == 0)
      {
        if (!why.empty())
          o.stop_reason = why;
        return false;
      }
    if (options.out)
      *options.out << "model choice: the swept p-p STE's estimate " << pc(d.estimate[1]) << " (mesh ripple included) "
                   << "is above the target; refining h_contact by " << fc << " and sweeping again" << std::endl;
    d.role          = "swept";
    d.swept_torques = torques_swept > 0 ? torques_swept : n_t;
    Sizes cand;
    cand.mesh[0] = in.mesh[0];
    cand.mesh[1] = in.mesh[1];
    cand.degree  = in.fe.degree;
    o.model.reset();
    o.met = false;
    iterate(o, in, fixed, options, scaled(cand, 1 / fc, 1), d.estimate, nullptr, o.seconds);
    return true;
  }

  std::string model_choice_summary(const TargetOutcome &o)
  {
    std::ostringstream s;
    const Level &d = o.delivered_level();
    s << "Model choice (Solve/Target: " << to_string(o.target) << "): " << (o.met ? "met" : "NOT met")
      << " with h_contact " << mm_3(d.h_contact) << " mm, h_fillet " << mm_3(d.h_fillet) << " mm, Q" << d.degree
      << ", " << d.dofs << " DoFs.\n";
    if (!o.stop_reason.empty())
      s << "Refinement stopped: " << o.stop_reason << ".\n";
    s << "\nFirst guess, from the measured model ladder (docs/model-choice.md):\n";
    for (const auto &r : o.choice.reasons)
      s << "- " << r << "\n";
    s << "\n| level | role | h_contact [mm] | h_fillet [mm] | degree | DoFs | set-up [s] | samples [s] |";
    for (const auto *n : AccuracyTarget::names())
      s << " est. " << n << " |";
    s << "\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < o.levels.size(); ++k)
      {
        const Level &l = o.levels[k];
        const std::string role =
          l.swept_torques > 0 && l.swept_torques < o.torques.size() ?
            l.role + " (stopped after " + std::to_string(l.swept_torques) + " of " + std::to_string(o.torques.size()) +
              " torques)" :
            l.role;
        s << "| " << k + 1 << " | " << role << " | " << mm_3(l.h_contact) << " | " << mm_3(l.h_fillet) << " | Q"
          << l.degree << " | " << l.dofs << " | " << std::fixed << std::setprecision(1) << l.seconds_setup << " | "
          << l.seconds_samples << std::defaultfloat << (l.subdivided ? " (subdivided mesh)" : "")
          << (l.remeshed ? " (remeshed " + std::to_string(l.remeshed) + "x)" : "") << " |";
        for (int q = 0; q < n_quantities; ++q)
          s << " " << (o.target.tolerance[q] > 0 ? pc(l.estimate[q]) : "-") << " |";
        s << "\n";
      }
    s << "\nAchieved (estimated relative error of the delivered run: Richardson order " << o.order
      << " against the companion at (A+B)/2 and (B+D)/2 for the STE, also at B and D for the stresses, "
         "every torque; the p-p STE with twice the swept mesh ripple, its resolution; the root stress at least the "
         "fillet mesh's resolution, "
      << pc(d.fillet_resolution) << ") against the target:";
    for (int q = 0; q < n_quantities; ++q)
      if (o.target.tolerance[q] > 0)
        s << " " << AccuracyTarget::names()[q] << " " << pc(d.estimate[q]) << " / " << pc(o.target.tolerance[q])
          << (d.estimate[q] <= o.target.tolerance[q] ? "" : " (above)") << ";";
    s << " choice " << std::fixed << std::setprecision(1) << o.seconds << " s.\n";
    if (o.target.tolerance[1] > 0 && std::isfinite(d.pp_richardson))
      s << "The p-p STE estimate at " << d.pp_torque << " N m, where it is largest, combines the Richardson part "
        << "of the zone middles " << pc(d.pp_richardson) << " and twice the swept position-to-position ripple "
        << pc(d.pp_ripple) << " of the swept p-p (root sum of squares); the p-p's resolution, twice the ripple at "
        << "its largest over the torques, is " << pc(d.pp_resolution)
        << ": below it the p-p error is scatter, not ordered by h (docs/model-choice.md, step 3).\n";
    s << "Sweep: " << o.route << (o.route_why.empty() ? "" : " (" + o.route_why + ")") << ".";
    if (std::isfinite(o.condensation[0]))
      {
        s << " The condensation's error measured on the run (full FE where the STE, the root stresses and p_max "
             "peak at the lowest and highest torque), included in the estimates above:";
        for (int q = 0; q < n_quantities; ++q)
          s << " " << AccuracyTarget::names()[q] << " " << pc(o.condensation[q]) << ";";
      }
    s << "\n";
    return s.str();
  }

  std::string model_choice_json(const TargetOutcome &o)
  {
    std::ostringstream s;
    const auto &keys = AccuracyTarget::keys();
    auto quantities  = [&](const std::array<double, n_quantities> &v) {
      std::ostringstream q;
      q << "{";
      for (int i = 0; i < n_quantities; ++i)
        q << (i ? ", " : "") << "\"" << keys[i] << "\": " << json(v[i]);
      q << "}";
      return q.str();
    };
    const Level &d = o.delivered_level();
    s << "{\n    \"target\": " << quantities(o.target.tolerance) << ",\n    \"preset\": \"" << o.target.preset
      << "\",\n    \"met\": " << (o.met ? "true" : "false") << ",\n    \"stop_reason\": \"" << o.stop_reason
      << "\",\n    \"chosen\": {\"model\": \""
      << (o.choice.mesh[0].model == mesh::GearMeshParameters::Model::sector ? "sector" : "full gear")
      << "\", \"degree\": " << d.degree << ", \"h_contact_mm\": " << json(d.h_contact * 1e3)
      << ", \"h_fillet_mm\": " << json(d.h_fillet * 1e3) << ", \"dofs\": " << d.dofs
      << "},\n    \"estimate\": " << quantities(d.estimate) << ",\n    \"order\": " << json(o.order)
      << ",\n    \"sample_roll_deg\": [";
    for (std::size_t i = 0; i < o.positions.size(); ++i)
      s << (i ? ", " : "") << json(o.positions[i] / units::deg);
    s << "],\n    \"levels\": [";
    for (std::size_t k = 0; k < o.levels.size(); ++k)
      {
        const Level &l = o.levels[k];
        s << (k ? "," : "") << "\n      {\"role\": \"" << l.role << "\", \"h_contact_mm\": " << json(l.h_contact * 1e3)
          << ", \"h_fillet_mm\": " << json(l.h_fillet * 1e3) << ", \"degree\": " << l.degree
          << ", \"dofs\": " << l.dofs << ", \"subdivided\": " << (l.subdivided ? "true" : "false")
          << ", \"remeshed\": " << l.remeshed << ", \"swept_torques\": " << l.swept_torques
          << ", \"setup_seconds\": " << json(l.seconds_setup)
          << ", \"samples_seconds\": " << json(l.seconds_samples) << ", \"estimate\": " << quantities(l.estimate)
          << ", \"root_stress_resolution\": " << json(l.fillet_resolution)
          << ", \"pp_ste_parts\": {\"richardson\": " << json(l.pp_richardson)
          << ", \"twice_ripple\": " << json(l.pp_ripple) << ", \"torque\": " << json(l.pp_torque) << "}"
          << ", \"pp_ste_resolution\": " << json(l.pp_resolution)
          << "}";
      }
    auto escaped = [](const std::string &r) {
      std::string esc;
      for (const char c : r)
        esc += c == '"' ? std::string("\\\"") : std::string(1, c);
      return esc;
    };
    s << "\n    ],\n    \"reasons\": [";
    for (std::size_t k = 0; k < o.choice.reasons.size(); ++k)
      s << (k ? ", " : "") << "\n      \"" << escaped(o.choice.reasons[k]) << "\"";
    s << "\n    ],\n    \"route\": {\"name\": \"" << o.route << "\", \"why\": \"" << escaped(o.route_why)
      << "\", \"condensation_error\": " << quantities(o.condensation) << "}";
    s << ",\n    \"seconds\": " << json(o.seconds) << "\n  }";
    return s.str();
  }
} // namespace gearfem::model_choice
