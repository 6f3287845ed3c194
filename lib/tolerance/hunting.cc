// The hunting cycle with manufacturing deviations on a condensed cycle.
#include "tolerance/hunting.h"

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

namespace gearfem::tolerance
{
  namespace
  {
    using Clock = std::chrono::steady_clock;
    double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
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
    const auto &torques    = in.solve.torques;
    const std::size_t M    = resolver.positions().size();
    const double p1        = 2 * units::pi / z1;
    const double z_ratio   = double(z2) / z1;
    const double face_width = std::min(in.material[0].thickness, in.material[1].thickness);
    solve::SolveRunResult &run = h.run;
    io::SolveResults &t        = run.results;
    t = solve::start_results(in, opt.input_name, "gearfem solve (hunting cycle on a condensed cycle)");
    const std::size_t total = torques.size() * std::size_t(h.pitches) * M;
    Progress progress(opt.out, total, "position");
    h.ste.assign(torques.size(), {});
    for (int b = 0; b < 2; ++b)
      h.max_root_stress[b].assign(torques.size(), 0.0);
    h.max_pressure.assign(torques.size(), 0.0);
    double t_contact = 0, t_post = 0;
    const auto t_start = Clock::now();
    std::size_t i = 0;
    for (std::size_t ti = 0; ti < torques.size() && run.failure.empty(); ++ti)
      for (long j = 0; j < h.pitches && run.failure.empty(); ++j)
        for (std::size_t k = 0; k < M && run.failure.empty(); ++k, ++i)
          try
            {
              const std::size_t idx = resolver.positions()[k];
              const auto &p         = cycle.at(idx, torques[ti]);
              const Modification mod = deviation_modification(p, d, j);
              condensed::Resolved r  = resolver.solve(idx, torques[ti], resolver.offsets(p) + mod.offset,
                                                      mod.advance, opt.post);
              r.state.phi1 += double(j) * p1;
              r.result.phi1 = r.state.phi1;
              for (auto &tp : r.result.pairs)
                tp.pinion_tooth = wrap(tp.pinion_tooth - j, z1), tp.gear_tooth = wrap(tp.gear_tooth + j, z2);
              if (opt.tables)
                solve::append_position(t, r.state, r.result, "", int(long(M) * j + long(k)), z_ratio, face_width);
              h.ste[ti].push_back(r.result.ste);
              h.max_root_stress[0][ti] = std::max(h.max_root_stress[0][ti], r.result.max_root_stress_pinion);
              h.max_root_stress[1][ti] = std::max(h.max_root_stress[1][ti], r.result.max_root_stress_gear);
              h.max_pressure[ti]       = std::max(h.max_pressure[ti], r.result.p_max);
              t_contact += r.state.t_contact, t_post += r.result.t_post;
              ++run.solved;
              if (opt.out && ((i + 1) % std::max<std::size_t>(1, total / 20) == 0 || i + 1 == total))
                {
                  std::ostringstream s;
                  s << "T " << torques[ti] << " N m, pitch " << j + 1 << "/" << h.pitches << ", STE "
                    << std::setprecision(4) << r.result.ste * 1e6 << " um";
                  progress.step(i + 1, s.str());
                }
            }
          catch (const SolverError &e)
            {
              run.failure = "hunting cycle, pitch " + std::to_string(j) + ": " + e.what();
            }
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
    if (opt.tables)
      run.unresolved = solve::count_unresolved(t, opt.post.unresolved_share);
    const auto t_out = Clock::now();
    if (!opt.output_dir.empty() && opt.tables)
      {
        io::write_solve_results(t, opt.output_dir);
        spec.write_csv(opt.output_dir / "spectrum.csv");
      }
    run.seconds = {{"contact", t_contact}, {"post", t_post}, {"output", since(t_out)}, {"total", since(t_start)}};
    return h;
  }
} // namespace gearfem::tolerance
