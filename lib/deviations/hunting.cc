// The hunting cycle with manufacturing deviations on a condensed cycle.
#include "deviations/hunting.h"

#include "base/errors.h"
#include "base/progress.h"
#include "base/table.h"
#include "base/units.h"
#include "condensed/resolve.h"
#include "dynamics/analysis.h"
#include "io/solve_results.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace gearfem::deviations
{
  namespace
  {
    int wrap(long k, int z) { return int(((k % z) + z) % z); }
  } // namespace

  geometry::PairDeviations pair_deviations(const geometry::GearPair &pair, const geometry::GearDeviations &g1,
                                           const geometry::GearDeviations &g2)
  {
    geometry::PairDeviations d;
    d.gear[0] = g1, d.gear[1] = g2;
    const double L = pair.point("T2").g; // T1 T2
    const double gA = pair.point("A").g, gE = pair.point("E").g;
    for (int b = 0; b < 2; ++b)
      {
        const auto &g = pair.gear(b + 1);
        d.teeth[b] = g.teeth();
        geometry::check_deviations(d.gear[b], g.teeth(), "Deviations/Gear " + std::to_string(b + 1));
        auto &R       = d.range[b];
        R.base_radius = pair.base_radius(b + 1);
        const double r_ref = 0.5 * g.parameters().rack.module * g.teeth();
        R.cos_alpha = R.base_radius / r_ref;
        // Roll lengths of the active profile: from T1 for the pinion, from T2 for the gear.
        const double xa = b == 0 ? gA : L - gA, xe = b == 0 ? gE : L - gE;
        R.xi_start = std::min(xa, xe), R.xi_end = std::max(xa, xe);
      }
    d.finalise();
    return d;
  }

  int tooth_at(const Eigen::Vector2d &x, int z)
  {
    const double pitch = 2 * units::pi / z;
    const double a     = std::atan2(x.y(), x.x()) - 0.5 * units::pi;
    return wrap(long(std::lround(a / pitch)), z);
  }

  Modification deviation_modification(const contact::CondensedPosition &p, const geometry::PairDeviations &d,
                                      long pitch)
  {
    Modification mod;
    mod.offset  = Eigen::VectorXd::Zero(Eigen::Index(p.size()));
    mod.advance = Eigen::VectorXd::Zero(Eigen::Index(p.size()));
    if (d.empty())
      return mod;
    // Pitch j relabels the teeth: pinion s -> s - j, gear s -> s + j (see the header); the
    // bodies have turned by +j p1 and -j p2.
    const long shift[2] = {-pitch, pitch};
    Eigen::Vector2d v[2];
    for (int b = 0; b < 2; ++b)
      v[b] = d.runout(b + 1, p.placement[b].angle - 2 * units::pi / d.teeth[b] * double(shift[b]));
    for (std::size_t c = 0; c < p.size(); ++c)
      {
        const auto &pt = p.cand[c].point;
        double off     = 0;
        int tooth[2]   = {-1, -1};
        for (const auto &s : p.modification[c])
          {
            const int b = s.body - 1;
            const int t = wrap(tooth_at(s.x, d.teeth[b]) + shift[b], d.teeth[b]);
            tooth[b]    = t;
            off -= s.weight * d.profile_plus_material(s.body, t, s.x.norm());
          }
        double advance = 0;
        for (int b = 0; b < 2; ++b)
          {
            if (tooth[b] >= 0)
              advance += d.rigid_plus_material(b + 1, tooth[b]);
            // Runout: a displacement v of body b moves its surface by v; the gap is measured
            // along the master's outward normal from master to slave.
            if (v[b].squaredNorm() > 0)
              off += (pt.slave_body == b + 1 ? 1.0 : -1.0) * v[b].dot(pt.normal);
          }
        mod.offset[Eigen::Index(c)]  = off;
        mod.advance[Eigen::Index(c)] = advance / d.range[0].base_radius;
      }
    return mod;
  }

  std::vector<OrderLine> order_spectrum(const std::vector<double> &samples, int samples_per_pitch, int z1, int z2)
  {
    // Sample spacing in pinion revolutions: 1 / (z1 samples_per_pitch).
    const auto s = dynamics::amplitude_spectrum(samples, 1.0 / (double(z1) * samples_per_pitch));
    std::vector<OrderLine> out(s.frequency.size());
    for (std::size_t k = 0; k < out.size(); ++k)
      out[k] = {s.frequency[k], s.frequency[k] * z1 / z2, s.amplitude[k]};
    return out;
  }

  SpectrumSummary summarise(const std::vector<OrderLine> &lines, int z1)
  {
    SpectrumSummary s;
    if (lines.size() < 2)
      return s;
    const double bin = lines[1].order_pinion - lines[0].order_pinion;
    for (const auto &l : lines)
      {
        if (l.order_pinion <= 0.5 * bin)
          continue;
        const double h = l.order_pinion / z1;
        const long hn  = std::lround(h);
        if (hn >= 1 && std::abs(l.order_pinion - double(hn) * z1) < 0.5 * bin)
          {
            if (hn <= 3)
              s.mesh[hn - 1] = l.amplitude;
            continue;
          }
        if (l.amplitude > s.largest_other)
          s.largest_other = l.amplitude, s.largest_other_order = l.order_pinion;
      }
    return s;
  }

  void check_one_pitch_cycle(const solve::GearContactInput &in)
  {
    const auto &s = in.solve;
    if (s.positions != solve::SolveParameters::Positions::cycle || std::abs(s.pitches - 1.0) > 1e-12)
      throw InputError("Solve/Positions", s.positions == solve::SolveParameters::Positions::cycle ?
                                            "cycle over " + to_string_g(s.pitches) + " pitches" :
                                            std::string("not a cycle"),
                       "cycle over 1 pitch (Solve/Pitches = 1)",
                       "the hunting cycle repeats the positions of one pitch, pitch after pitch");
  }

  namespace
  {
    /// Point p of the hunting plan: cycle position k = p.position_index % M at pitch
    /// j = p.position_index / M, with the deviations of the teeth in mesh at that pitch as gap
    /// offsets and drive advances on top of the variant's reliefs; the roll angle and the tooth
    /// indices of the result are those of pitch j.
    class HuntingSolver : public condensed::CycleSolver
    {
    public:
      HuntingSolver(const condensed::CondensedCycle &cycle, const condensed::Resolver &resolver,
                    const geometry::PairDeviations &d, std::size_t M, int z1, int z2, const post::PostOptions &post)
        : condensed::CycleSolver(resolver, post), cycle_(cycle), d_(d), M_(M), z1_(z1), z2_(z2)
      {}

    protected:
      condensed::Resolved resolve(const loading::SweepPoint &p) override
      {
        const long j = long(p.position_index / M_);
        try
          {
            const std::size_t idx  = resolver_.positions()[p.position_index % M_];
            const auto &cp         = cycle_.at(idx, p.torque);
            const Modification mod = deviation_modification(cp, d_, j);
            condensed::Resolved r =
              resolver_.solve(idx, p.torque, resolver_.offsets(cp) + mod.offset, mod.advance, options_);
            r.state.phi1 += double(j) * 2 * units::pi / z1_;
            r.result.phi1 = r.state.phi1;
            for (auto &tp : r.result.pairs)
              tp.pinion_tooth = wrap(tp.pinion_tooth - j, z1_), tp.gear_tooth = wrap(tp.gear_tooth + j, z2_);
            return r;
          }
        catch (const SolverError &e)
          {
            throw SolverError("hunting cycle, pitch " + std::to_string(j) + ": " + e.what());
          }
      }

    private:
      const condensed::CondensedCycle &cycle_;
      const geometry::PairDeviations &d_;
      std::size_t M_;
      int z1_, z2_;
    };

    /// Collects the STE over the cycle and the peaks of each torque.
    class PeaksObserver : public post::PositionObserver
    {
    public:
      explicit PeaksObserver(HuntingRun &h) : h_(h) {}
      void finished(const loading::SweepPoint &p, const contact::ContactState &, post::PositionResult &r) override
      {
        const std::size_t ti = p.torque_index;
        h_.ste[ti].push_back(r.ste);
        h_.max_root_stress[0][ti] = std::max(h_.max_root_stress[0][ti], r.max_root_stress_pinion);
        h_.max_root_stress[1][ti] = std::max(h_.max_root_stress[1][ti], r.max_root_stress_gear);
        h_.max_pressure[ti]       = std::max(h_.max_pressure[ti], r.p_max);
      }

    private:
      HuntingRun &h_;
    };
  } // namespace

  HuntingRun run_hunting(const condensed::CondensedCycle &cycle, const solve::GearContactInput &in,
                         const geometry::PairDeviations &d, const HuntingOptions &opt)
  {
    check_one_pitch_cycle(in);
    post::validate(opt.post);
    const condensed::Resolver resolver(cycle, in);
    const int z1 = in.pair->gear(1).teeth(), z2 = in.pair->gear(2).teeth();
    HuntingRun h;
    h.pitches = opt.pitches > 0 ? opt.pitches : geometry::hunting_pitches(z1, z2);
    if (h.pitches > 100000)
      throw InputError("Deviations/Pitches", std::to_string(h.pitches), "1 .. 100000 pitches",
                       "the hunting period of this pair is long: set a number of pitches");
    const auto &torques = in.solve.torques;
    const std::size_t M = resolver.positions().size();
    h.ste.assign(torques.size(), {});
    for (int b = 0; b < 2; ++b)
      h.max_root_stress[b].assign(torques.size(), 0.0);
    h.max_pressure.assign(torques.size(), 0.0);
    // The plan: every pitch of the cycle repeats the positions of one pitch.
    loading::SweepPlan plan;
    plan.torques          = torques;
    const auto positions  = in.positions();
    for (long j = 0; j < h.pitches; ++j)
      for (std::size_t k = 0; k < M; ++k)
        plan.positions.emplace_back("", positions[k].second + double(j) * 2 * units::pi / z1);
    HuntingSolver solver(cycle, resolver, d, M, z1, z2, opt.post);
    PeaksObserver peaks(h);
    solve::PointsSettings settings;
    settings.program        = "gearfem solve (hunting cycle on a condensed cycle)";
    settings.journal        = false;
    settings.progress_every = std::max<std::size_t>(1, plan.size() / 20);
    settings.tables         = opt.tables;
    settings.observers      = {&peaks};
    solve::SolveRunOptions ro;
    ro.output_dir = opt.tables ? opt.output_dir : std::filesystem::path();
    ro.input_name = opt.input_name;
    ro.out        = opt.out;
    ro.post       = opt.post;
    h.run         = solve::run_points(solver, in, plan, ro, settings);
    // Spectra of the complete torques only.
    Table spec;
    spec.add_column("torque", "N m");
    spec.add_column("order pinion", "-");
    spec.add_column("order gear", "-");
    spec.add_column("mesh harmonic", "-");
    spec.add_column("amplitude", "um");
    for (std::size_t ti = 0; ti < torques.size(); ++ti)
      {
        if (h.ste[ti].size() != std::size_t(h.pitches) * M)
          break;
        h.spectrum.push_back(order_spectrum(h.ste[ti], int(M), z1, z2));
        h.summary.push_back(summarise(h.spectrum.back(), z1));
        for (const auto &l : h.spectrum.back())
          spec.add_row({torques[ti], l.order_pinion, l.order_gear, l.order_pinion / z1, l.amplitude * 1e6});
      }
    if (!opt.output_dir.empty() && opt.tables)
      spec.write_csv(opt.output_dir / "spectrum.csv");
    return h;
  }
} // namespace gearfem::deviations
