#include "system_deflection/train.h"

#include "base/atomic_file.h"
#include "base/errors.h"
#include "base/progress.h"
#include "base/units.h"
#include "system_deflection/tables.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace gearfem::system_deflection
{
  namespace
  {
    /// The shafts placed (shaft 0 at the origin, each gear's axis at its stage's centre
    /// distance along its direction) and every stage's mesh layout on them.
    std::vector<shafts::MeshLayout> layouts(TrainInput &in)
    {
      auto &sh = in.system.shafts;
      sh[0].x = sh[0].y = 0;
      std::vector<shafts::MeshLayout> out;
      for (std::size_t k = 0; k < in.stages.size(); ++k)
        {
          const auto &st   = in.stages[k];
          const auto &pair = *st.request.section.pair;
          const auto &o    = st.request.slicing;
          const double a   = pair.center_distance();
          sh[k + 1].x = sh[k].x + a * std::cos(st.direction), sh[k + 1].y = sh[k].y + a * std::sin(st.direction);
          shafts::MeshLayout m;
          m.pinion_shaft = int(k), m.gear_shaft = int(k + 1);
          m.pinion_face_start = st.pinion_face_start, m.gear_face_start = st.gear_face_start;
          m.face_width     = o.helix.face_width;
          m.alpha_wt       = o.alpha_wt;
          m.pitch_radius_1 = pair.working_pitch_radius(1);
          // External meshes: each stage's pinion turns against the one before it.
          m.drive_sense = k % 2 == 0 ? 1 : -1;
          m.beta_b      = (o.helix.roll_per_length >= 0 ? 1.0 : -1.0) * m.drive_sense * o.helix.beta_b;
          m.validate(in.system);
          out.push_back(m);
        }
      return out;
    }
  } // namespace

  TrainRun run_train(TrainInput in, std::ostream *out)
  {
    const std::size_t S = in.stages.size();
    if (S < 1 || in.system.shafts.size() != S + 1)
      throw InputError("Train/Stages", std::to_string(S), "1 or more stages on stages + 1 shafts");
    if (in.torques.empty())
      throw InputError("Train/Torques", "(none)", "one or more input torques > 0");
    TrainRun run;
    run.ratio.push_back(1.0);
    for (std::size_t k = 0; k + 1 < S; ++k)
      {
        const auto &p = *in.stages[k].request.section.pair;
        run.ratio.push_back(run.ratio.back() * double(p.gear(2).teeth()) / double(p.gear(1).teeth()));
      }
    run.meshes = layouts(in);
    run.system = in.system;
    // Every stage's cycle at its own torques, then its sliced pair on it.
    std::vector<std::unique_ptr<condensed::CondensedCycle>> cycles;
    std::vector<std::unique_ptr<helical::SlicedPair>> pairs;
    std::vector<TrainMesh> meshes;
    for (std::size_t k = 0; k < S; ++k)
      {
        auto &st = in.stages[k];
        auto &h  = run.stages.emplace_back();
        h.options = st.request.slicing, h.helix = h.options.helix;
        for (const double T : in.torques)
          h.torques.push_back(T * run.ratio[k]);
        st.request.section.solve.torques = h.torques;
        h.eps_alpha = st.request.section.pair->contact_ratio();
        h.eps_gamma = h.eps_alpha + h.helix.overlap_ratio;
        helical::RunOptions ro = st.request.run;
        ro.out = out, ro.cycle_file.clear(), ro.write_cycle.clear();
        if (out)
          *out << "stage " << k + 1 << " (" << st.input.filename().string() << "), pinion torque x"
                  << std::setprecision(5) << run.ratio[k] << ":\n";
        cycles.push_back(std::make_unique<condensed::CondensedCycle>(
          helical::section_cycle(st.request.section, h.torques, ro, h)));
        pairs.push_back(std::make_unique<helical::SlicedPair>(*cycles.back(), st.request.section, h.options));
        meshes.push_back({pairs.back().get(), run.meshes[k]});
      }
    const CoupledTrain train(meshes, run.system, in.options);
    run.coupled.resize(S);
    // The sweep over stage 1's grid; stage k's roll angle follows through the ratios.
    const auto grid = run.stages[0].options.grid.positions();
    const std::size_t total = grid.size() * in.torques.size();
    Progress progress(out, total, "train position");
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::vector<double>> warm;
    double last = -1;
    for (std::size_t i = 0; i < total && run.failure.empty(); ++i)
      {
        const double T  = in.torques[i / grid.size()];
        const double d1 = grid[i % grid.size()].second - run.stages[0].options.grid.phi0;
        std::vector<double> phi, torque;
        std::vector<helical::LeadModification> lead;
        for (std::size_t k = 0; k < S; ++k)
          {
            phi.push_back(run.stages[k].options.grid.phi0 + d1 / run.ratio[k]);
            torque.push_back(T * run.ratio[k]);
            lead.push_back(run.stages[k].options.lead);
          }
        if (T != last)
          {
            for (auto &g : warm)
              for (auto &v : g)
                v *= T / last; // the mismatch follows the load on linear shafts
            last = T;
          }
        try
          {
            const auto r = train.solve(phi, torque, lead, warm);
            warm.clear();
            for (std::size_t k = 0; k < S; ++k)
              {
                run.coupled[k].push_back(r[k]);
                run.stages[k].results.push_back(r[k].helical);
                warm.push_back(r[k].mismatch);
              }
            std::ostringstream d;
            d << "T " << T << " N m, K_Hbeta";
            for (const auto &x : r)
              d << ' ' << std::setprecision(4) << x.helical.k_h_beta;
            d << ", " << r.front().iterations << " iterations";
            if (out && ((i + 1) % std::max<std::size_t>(1, total / 10) == 0 || i + 1 == total))
              progress.step(i + 1, d.str());
          }
        catch (const SolverError &e)
          {
            run.failure = e.what();
          }
      }
    run.sweep_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (auto &h : run.stages)
      {
        h.summary = helical::summarise(h.results);
        for (auto &s : h.summary)
          s.c_gamma = s.k_mean / h.helix.face_width;
        h.sweep_seconds = run.sweep_seconds;
      }
    for (std::size_t k = 0; k < S; ++k)
      run.iso.push_back(method_c(in.stages[k].request.section, run.stages[k].options, run.coupled[k],
                                 run.stages[k].summary));
    // Per input torque: the shafts under every stage's mean slice forces.
    for (std::size_t t = 0; t < in.torques.size(); ++t)
      {
        std::vector<CoupledResult> mean;
        bool all = true;
        for (std::size_t k = 0; k < S; ++k)
          {
            int n = 0;
            mean.push_back(mean_at(run.coupled[k], in.torques[t] * run.ratio[k], n));
            all = all && n > 0;
          }
        if (all)
          run.shafts.push_back({in.torques[t], train.shafts_under(mean)});
      }
    return run;
  }

  void write_train(const TrainRun &run, const std::filesystem::path &dir, const std::string &input_name)
  {
    std::vector<MeshTables> tables;
    const std::size_t grid = std::size_t(run.stages.front().options.grid.size);
    for (std::size_t k = 0; k < run.stages.size(); ++k)
      {
        const auto sub = dir / ("stage_" + std::to_string(k + 1));
        std::filesystem::create_directories(sub);
        helical::write_helical(run.stages[k], sub, input_name);
        tables.push_back({int(k + 1), grid, &run.coupled[k]});
      }
    write_shaft_tables(tables, run.shafts, run.system, dir);
    AtomicOutputFile f(dir / "system.json");
    auto &s = f.stream();
    s << std::setprecision(10) << "{\n  \"format\": \"gearfem-system\", \"version\": 1, \"input\": \"" << input_name
      << "\",\n  \"shafts\": [";
    for (std::size_t i = 0; i < run.system.shafts.size(); ++i)
      s << (i ? ", " : "") << "{\"x_mm\": " << run.system.shafts[i].x / units::mm
        << ", \"y_mm\": " << run.system.shafts[i].y / units::mm << "}";
    s << "],\n  \"stages\": [";
    for (std::size_t k = 0; k < run.meshes.size(); ++k)
      {
        const auto &m = run.meshes[k];
        s << (k ? ",\n" : "\n") << "    {\"torque_ratio\": " << run.ratio[k] << ", \"pinion_shaft\": " << m.pinion_shaft + 1
          << ", \"gear_shaft\": " << m.gear_shaft + 1 << ", \"pinion_face_start_mm\": " << m.pinion_face_start / units::mm
          << ", \"gear_face_start_mm\": " << m.gear_face_start / units::mm
          << ", \"pitch_radius_1_mm\": " << m.pitch_radius_1 / units::mm << ", \"drive_sense\": " << m.drive_sense
          << ", \"face_width_mm\": " << m.face_width / units::mm << ", \"alpha_wt_deg\": " << m.alpha_wt / units::deg
          << ", \"beta_b_deg\": " << m.beta_b / units::deg << ",\n     \"torques\": [";
        write_method_c(s, run.iso[k]);
        s << "]}";
      }
    s << "\n  ],\n  \"sweep_seconds\": " << run.sweep_seconds << ", \"solved\": " << run.coupled.front().size()
      << ", \"failure\": \"" << (run.failure.empty() ? "" : "see the console") << "\"\n}\n";
    f.commit();
  }
} // namespace gearfem::system_deflection
